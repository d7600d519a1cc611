#!/usr/bin/python3
"""rostest: scenario_node plays a humans-only script through world_node's services to the end."""
import math
import threading
import time
import unittest

import rosgraph
import rospy
import rostest
from std_srvs.srv import SetBool

from ari_social_sim.msg import ScenarioStatus, WorldState


class Recorder:
    """Keeps the speech acts as they start and the last world state and scenario status."""

    def __init__(self):
        self.lock = threading.Lock()
        self.acts = []  # (speaker id, act) in order of starting
        self.state = None
        self.status = None
        self._speaking = {}
        self.state_sub = rospy.Subscriber("/sim/world_state", WorldState, self.on_state,
                                          queue_size=100)
        rospy.Subscriber("/scenario/status", ScenarioStatus, self.on_status, queue_size=10)

    def on_state(self, msg):
        with self.lock:
            self.state = msg
            for h in msg.humans:
                key = (h.speech.act, h.speech.start_time) if h.speech.is_speaking else None
                if key is not None and self._speaking.get(h.id) != key:
                    self.acts.append((h.id, h.speech.act))
                self._speaking[h.id] = key

    def on_status(self, msg):
        with self.lock:
            self.status = msg


class ScenarioNodeTest(unittest.TestCase):
    def test_script_runs_to_its_stop(self):
        recorder = Recorder()
        master = rosgraph.Master("/test_scenario_node")
        limit = time.monotonic() + 60.0
        while time.monotonic() < limit:
            _, subscribers, _ = master.getSystemState()
            listeners = dict(subscribers).get("/sim/world_state", [])
            if "/scenario_node" in listeners and recorder.state_sub.get_num_connections() > 0:
                break
            time.sleep(0.05)
        rospy.wait_for_service("/sim/pause", 30.0)
        self.assertTrue(rospy.ServiceProxy("/sim/pause", SetBool)(False).success)
        limit = time.monotonic() + 90.0
        while time.monotonic() < limit:
            with recorder.lock:
                if recorder.status is not None and recorder.status.finished:
                    break
            time.sleep(0.05)
        with recorder.lock:
            status, state, acts = recorder.status, recorder.state, list(recorder.acts)
        self.assertIsNotNone(status, "no /scenario/status")
        self.assertTrue(status.finished)
        self.assertTrue(status.success, status.reason)
        self.assertEqual(status.state, "gather")
        self.assertEqual(status.reason, "Ana and Ben met")
        # Ana greets first, then Ben, who was spawned by the script.
        self.assertEqual(acts, [(10, "greet()"), (12, "greet()")])
        ana = next(h for h in state.humans if h.id == 10)
        ben = next(h for h in state.humans if h.id == 12)
        self.assertLess(math.hypot(ana.pose.x - ben.pose.x, ana.pose.y - ben.pose.y), 1.5)
        self.assertEqual(ana.group_id, 1)
        self.assertEqual(ben.group_id, 1)
        self.assertLess(status.header.stamp.to_sec(), 60.0)


if __name__ == "__main__":
    rospy.init_node("test_scenario_node")
    rostest.rosrun("ari_social_sim", "scenario_node_plumbing", ScenarioNodeTest)
