#!/usr/bin/python3
"""rostest: point_head_action goals on a missing or vanishing tf frame abort naming the frame
within a second of wall time and never stop /clock; hostile goal fields are refused by name.

Every wait here is on the wall clock: a test that waited on sim time would hang with the node."""
import threading
import time
import unittest

import actionlib
import rospy
import rostest
import tf2_ros
from actionlib_msgs.msg import GoalStatus
from geometry_msgs.msg import PointStamped, TransformStamped, Vector3
from rosgraph_msgs.msg import Clock
from trajectory_msgs.msg import JointTrajectoryPoint

from ari_social_sim.msg import (FollowJointTrajectoryAction, FollowJointTrajectoryGoal,
                                FollowJointTrajectoryResult, JointTolerance, PointHeadAction,
                                PointHeadGoal)
from wall_clock import wait_wall

ABORT_BOUND_WALL_S = 1.0  # the node's own bound is 0.5 s; the rest is slack for a loaded machine
TERMINAL = (GoalStatus.ABORTED, GoalStatus.REJECTED, GoalStatus.SUCCEEDED, GoalStatus.PREEMPTED,
            GoalStatus.RECALLED, GoalStatus.LOST)
LEAVING_FRAME = "person_leaving"
# ARI stands at room_6x6's centre (3, 3) facing +x: a head 2 m ahead, 0.4 m to the left.
LEAVING_PERSON = (5.0, 3.4, 0.0)
HEAD_HEIGHT_M = 1.5


class ClockWatch:
    """The newest /clock and the wall time it came."""

    def __init__(self):
        self._lock = threading.Lock()
        self.sim_s = None
        rospy.Subscriber("/clock", Clock, self._on_clock, queue_size=10)

    def _on_clock(self, msg):
        with self._lock:
            self.sim_s = msg.clock.to_sec()

    def now(self):
        with self._lock:
            return self.sim_s


def target(frame, x=0.0, y=0.0, z=HEAD_HEIGHT_M):
    point = PointStamped()
    point.header.frame_id = frame
    point.point.x, point.point.y, point.point.z = x, y, z
    return point


def head_goal(point, min_duration_s=0.0, max_velocity=0.0):
    return PointHeadGoal(target=point, pointing_axis=Vector3(0, 0, 1),
                         pointing_frame="head_front_camera_color_optical_frame",
                         min_duration=rospy.Duration.from_sec(min_duration_s),
                         max_velocity=max_velocity)


