#!/usr/bin/python3
"""rostest: the whole suite plays group_discussion to its end; its live bag and a batch bag of
the same scenario and seed hold the same topics with the same message types."""
import math
import os
import subprocess
import tempfile
import threading
import time
import unittest

import rosbag
import rosgraph
import rosnode
import rospy
import rostest
from std_srvs.srv import SetBool

from ari_social_sim.msg import ScenarioStatus, WorldState

ARI_START = (1.0, 5.0)
IRENE = 11
# The script's speech acts in order: (speaker, text); ARI speaks through /tts.
SCRIPT = [
    ("ari", "Hello, I am ARI. Can I help you?"),
    (IRENE, "Hello. Yes. What is the time?"),
    ("ari", "It is 14:30."),
    (IRENE, "Thank you. Good bye."),
    ("ari", "Good bye."),
]


class Recorder:
    """Every utterance as it starts, ARI's closest approach to Irene, the last state and status."""

    def __init__(self):
        self.lock = threading.Lock()
        self.utterances = []  # (speaker, text) in order of starting
        self.closest_to_irene = math.inf
        self.state = None
        self.status = None
        self._speaking = {}
        self.state_sub = rospy.Subscriber("/sim/world_state", WorldState, self.on_state,
                                          queue_size=1000)
        rospy.Subscriber("/scenario/status", ScenarioStatus, self.on_status, queue_size=10)

    def _speech(self, speaker, speech):
        key = (speech.content, speech.start_time) if speech.is_speaking else None
        if key is not None and self._speaking.get(speaker) != key:
            self.utterances.append((speaker, speech.content))
        self._speaking[speaker] = key

    def on_state(self, msg):
        with self.lock:
            self.state = msg
            if msg.has_ari:
                self._speech("ari", msg.ari.speech)
            for h in msg.humans:
                self._speech(h.id, h.speech)
                if h.id == IRENE and msg.has_ari:
                    d = math.hypot(h.pose.x - msg.ari.pose.x, h.pose.y - msg.ari.pose.y)
                    self.closest_to_irene = min(self.closest_to_irene, d)

    def on_status(self, msg):
        with self.lock:
            self.status = msg


def wait_for(predicate, timeout, what):
    limit = time.monotonic() + timeout
    while time.monotonic() < limit and not rospy.is_shutdown():
        if predicate():
            return
        time.sleep(0.05)
    raise AssertionError("timed out waiting for " + what)


def topics_and_types(path):
    with rosbag.Bag(path) as bag:
        info = bag.get_type_and_topic_info()
    return {topic: (t.msg_type, t.message_count) for topic, t in info.topics.items()}


class ScenarioSuiteTest(unittest.TestCase):
    def test_group_discussion_end_to_end(self):
        recorder = Recorder()
        master = rosgraph.Master("/test_scenario_suite")

        def scenario_node_listens():
            _, subscribers, _ = master.getSystemState()
            listeners = dict(subscribers).get("/sim/world_state", [])
            return "/scenario_node" in listeners and recorder.state_sub.get_num_connections() > 0

        # scenario_node subscribes once every server the script uses is up.
        wait_for(scenario_node_listens, 120.0, "scenario_node on /sim/world_state")
        rospy.wait_for_service("/sim/pause", 30.0)
        self.assertTrue(rospy.ServiceProxy("/sim/pause", SetBool)(False).success)
        wait_for(lambda: recorder.status is not None and recorder.status.finished, 240.0,
                 "the scenario's end")
        time.sleep(0.5)  # the last states in flight
        with recorder.lock:
            status, state = recorder.status, recorder.state
            utterances, closest = list(recorder.utterances), recorder.closest_to_irene
        rospy.loginfo("group_discussion: %s at %.2f s, closest to Irene %.2f m, utterances %s",
                      status.reason, status.header.stamp.to_sec(), closest, utterances)
        self.assertTrue(status.success, status.reason)
        self.assertEqual(status.reason, "ARI left the group")
        self.assertLess(status.header.stamp.to_sec(), 120.0)
        self.assertLess(closest, 1.5)
        self.assertEqual(utterances, SCRIPT)
        back = math.hypot(state.ari.pose.x - ARI_START[0], state.ari.pose.y - ARI_START[1])
        self.assertLess(back, 0.5)

        # The live recording ends with the recorder; a batch run of the same scenario and seed.
        bag = rospy.get_param("~bag")
        rosnode.kill_nodes(["/scenario_recorder"])
        wait_for(lambda: os.path.exists(bag) and not os.path.exists(bag + ".active"), 30.0,
                 "the live bag to be closed")
        out = tempfile.mkdtemp(prefix="scenario_suite_")
        subprocess.run(["rosrun", "ari_social_sim", "run_episodes", "--scenario",
                        "group_discussion", "--episodes", "1", "--seed", "1", "--out", out],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        live = topics_and_types(bag)
        batch = topics_and_types(os.path.join(out, "group_discussion_1.bag"))
        for topic in sorted(set(live) | set(batch)):
            rospy.loginfo("%-36s live %-34s %6s  batch %-34s %6s", topic,
                          *live.get(topic, ("-", 0)), *batch.get(topic, ("-", 0)))
        live_types = {topic: t for topic, (t, _) in live.items()}
        batch_types = {topic: t for topic, (t, _) in batch.items()}
        # World, tf, perception's frame-level topics, navigation's commands, the script's status
        # (no simulated humans in this scenario: no /sim/dialogue/* topics in either).
        self.assertEqual(len(live_types), 16)
        self.assertEqual(sorted(set(live_types) ^ set(batch_types)), [])
        self.assertEqual(live_types, batch_types)
        # Both recorded the whole run: one world state per 0.05 s step until the end.
        for counts in (live, batch):
            self.assertGreaterEqual(counts["/sim/world_state"][1], 400)


if __name__ == "__main__":
    rospy.init_node("test_scenario_suite")
    rostest.rosrun("ari_social_sim", "scenario_suite", ScenarioSuiteTest)
