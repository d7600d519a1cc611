#!/usr/bin/python3
"""rostest: in 3D mode the 2D world's ARI is the physics' ARI (3D mode, docs/physics.md)."""
import math
import time
import unittest

import rosgraph
import rospy
import rostest
from geometry_msgs.msg import Twist, Vector3
from nav_msgs.msg import Odometry
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

from ari_social_sim.msg import WorldState


def publishers_of(topic):
    master = rosgraph.Master("/world_3d_mode")
    publishers, _, _ = master.getSystemState()
    return sorted(next((nodes for name, nodes in publishers if name == topic), []))


class World3dMode(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("world_3d_mode")

    def test_world_follows_the_physics_ari(self):
        # Only the physics drives and reports ARI's base.
        rospy.wait_for_message("/ground_truth_odom", Odometry, timeout=60)
        self.truths = []
        rospy.Subscriber("/ground_truth_odom", Odometry, self.truths.append, queue_size=200)
        self.assertEqual(publishers_of("/mobile_base_controller/odom"), ["/ari_physics_node"])
        start = rospy.wait_for_message("/sim/world_state", WorldState, timeout=30).ari.pose
        cmd_vel = rospy.Publisher("/mobile_base_controller/cmd_vel", Twist, queue_size=1)
        head = rospy.Publisher("/head_controller/command", JointTrajectory, queue_size=1)
        rospy.sleep(0.5)
        # Turning in place (people walk past ARI's front in this scene) and panning the head.
        head.publish(JointTrajectory(joint_names=["head_1_joint", "head_2_joint"], points=[
            JointTrajectoryPoint(positions=[0.5, 0.0], time_from_start=rospy.Duration(0.5))]))
        end = rospy.Time.now() + rospy.Duration(3.0)
        rate = rospy.Rate(20)
        while rospy.Time.now() < end:
            cmd_vel.publish(Twist(angular=Vector3(0, 0, 0.5)))
            rate.sleep()
        for _ in range(30):
            cmd_vel.publish(Twist())
            rate.sleep()
        state = rospy.wait_for_message("/sim/world_state", WorldState, timeout=10)
        # world_node steps onto the latest ground truth it has received, at most one of its 0.05 s
        # steps old (people in this scene may still be nudging ARI): compare with those.
        stamp = state.header.stamp.to_sec()
        candidates = [t for t in self.truths if stamp - 0.11 <= t.header.stamp.to_sec() <= stamp]
        self.assertTrue(candidates, "no ground truth in the world step before the state")

        def gaps(truth):
            q = truth.pose.pose.orientation
            yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
            return (abs(math.remainder(state.ari.pose.theta - yaw, 2 * math.pi)),
                    math.hypot(state.ari.pose.x - truth.pose.pose.position.x,
                               state.ari.pose.y - truth.pose.pose.position.y))

        yaw_gap, gap = min((gaps(t) for t in candidates), key=lambda g: g[0] + g[1])
        turned = math.remainder(state.ari.pose.theta - start.theta, 2 * math.pi)
        rospy.loginfo("3D mode: world ARI turned %.3f rad, %.4f rad and %.4f m from the physics' "
                      "ground truth; head pan %.3f rad", turned, yaw_gap, gap, state.ari.head_pan)
        # 0.5 rad/s for 3 s less the 2.094 rad/s^2 ramps: about 1.5 rad, counter-clockwise.
        self.assertGreater(turned, 1.2)
        self.assertLess(yaw_gap, 0.01)
        self.assertLess(gap, 0.01)
        self.assertAlmostEqual(state.ari.head_pan, 0.5, delta=0.02)

if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "world_3d_mode", World3dMode)
