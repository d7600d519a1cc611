#!/usr/bin/python3
"""rostest (fuzz_physics.test): the fuzz test of test_fuzz.py aimed at ari_physics_node, in the
default standalone launch (its own /clock): seeded PointHead and FollowJointTrajectory goals,
query_state requests, controller commands, cmd_vel, /sim/world_state and /tf transforms, each
valid but for one hostile field (fuzz_values.py).

Refusals (goals rejected or aborted, requests failed) are counted per field and printed, with the
node's own drop counters from /diagnostics. Afterwards the node must answer, /clock advance,
every joint state and the ground truth be finite, and a normal goal of each kind succeed. Every
wait is on the wall clock: a test that waited on sim time would hang with the node.
"""
import math
import random
import sys
import threading
import time
import unittest
from collections import Counter

import actionlib
import rosnode
import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PointStamped, TransformStamped, Twist, Vector3
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import JointState
from tf2_msgs.msg import TFMessage
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

from ari_social_sim.msg import (FollowJointTrajectoryAction, FollowJointTrajectoryGoal,
                                HumanState, JointTolerance, JointTrajectoryControllerState,
                                PointHeadAction, PointHeadGoal, WorldState)
from ari_social_sim.srv import QueryTrajectoryState
from fuzz_values import mutate
from wall_clock import wait_wall

SEED = 20261128
GOALS = 160
REQUESTS = 100
TOPIC_MESSAGES = 500
CONTROLLERS = ["head_controller", "arm_left_controller", "hand_right_controller"]
PERSON_FRAME = "person_fuzz"  # a frame this test broadcasts, as perception does a person's
CAMERA_FRAME = "head_front_camera_color_optical_frame"
TERMINAL = (GoalStatus.ABORTED, GoalStatus.REJECTED, GoalStatus.SUCCEEDED, GoalStatus.PREEMPTED,
            GoalStatus.RECALLED, GoalStatus.LOST)


class Latest:
    """The newest message of a topic, and every /diagnostics counter of the node."""

    def __init__(self):
        self.lock = threading.Lock()
        self.clock_s = None
        self.joints = None
        self.ground_truth = None
        self.counters = {}
        self.controller_joints = {}
        self.controller_positions = {}  # where each controller's joints stand now
        rospy.Subscriber("/clock", Clock, self.keep("clock_s", lambda m: m.clock.to_sec()))
        rospy.Subscriber("/joint_states", JointState, self.keep("joints", lambda m: m))
        rospy.Subscriber("/ground_truth_odom", Odometry, self.keep("ground_truth", lambda m: m))
        rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diagnostics)
        for controller in CONTROLLERS:
            rospy.Subscriber("/%s/state" % controller, JointTrajectoryControllerState,
                             self.on_controller_state, controller)

    def keep(self, name, value):
        def store(msg):
            with self.lock:
                setattr(self, name, value(msg))
        return store

    def on_diagnostics(self, msg):
        with self.lock:
            for status in msg.status:
                if status.name.startswith("ari_physics_node"):
                    self.counters.update({kv.key: int(kv.value) for kv in status.values})

    def on_controller_state(self, msg, controller):
        with self.lock:
            self.controller_joints[controller] = list(msg.joint_names)
            self.controller_positions[controller] = list(msg.actual.positions)

    def get(self, name):
        with self.lock:
            return getattr(self, name)


def head_goal(rng):
    point = PointStamped()
    point.header.frame_id = rng.choice(["base_footprint", PERSON_FRAME])
    point.point.x = rng.uniform(1.0, 3.0) if point.header.frame_id == "base_footprint" else 0.0
    point.point.y = rng.uniform(-1.0, 1.0)
    point.point.z = 1.5
    return PointHeadGoal(target=point, pointing_axis=Vector3(0, 0, 1), pointing_frame=CAMERA_FRAME,
                         min_duration=rospy.Duration(0.3), max_velocity=1.0)