class PointHeadLostFrame(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("point_head_lost_frame")
        cls.clock = ClockWatch()
        assert wait_wall(lambda: cls.clock.now() is not None, 60.0), "no /clock"
        cls.point_head = actionlib.SimpleActionClient("/head_controller/point_head_action",
                                                      PointHeadAction)
        cls.head = actionlib.SimpleActionClient("/head_controller/follow_joint_trajectory",
                                                FollowJointTrajectoryAction)
        assert wait_wall(lambda: cls.point_head.wait_for_server(rospy.Duration(0.1)), 60.0)
        assert wait_wall(lambda: cls.head.wait_for_server(rospy.Duration(0.1)), 60.0)
        cls.broadcaster = tf2_ros.TransformBroadcaster()

    def send_and_wait(self, client, goal, timeout_s=5.0):
        """Sends `goal`; returns its final state, text and the wall time it took, once its
        result has come too: status and result are separate topics, and the status can come
        first."""
        start = time.monotonic()
        client.send_goal(goal)
        self.assertTrue(wait_wall(lambda: client.get_state() in TERMINAL
                                  and client.get_result() is not None, timeout_s),
                        "no result within %.1f s of wall time" % timeout_s)
        return client.get_state(), client.get_goal_status_text(), time.monotonic() - start

    def assert_clock_runs_on(self, label):
        before = self.clock.now()
        time.sleep(0.5)
        advance = self.clock.now() - before
        rospy.loginfo("%s: /clock advanced %.3f s in the next 0.5 s of wall time", label, advance)
        print("%s: /clock advanced %.3f s in the next 0.5 s of wall time" % (label, advance))
        self.assertGreater(advance, 0.2)

    def report(self, text):
        rospy.loginfo(text)
        print(text)

    def test_1_unknown_frame_aborts_and_the_clock_runs(self):
        clock_at_goal = self.clock.now()
        state, text, wall_s = self.send_and_wait(self.point_head,
                                                 head_goal(target("person_human10")))
        clock_advance = self.clock.now() - clock_at_goal
        self.report("unknown frame: %s after %.3f s of wall time, /clock advanced %.3f s "
                    "meanwhile: '%s'" % (GoalStatus.to_string(state), wall_s, clock_advance, text))
        self.assertEqual(state, GoalStatus.ABORTED)
        self.assertIn("'person_human10'", text)
        self.assertIn("target.header.frame_id", text)
        self.assertLess(wall_s, ABORT_BOUND_WALL_S)
        self.assertGreater(clock_advance, 0.2)
        self.assert_clock_runs_on("after the unknown frame")

    def publish_leaving_person(self, seconds):
        """The frame for `seconds` of wall time at 20 Hz, stamped in sim time; then nothing.
        Keeps the wall time of the last transform in self.last_sent."""
        transform = TransformStamped()
        transform.header.frame_id = "map"
        transform.child_frame_id = LEAVING_FRAME
        transform.transform.translation.x, transform.transform.translation.y, _ = LEAVING_PERSON
        transform.transform.rotation.w = 1.0
        limit = time.monotonic() + seconds
        while time.monotonic() < limit:
            transform.header.stamp = rospy.Time.now()
            self.broadcaster.sendTransform(transform)
            self.last_sent = time.monotonic()
            time.sleep(0.05)

    def test_2_frame_that_stops_coming_aborts_mid_goal(self):
        publisher = threading.Thread(target=self.publish_leaving_person, args=(1.0,))
        publisher.start()
        time.sleep(0.3)
        # min_duration 5 s: the head is still on its way when the frame stops.
        self.point_head.send_goal(head_goal(target(LEAVING_FRAME), min_duration_s=5.0))
        self.assertTrue(wait_wall(lambda: self.point_head.get_state() == GoalStatus.ACTIVE, 0.6))
        publisher.join()
        stopped = self.last_sent
        clock_at_stop = self.clock.now()
        self.assertEqual(self.point_head.get_state(), GoalStatus.ACTIVE, "ended before the frame")
        self.assertTrue(wait_wall(lambda: self.point_head.get_state() in TERMINAL, 5.0))
        wall_s = time.monotonic() - stopped
        clock_advance = self.clock.now() - clock_at_stop
        state, text = self.point_head.get_state(), self.point_head.get_goal_status_text()
        self.report("frame gone mid-goal: %s %.3f s of wall time after its last transform, "
                    "/clock advanced %.3f s meanwhile: '%s'"
                    % (GoalStatus.to_string(state), wall_s, clock_advance, text))
        self.assertEqual(state, GoalStatus.ABORTED)
        self.assertIn("'%s'" % LEAVING_FRAME, text)
        self.assertLess(wall_s, ABORT_BOUND_WALL_S)
        self.assertGreater(clock_advance, 0.2)
        self.assert_clock_runs_on("after the frame left")

    def test_3_hostile_point_head_fields_are_refused_by_name(self):
        cases = [
            (head_goal(target("base_footprint", x=float("nan"))),
             "target.point.x: expected a finite number, got nan"),
            (head_goal(target("base_footprint", x=2.0, y=1.0), max_velocity=1e-300),
             "max_velocity: expected a speed that moves the head"),
            (head_goal(target("base_footprint", x=2.0), max_velocity=1e308),
             "max_velocity: expected 0 (the joints' limits) or a finite number (0, 3] rad/s"),
            (head_goal(target("base_footprint", x=2.0), min_duration_s=1e9),
             "min_duration: expected a finite number [0, 60] s, got 1e+09"),
        ]
        for goal, expected in cases:
            state, text, wall_s = self.send_and_wait(self.point_head, goal)
            self.report("point_head: %s in %.3f s: '%s'" % (GoalStatus.to_string(state), wall_s,
                                                            text))
            self.assertEqual(state, GoalStatus.REJECTED)
            self.assertIn(expected, text)

    def test_4_hostile_trajectory_fields_are_refused_by_name(self):
        def goal(position=0.3, velocity=None, tolerance=0.0):
            g = FollowJointTrajectoryGoal()
            g.trajectory.joint_names = ["head_1_joint", "head_2_joint"]
            point = JointTrajectoryPoint(positions=[position, 0.0],
                                         time_from_start=rospy.Duration(1.0))
            if velocity is not None:
                point.velocities = [velocity, 0.0]
            g.trajectory.points = [point]
            g.goal_tolerance = [JointTolerance(name="head_1_joint", position=tolerance)]
            return g

        cases = [
            (goal(tolerance=float("nan")), "goal_tolerance[0].position: expected -1 (none)"),
            (goal(velocity=1e308),
             "trajectory.points[0].velocities[0] (head_1_joint): expected a finite number "
             "[-3, 3] rad/s, got 1e+308"),
        ]
        for hostile, expected in cases:
            state, text, wall_s = self.send_and_wait(self.head, hostile)
            self.report("follow_joint_trajectory: %s in %.3f s: '%s'"
                        % (GoalStatus.to_string(state), wall_s, text))
            self.assertEqual(state, GoalStatus.REJECTED)
            self.assertEqual(self.head.get_result().error_code,
                             FollowJointTrajectoryResult.INVALID_GOAL)
            self.assertIn(expected, text)
        # The controller still works after them.
        state, text, _ = self.send_and_wait(self.head, goal(), timeout_s=10.0)
        self.assertEqual(state, GoalStatus.SUCCEEDED, text)


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "point_head_lost_frame", PointHeadLostFrame)
