#!/usr/bin/python3
"""rostest: in 3D mode world_node drops /ground_truth_odom and /joint_states messages with a
non-finite field it uses, counts them on /diagnostics, and follows the next valid ones (README,
world_node)."""
import math
import time
import unittest

import rospy
import rostest
from nav_msgs.msg import Odometry
from sensor_msgs.msg import JointState

from ari_social_sim.msg import WorldState
from test_world_node import Latest, LatestDiagnostics

NAN = float("nan")


def ground_truth(x, y, yaw):
    truth = Odometry()
    truth.header.frame_id = "map"
    truth.pose.pose.position.x = x
    truth.pose.pose.position.y = y
    truth.pose.pose.orientation.z = math.sin(0.5 * yaw)
    truth.pose.pose.orientation.w = math.cos(0.5 * yaw)
    return truth


class WorldNode3dInputs(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("world_node_3d_inputs")
        cls.state = Latest("/sim/world_state", WorldState)
        cls.diagnostics = LatestDiagnostics()

    def test_non_finite_ground_truth_and_joint_states_are_dropped(self):
        truth = rospy.Publisher("/ground_truth_odom", Odometry, queue_size=10)
        joints = rospy.Publisher("/joint_states", JointState, queue_size=10)
        limit = time.monotonic() + 10
        while time.monotonic() < limit and (truth.get_num_connections() == 0 or
                                            joints.get_num_connections() == 0):
            time.sleep(0.05)
        before = self.diagnostics.wait()
        bad_truths = [ground_truth(NAN, 2.6, 3.0), ground_truth(8.6, 2.6, NAN)]
        bad_truths[1].pose.pose.orientation.w = NAN  # the yaw is NaN, not only a component
        for bad in bad_truths:
            truth.publish(bad)
            joints.publish(JointState(name=["head_1_joint"], position=[NAN]))
            time.sleep(0.1)
        # The next valid messages move ARI (from (8.6, 2.6) in this scene) and pan its head.
        for _ in range(10):
            truth.publish(ground_truth(8.4, 2.6, 3.0))
            joints.publish(JointState(name=["head_1_joint"], position=[0.4]))
            time.sleep(0.05)
        state = self.state.wait(lambda m: abs(m.ari.pose.x - 8.4) < 1e-3 and
                                abs(m.ari.head_pan - 0.4) < 1e-6)
        self.assertTrue(all(math.isfinite(v) for v in (state.ari.pose.x, state.ari.pose.y,
                                                       state.ari.pose.theta, state.ari.head_pan)))
        x = "dropped /ground_truth_odom pose.position.x"
        yaw = "dropped /ground_truth_odom pose.orientation"
        pan = "dropped /joint_states position[head_1_joint]"
        after = self.diagnostics.wait(lambda d: d[x] > before[x] and d[yaw] > before[yaw] and
                                      d[pan] >= before[pan] + 2)
        self.assertEqual((after[x] - before[x], after[yaw] - before[yaw], after[pan] - before[pan]),
                         (1, 1, 2))
        rospy.loginfo("/diagnostics in 3D mode: %s", after)


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "world_node_3d_inputs", WorldNode3dInputs)