def trajectory(rng, joints, positions):
    """Two points within the joints' limits: halfway to 0 from where the joints stand (every
    limit range of ARI's joints holds 0), then back."""
    halfway = [p * rng.uniform(0.3, 0.7) for p in positions]
    points = [JointTrajectoryPoint(positions=target, time_from_start=rospy.Duration(0.4 * (k + 1)))
              for k, target in enumerate([halfway, list(positions)])]
    return JointTrajectory(joint_names=list(joints), points=points)


def trajectory_goal(rng, joints, positions):
    goal = FollowJointTrajectoryGoal(trajectory=trajectory(rng, joints, positions))
    goal.goal_tolerance = [JointTolerance(name=joints[0], position=0.5)]
    goal.goal_time_tolerance = rospy.Duration(2.0)
    return goal


def world_state(rng):
    state = WorldState()
    state.header.stamp = rospy.Time.now()
    human = HumanState(id=10, role="visitor", age=40.0)
    # ARI stands at room_6x6's centre (3, 3): a person 1.5 m or more ahead of it.
    human.pose.x, human.pose.y = rng.uniform(4.5, 5.5), rng.uniform(1.0, 5.0)
    state.humans = [human]
    return state


def person_transform():
    transform = TransformStamped()
    transform.header.stamp = rospy.Time.now()
    transform.header.frame_id, transform.child_frame_id = "map", PERSON_FRAME
    transform.transform.translation.x, transform.transform.translation.y = 5.0, 3.4
    transform.transform.rotation.w = 1.0
    return transform


