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

from std_msgs.msg import Bool

from ari_social_sim.msg import IdsList, LiveSpeech, ScenarioStatus, WorldState

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
        self.small_talk = []  # the same for the group's own talk
        self.finished_talk = {}  # (speaker, text, start time) of a line that ended -> its end time
        self.closest_to_irene = math.inf
        self.state = None
        self.status = None
        self._speaking = {}
        self.voice_finals = []  # final transcripts of ROS4HRI's /humans/voices/<id>/speech
        self.voices_speaking = set()  # voices whose is_speaking was ever true
        self.followed = {}
        self.following_since = None  # sim time the newest voice was followed from
        self.perceived_until = 0.0  # stamp of perception's last /humans/voices/tracked
        rospy.Subscriber("/humans/voices/tracked", IdsList, self.on_voices, queue_size=10)
        self.state_sub = rospy.Subscriber("/sim/world_state", WorldState, self.on_state,
                                          queue_size=1000)
        rospy.Subscriber("/scenario/status", ScenarioStatus, self.on_status, queue_size=10)

    def _speech(self, speaker, speech, now_s):
        key = (speech.content, speech.start_time) if speech.is_speaking else None
        previous = self._speaking.get(speaker)
        if key is not None and previous != key:
            # The group's own talk (docs/world.md section 12) apart from the script's lines.
            own_talk = "small_talk" in speech.act or speech.act == "backchannel()"
            if own_talk:
                self.small_talk.append((speaker, speech.content, speech.start_time))
            else:
                self.utterances.append((speaker, speech.content))
        if previous is not None and previous != key:
            self.finished_talk[(speaker,) + previous] = now_s
        self._speaking[speaker] = key

    def on_state(self, msg):
        with self.lock:
            self.state = msg
            now_s = msg.header.stamp.to_sec()
            if msg.has_ari:
                self._speech("ari", msg.ari.speech, now_s)
            for h in msg.humans:
                self._speech(h.id, h.speech, now_s)
                if h.id == IRENE and msg.has_ari:
                    d = math.hypot(h.pose.x - msg.ari.pose.x, h.pose.y - msg.ari.pose.y)
                    self.closest_to_irene = min(self.closest_to_irene, d)

    def on_status(self, msg):
        with self.lock:
            self.status = msg

    def on_voices(self, msg):
        with self.lock:
            self.perceived_until = msg.header.stamp.to_sec()
        for voice in msg.ids:
            if voice not in self.followed:
                self.following_since = rospy.get_time()
                self.followed[voice] = (
                    rospy.Subscriber("/humans/voices/%s/speech" % voice, LiveSpeech,
                                     self.on_voice_speech, queue_size=50),
                    rospy.Subscriber("/humans/voices/%s/is_speaking" % voice, Bool,
                                     lambda msg, v=voice: self.on_is_speaking(v, msg),
                                     queue_size=50))

    def on_voice_speech(self, msg):
        if msg.final:
            with self.lock:
                self.voice_finals.append(msg.final)

    def on_is_speaking(self, voice, msg):
        if msg.data:
            with self.lock:
                self.voices_speaking.add(voice)


def heard_in(line, finals):
    """Whether a final transcript shares at least half of the line's words (perception's
    recogniser errors change some)."""
    words = set(line.lower().strip(".?!").split())
    return any(len(words & set(f.lower().strip(".?!").split())) >= 0.5 * len(words)
               for f in finals)


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
        # A line's final transcript comes when perception has seen its end. On a loaded machine
        # perception may run behind the world, which scenario_node pauses at the end: wait until
        # perception has seen the last state (it takes every state: ~max_rate 30 Hz).
        end_s = recorder.status.header.stamp.to_sec()

        def perception_caught_up():
            with recorder.lock:
                last_state_s = recorder.state.header.stamp.to_sec()
                return recorder.perceived_until >= max(end_s, last_state_s)
        wait_for(perception_caught_up, 60.0, "perception to reach the world's last state")
        with recorder.lock:
            status, state = recorder.status, recorder.state
            utterances, closest = list(recorder.utterances), recorder.closest_to_irene
            small_talk = list(recorder.small_talk)
            finished_talk, following_since = dict(recorder.finished_talk), recorder.following_since
            voice_finals, voices_speaking = list(recorder.voice_finals), set(recorder.voices_speaking)
        rospy.loginfo("group_discussion: %s at %.2f s, closest to Irene %.2f m, utterances %s",
                      status.reason, status.header.stamp.to_sec(), closest, utterances)
        self.assertTrue(status.success, status.reason)
        self.assertEqual(status.reason, "ARI left the group")
        self.assertLess(status.header.stamp.to_sec(), 120.0)
        self.assertLess(closest, 1.5)
        self.assertEqual(utterances, SCRIPT)
        # Paul and Irene talk among themselves as well.
        self.assertTrue({speaker for speaker, _, _ in small_talk} & {10, IRENE}, small_talk)
        # ROS4HRI's voices carry the group's turns: most lines of more than a backchannel reach
        # /humans/voices/<id>/speech as final transcripts, and the speakers' is_speaking rises.
        # Counted: lines begun a second after the test followed the newest voice, as a ROS4HRI
        # client does once a voice is tracked (the first line of a voice can end before the
        # client's subscription connects), and ended before the scenario did (a final comes at
        # the end of a line).
        self.assertIsNotNone(following_since, "no voice on /humans/voices/tracked")
        lines = [text for speaker, text, start in small_talk
                 if finished_talk.get((speaker, text, start), math.inf) <= end_s
                 and start > following_since + 1.0
                 and len(text.split()) > 2]
        heard = [line for line in lines if heard_in(line, voice_finals)]
        rospy.loginfo("small talk: %d lines, %d heard on /humans/voices (%d voices speaking)",
                      len(lines), len(heard), len(voices_speaking))
        self.assertGreaterEqual(len(lines), 2, small_talk)
        missed = [line for line in lines if line not in heard]
        self.assertGreaterEqual(len(heard), 0.8 * len(lines),
                                ("missed", missed, "finals", voice_finals))
        self.assertGreaterEqual(len(voices_speaking), 2)
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
        # World, tf, perception's frame-level topics (with /humans/interactions/gazing: Paul and
        # Irene look at each other as they talk), navigation's commands, the script's status (no
        # simulated humans in this scenario: no /sim/dialogue/* topics in either).
        self.assertEqual(len(live_types), 17)
        self.assertIn("/humans/interactions/gazing", live_types)
        self.assertEqual(sorted(set(live_types) ^ set(batch_types)), [])
        self.assertEqual(live_types, batch_types)
        # Both recorded the whole run: one world state per 0.05 s step until the end.
        for counts in (live, batch):
            self.assertGreaterEqual(counts["/sim/world_state"][1], 400)


if __name__ == "__main__":
    rospy.init_node("test_scenario_suite")
    rostest.rosrun("ari_social_sim", "scenario_suite", ScenarioSuiteTest)
