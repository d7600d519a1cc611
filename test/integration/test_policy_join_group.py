#!/usr/bin/python3
"""rostest, must-show 4 of issue 15 (policy_join_group.test): the trained join-group policy drives
ARI live through social_mpc_node and the scenario succeeds. That the policy, not SocialMPC, drove
shows in what social_mpc_node publishes: commands at the policy's 20 Hz while the goal is pursued
(SocialMPC sends 10 Hz) and no /social_mpc/plan (a policy has none)."""
import threading
import unittest

import rospy
import rostest
import scenario_start
from geometry_msgs.msg import Twist
from nav_msgs.msg import Path

from ari_social_sim.msg import ScenarioStatus


class Recorder:
    def __init__(self):
        self.lock = threading.Lock()
        self.command_times = []
        self.plans = 0
        self.status = None
        rospy.Subscriber("/mobile_base_controller/cmd_vel", Twist, self.on_command, queue_size=100)
        rospy.Subscriber("/social_mpc/plan", Path, self.on_plan, queue_size=10)
        rospy.Subscriber("/scenario/status", ScenarioStatus, self.on_status, queue_size=10)

    def on_command(self, msg):
        with self.lock:
            self.command_times.append(rospy.get_time())

    def on_plan(self, msg):
        with self.lock:
            self.plans += 1

    def on_status(self, msg):
        with self.lock:
            self.status = msg


class PolicyJoinGroup(unittest.TestCase):
    def test_the_trained_policy_joins_the_group_live(self):
        recorder = Recorder()
        warnings = scenario_start.NodeWarnings()
        self.assertTrue(scenario_start.unpause_when_scenario_node_listens("/test_policy_join_group"))
        scenario_start.wait_until_finished(recorder, 150.0)
        with recorder.lock:
            status, times, plans = recorder.status, list(recorder.command_times), recorder.plans
        self.assertIsNotNone(status, "no /scenario/status")
        self.assertTrue(status.finished, "not finished in state %s" % status.state)
        print("outcome: success=%s at %.2f s of sim time in state %s (%s); %d commands, %d plans"
              % (status.success, status.header.stamp.to_sec(), status.state, status.reason,
                 len(times), plans))
        self.assertTrue(status.success, "%s (warnings: %s)" % (status.reason, warnings.text()))
        self.assertEqual(plans, 0, "SocialMPC planned: the policy did not drive")
        self.assertGreater(len(times), 20)
        span = times[-1] - times[0]
        rate = (len(times) - 1) / span if span > 0 else 0.0
        self.assertGreater(rate, 15.0, "commands at %.1f Hz of sim time, not the policy's 20" % rate)


if __name__ == "__main__":
    rospy.init_node("test_policy_join_group")
    rostest.rosrun("ari_social_sim", "test_policy_join_group", PolicyJoinGroup)