class FuzzPhysics(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("fuzz_physics")
        cls.latest = Latest()
        assert wait_wall(lambda: cls.latest.get("clock_s") is not None, 60.0), "no /clock"
        cls.point_head = actionlib.SimpleActionClient("/head_controller/point_head_action",
                                                      PointHeadAction)
        cls.trajectories = {c: actionlib.SimpleActionClient("/%s/follow_joint_trajectory" % c,
                                                            FollowJointTrajectoryAction)
                            for c in CONTROLLERS}
        for client in [cls.point_head] + list(cls.trajectories.values()):
            assert wait_wall(lambda: client.wait_for_server(rospy.Duration(0.1)), 60.0)
        assert wait_wall(lambda: len(cls.latest.get("controller_joints")) == len(CONTROLLERS),
                         30.0), "no controller states"
        cls.joints = cls.latest.get("controller_joints")
        cls.publishers = {}

    def positions(self, controller):
        return self.latest.get("controller_positions")[controller]

    def publish(self, topic, msg_class, msg):
        if topic not in self.publishers:
            self.publishers[topic] = rospy.Publisher(topic, msg_class, queue_size=100)
            wait_wall(lambda: self.publishers[topic].get_num_connections() > 0, 2.0)
        self.publishers[topic].publish(msg)

    def keep_person_frame(self, stop):
        while not stop.is_set():
            self.publish("/tf", TFMessage, TFMessage([person_transform()]))
            time.sleep(0.05)

    def fuzz_goals(self, rng, sent, refused):
        for _ in range(GOALS):
            name = rng.choice(["point_head"] + CONTROLLERS)
            if name == "point_head":
                client, goal = self.point_head, head_goal(rng)
            else:
                client, goal = self.trajectories[name], trajectory_goal(rng, self.joints[name],
                                                                     self.positions(name))
            key = "%s %s" % (name, mutate(rng, goal))
            sent[key] += 1
            client.send_goal(goal)
            wait_wall(lambda: client.get_state() in TERMINAL, 0.3)
            if client.get_state() in (GoalStatus.REJECTED, GoalStatus.ABORTED):
                refused[key] += 1
            client.cancel_all_goals()

    def fuzz_requests(self, rng, sent, refused, errors):
        proxies = {}
        for controller in CONTROLLERS:
            name = "/%s/query_state" % controller
            rospy.wait_for_service(name, timeout=30.0)
            proxies[controller] = rospy.ServiceProxy(name, QueryTrajectoryState)
        for _ in range(REQUESTS):
            controller = rng.choice(CONTROLLERS)
            request = QueryTrajectoryState._request_class(time=rospy.Time.now())
            key = "/%s/query_state %s" % (controller, mutate(rng, request))
            sent[key] += 1
            try:
                proxies[controller](request)
            except rospy.ServiceException:  # refused: the node answers the call with an error
                refused[key] += 1
            except rospy.ROSException as e:
                errors.append("%s: %s" % (key, e))

    def fuzz_topics(self, rng, sent):
        for _ in range(TOPIC_MESSAGES):
            kind = rng.choice(["command", "cmd_vel", "world_state", "tf"])
            if kind == "command":
                controller = rng.choice(CONTROLLERS)
                topic = "/%s/command" % controller
                msg = trajectory(rng, self.joints[controller], self.positions(controller))
            elif kind == "cmd_vel":
                topic, msg = "/mobile_base_controller/cmd_vel", Twist()
                msg.linear.x, msg.angular.z = rng.uniform(-0.2, 0.5), rng.uniform(-1.0, 1.0)
            elif kind == "world_state":
                topic, msg = "/sim/world_state", world_state(rng)
            else:
                topic, msg = "/tf", TFMessage([person_transform()])
            sent["%s %s" % (topic, mutate(rng, msg))] += 1
            self.publish(topic, type(msg), msg)
            time.sleep(0.004)

    def test_hostile_input_leaves_the_physics_running_and_finite(self):
        rng = random.Random(SEED)
        sent, refused, errors = Counter(), Counter(), []
        stop = threading.Event()
        frame_keeper = threading.Thread(target=self.keep_person_frame, args=(stop,))
        frame_keeper.start()
        try:
            self.fuzz_goals(rng, sent, refused)
            self.fuzz_requests(rng, sent, refused, errors)
            self.fuzz_topics(rng, sent)
        finally:
            stop.set()
            frame_keeper.join()
        print("[ measured ] %d hostile goals, requests and messages to ari_physics_node, %d "
              "refused, %d failed calls" % (sum(sent.values()), sum(refused.values()),
                                            len(errors)))
        for key in sorted(sent):
            print("  %-78s sent %4d refused %4d" % (key, sent[key], refused[key]))
        time.sleep(1.5)  # the node's next /diagnostics (1 Hz)
        print("[ measured ] ari_physics_node's input counters (/diagnostics):")
        for key, value in sorted(self.latest.get("counters").items()):
            print("  %-78s %6d" % (key, value))
        self.assertGreaterEqual(sum(sent.values()), 700)
        self.assertEqual(errors, [])
        self.assertGreater(sum(v for k, v in self.latest.get("counters").items()
                               if k.startswith("dropped")), 0, "no drop counted")
        self.assert_still_sound()

    def assert_still_sound(self):
        self.assertTrue(rosnode.rosnode_ping("/ari_physics_node", max_count=1))
        # The people of the last (hostile) world state walk on; a world_node would have moved
        # them since. An empty world, as after everyone left.
        empty = WorldState()
        empty.header.stamp = rospy.Time.now()
        self.publish("/sim/world_state", WorldState, empty)
        before = self.latest.get("clock_s")
        self.assertTrue(wait_wall(lambda: self.latest.get("clock_s") > before + 0.2, 10.0),
                        "/clock stopped")
        joints = self.latest.get("joints")
        values = list(joints.position) + list(joints.velocity)
        self.assertTrue(all(math.isfinite(v) for v in values), joints)
        pose = self.latest.get("ground_truth").pose.pose.position
        self.assertTrue(all(math.isfinite(v) for v in (pose.x, pose.y, pose.z)), pose)
        # A normal goal of each kind still succeeds.
        rng = random.Random(SEED + 1)
        normal = [(self.point_head, head_goal(rng))]
        normal[0][1].target.header.frame_id = "base_footprint"
        normal[0][1].target.point.x = 2.0
        normal += [(self.trajectories[c], trajectory_goal(rng, self.joints[c], self.positions(c)))
                   for c in CONTROLLERS]
        for client, goal in normal:
            client.send_goal(goal)
            self.assertTrue(wait_wall(lambda: client.get_state() in TERMINAL, 30.0))
            self.assertEqual(client.get_state(), GoalStatus.SUCCEEDED,
                             client.get_goal_status_text())


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "fuzz_physics", FuzzPhysics, sys.argv)
