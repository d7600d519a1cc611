#!/usr/bin/python3
"""rostest, must-show 3 of issue 12: group_discussion succeeds end to end whatever perception
stands in (scenario_perception_modes.test): ARI joins Paul and Irene, converses and leaves, and
every person id that perception reported has the form of ~person_id_pattern (so the run cannot
have relied on the simulated `human<N>` naming when the ids were of another form)."""
import re
import threading
import unittest

import rospy
import rostest
import scenario_start

from ari_social_sim.msg import Group, IdsList, ScenarioStatus, WorldState


class Recorder:
    """The person ids and groups perception reported, and the scenario's last status."""

    def __init__(self):
        self.lock = threading.Lock()
        self.person_ids = set()
        self.group_sizes = []
        self.status = None
        self.state_sub = rospy.Subscriber("/sim/world_state", WorldState, lambda msg: None,
                                          queue_size=1)
        rospy.Subscriber("/humans/persons/tracked", IdsList, self.on_persons, queue_size=100)
        rospy.Subscriber("/humans/interactions/groups", Group, self.on_group, queue_size=100)
        rospy.Subscriber("/scenario/status", ScenarioStatus, self.on_status, queue_size=10)

    def on_persons(self, msg):
        with self.lock:
            self.person_ids.update(msg.ids)

    def on_group(self, msg):
        with self.lock:
            self.group_sizes.append(len(msg.members))
            self.person_ids.update(msg.members)

    def on_status(self, msg):
        with self.lock:
            self.status = msg


class ScenarioPerceptionModes(unittest.TestCase):
    def test_group_discussion_succeeds_with_this_perception(self):
        pattern = re.compile(rospy.get_param("~person_id_pattern"))
        recorder = Recorder()
        warnings = scenario_start.NodeWarnings()
        self.assertTrue(
            scenario_start.unpause_when_scenario_node_listens("/test_scenario_perception_modes"))
        scenario_start.wait_until_finished(recorder, 200.0)
        with recorder.lock:
            status, person_ids = recorder.status, sorted(recorder.person_ids)
            largest_group = max(recorder.group_sizes, default=0)
        print("persons reported: %s; largest group: %d members" % (person_ids, largest_group))
        self.assertIsNotNone(status, "no /scenario/status")
        self.assertTrue(status.finished, "not finished in state %s" % status.state)
        self.assertTrue(status.success, "%s (warnings: %s)" % (status.reason, warnings.text()))
        self.assertEqual(status.state, "leave")
        # Paul and Irene at least, and their group (ARI is never a member).
        self.assertGreaterEqual(len(person_ids), 2)
        self.assertGreaterEqual(largest_group, 2)
        wrong = [p for p in person_ids if not pattern.match(p)]
        self.assertEqual(wrong, [], "person ids not of the form %s" % pattern.pattern)


if __name__ == "__main__":
    rospy.init_node("test_scenario_perception_modes")
    rostest.rosrun("ari_social_sim", "scenario_perception_modes", ScenarioPerceptionModes)
