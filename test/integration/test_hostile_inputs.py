#!/usr/bin/env python3
"""Must-show 4 of issue 28: rogue transforms, a world reset and a second world publisher."""

import math
import time
import unittest

import actionlib
import rospy
import rostest
import tf2_msgs.msg
from geometry_msgs.msg import TransformStamped
from hri_msgs.msg import IdsList
from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal
from nav_msgs.msg import OccupancyGrid
from rosgraph_msgs.msg import Log
from std_srvs.srv import Trigger
from visualization_msgs.msg import MarkerArray

from ari_social_sim.msg import WorldState

GOAL = (3.0, 3.0)  # m, map frame: free, between ARI's start and Ana


def transform(parent, child, x):
    t = TransformStamped()
    t.header.stamp = rospy.Time.now()
    t.header.frame_id = parent
    t.child_frame_id = child
    t.transform.translation.x = x
    t.transform.rotation.w = 1.0
    return t


def finite_markers(msg):
    for marker in msg.markers:
        values = [marker.pose.position.x, marker.pose.position.y, marker.scale.x]
        values += [v for p in marker.points for v in (p.x, p.y, p.z)]
        if not all(math.isfinite(v) for v in values):
            return False
    return True


class HostileInputs(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("hostile_inputs")
        cls.bodies = []
        cls.non_finite_markers = 0
        cls.errors = []
        rospy.Subscriber("/humans/bodies/tracked", IdsList, cls.on_bodies)
        rospy.Subscriber("/social_mpc/markers", MarkerArray, cls.on_markers)
        rospy.Subscriber("/rosout_agg", Log, cls.on_log)
        cls.tf_pub = rospy.Publisher("/tf", tf2_msgs.msg.TFMessage, queue_size=10)
        cls.move_base = actionlib.SimpleActionClient("move_base", MoveBaseAction)
        assert cls.move_base.wait_for_server(rospy.Duration(20.0))
        deadline = time.time() + 20.0
        while len(cls.bodies) < 4 and time.time() < deadline:
            time.sleep(0.1)

    @classmethod
    def on_bodies(cls, msg):
        cls.bodies = list(msg.ids)

    @classmethod
    def on_markers(cls, msg):
        if not finite_markers(msg):
            cls.non_finite_markers += 1

    @classmethod
    def on_log(cls, msg):
        if msg.level >= Log.ERROR:
            cls.errors.append(msg.msg)

    def drive_to(self, xy, timeout_s=15.0):
        start = time.time()
        self.move_base.send_goal(MoveBaseGoal(target_pose=self.goal_pose(xy)))
        self.assertTrue(self.move_base.wait_for_result(rospy.Duration(timeout_s)))
        self.assertEqual(self.move_base.get_state(), actionlib.GoalStatus.SUCCEEDED,
                         self.move_base.get_goal_status_text())
        return time.time() - start

    def rogue_for(self, seconds, make):
        deadline = time.time() + seconds
        while time.time() < deadline:
            self.tf_pub.publish(tf2_msgs.msg.TFMessage(make()))
            time.sleep(0.02)

    def test_1_rogue_transforms_leave_markers_finite_and_goals_working(self):
        self.assertGreaterEqual(len(self.bodies), 1, "perception tracks nobody")
        body = "body_" + self.bodies[0]
        self.move_base.send_goal(MoveBaseGoal(target_pose=self.goal_pose((6.0, 1.5))))
        for x in (float("inf"), 1e300):
            self.rogue_for(1.0, lambda: [transform("base_footprint", body, x)])
        self.rogue_for(1.0, lambda: [transform("map", "odom", 1e300)])
        self.move_base.cancel_all_goals()
        time.sleep(0.5)
        self.assertEqual(self.non_finite_markers, 0)
        took = self.drive_to(GOAL)
        print("[hostile] goal after the rogue transforms took %.1f s (wall)" % took)
        self.assertEqual(self.non_finite_markers, 0)

    def test_2_reset_late_in_a_run_leaves_no_ghost(self):
        reset = rospy.ServiceProxy("/sim/reset", Trigger)
        self.assertTrue(reset().success)
        time.sleep(1.0)
        before = self.drive_to(GOAL)
        self.assertTrue(reset().success)
        time.sleep(1.0)
        after = self.drive_to(GOAL)
        print("[hostile] the same goal took %.1f s before the reset, %.1f s after" %
              (before, after))
        self.assertLess(after, 1.5 * before + 1.0)

    def test_3_second_world_publisher_is_refused(self):
        states = rospy.Publisher("/sim/world_state", WorldState, queue_size=1)
        maps = rospy.Publisher("/map", OccupancyGrid, queue_size=1, latch=True)
        time.sleep(0.5)
        empty_map = OccupancyGrid()
        empty_map.header.frame_id = "map"
        empty_map.info.resolution = 0.05
        empty_map.info.width = empty_map.info.height = 10
        empty_map.info.origin.orientation.w = 1.0
        empty_map.data = [0] * 100
        maps.publish(empty_map)
        fewest = len(self.bodies)
        deadline = time.time() + 3.0
        while time.time() < deadline:
            state = WorldState()
            state.header.stamp = rospy.Time.now()
            state.header.frame_id = "map"
            states.publish(state)  # a world with nobody in it
            fewest = min(fewest, len(self.bodies))
            time.sleep(0.05)
        states.unregister()
        maps.unregister()
        print("[hostile] perception tracked at least %d bodies while a second publisher ran" %
              fewest)
        self.assertGreaterEqual(fewest, 1)
        refused = [e for e in self.errors if "second publisher" in e and "/hostile_inputs" in e]
        self.assertTrue(refused, "no error names the second publisher: %s" % self.errors)
        print("[hostile] %s" % refused[0])

    @staticmethod
    def goal_pose(xy):
        goal = MoveBaseGoal().target_pose
        goal.header.frame_id = "map"
        goal.pose.position.x, goal.pose.position.y = xy
        goal.pose.orientation.w = 1.0
        return goal


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "hostile_inputs", HostileInputs)
