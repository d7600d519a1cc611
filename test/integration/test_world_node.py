#!/usr/bin/python3
"""rostest: world_node's topics and services behave as documented (README, world_node)."""
import threading
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Point, Pose2D, Twist
from nav_msgs.msg import OccupancyGrid, Odometry
from rosgraph_msgs.msg import Clock
from std_srvs.srv import SetBool, Trigger

from ari_social_sim.msg import WorldState
from ari_social_sim.srv import (AddGroupMembers, CreateGroup, RemoveHuman, Say, SetGazeTargets,
                                SetGoal, SetGroupCentre, SetPose, SetVelocity, SpawnHuman,
                                StepSimulation)

STEP_S = 0.05  # world_node's default step


class Latest:
    """Keeps the last message of a topic and how many arrived."""

    def __init__(self, topic, msg_type):
        self.msg = None
        self.count = 0
        self._lock = threading.Lock()
        rospy.Subscriber(topic, msg_type, self._on_msg, queue_size=10)

    def _on_msg(self, msg):
        with self._lock:
            self.msg = msg
            self.count += 1

    def wait(self, predicate=lambda m: True, timeout=20.0):
        # Wall time: sim time stands still while the world is paused.
        limit = time.monotonic() + timeout
        while time.monotonic() < limit:
            with self._lock:
                if self.msg is not None and predicate(self.msg):
                    return self.msg
            time.sleep(0.02)
        raise AssertionError("timed out waiting on a message")


def human(state, human_id):
    return next((h for h in state.humans if h.id == human_id), None)


class WorldNodeContract(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("world_node_contract")
        cls.clock = Latest("/clock", Clock)
        cls.state = Latest("/sim/world_state", WorldState)
        cls.odom = Latest("/mobile_base_controller/odom", Odometry)
        for name in ["spawn_human", "remove_human", "set_goal", "set_velocity", "set_pose",
                     "create_group", "add_group_members", "set_group_centre", "say",
                     "set_gaze_targets", "reset", "pause", "step"]:
            rospy.wait_for_service("/sim/" + name, timeout=30)
        cls.call = {
            "spawn": rospy.ServiceProxy("/sim/spawn_human", SpawnHuman),
            "remove": rospy.ServiceProxy("/sim/remove_human", RemoveHuman),
            "goal": rospy.ServiceProxy("/sim/set_goal", SetGoal),
            "velocity": rospy.ServiceProxy("/sim/set_velocity", SetVelocity),
            "pose": rospy.ServiceProxy("/sim/set_pose", SetPose),
            "group": rospy.ServiceProxy("/sim/create_group", CreateGroup),
            "members": rospy.ServiceProxy("/sim/add_group_members", AddGroupMembers),
            "centre": rospy.ServiceProxy("/sim/set_group_centre", SetGroupCentre),
            "say": rospy.ServiceProxy("/sim/say", Say),
            "gaze": rospy.ServiceProxy("/sim/set_gaze_targets", SetGazeTargets),
            "reset": rospy.ServiceProxy("/sim/reset", Trigger),
            "pause": rospy.ServiceProxy("/sim/pause", SetBool),
            "step": rospy.ServiceProxy("/sim/step", StepSimulation),
        }

    def setUp(self):
        self.assertTrue(self.call["pause"](False).success)
        self.assertTrue(self.call["reset"]().success)

    def test_01_clock_advances_and_world_state_follows(self):
        first = self.clock.wait().clock.to_sec()
        later = self.clock.wait(lambda m: m.clock.to_sec() > first + 1.0).clock.to_sec()
        self.assertGreater(later, first + 1.0)
        state = self.state.wait(lambda m: m.header.stamp.to_sec() > first)
        self.assertEqual(state.header.frame_id, "map")
        # The default scene: ARI and six people, two groups.
        self.assertTrue(state.has_ari)
        self.assertEqual(len(state.humans), 6)
        self.assertEqual(sorted(g.id for g in state.groups), [1, 2])

    def test_02_map_is_latched_with_world_size_and_walls(self):
        grid = rospy.wait_for_message("/map", OccupancyGrid, timeout=10)
        # hospital_waiting_room: floor 12.4 x 9.4 m from (-0.2, -0.2) at 0.05 m: 248 x 188 cells.
        self.assertAlmostEqual(grid.info.resolution, 0.05, places=5)
        self.assertEqual((grid.info.width, grid.info.height), (248, 188))
        self.assertAlmostEqual(grid.info.origin.position.x, -0.2, places=5)

        def cell(x, y):
            col = int((x - grid.info.origin.position.x) / grid.info.resolution)
            row = int((y - grid.info.origin.position.y) / grid.info.resolution)
            return grid.data[row * grid.info.width + col]

        self.assertEqual(cell(3.0, 0.0), 100)    # south wall
        self.assertEqual(cell(0.0, 5.0), 100)    # west wall
        self.assertEqual(cell(5.7, 0.0), 0)      # the entrance door
        self.assertEqual(cell(6.0, 3.0), 0)      # open floor
        # People are never on the map: Marie stands at (2.0, 3.0).
        self.assertEqual(cell(2.0, 3.0), 0)

    def test_03_spawn_goal_velocity_pose_and_remove(self):
        spawned = self.call["spawn"](id=0, name="Zoe", role="visitor", pose=Pose2D(6.0, 3.0, 0.0),
                                     age=30.0, gender="female", mask=True, emotion="happy")
        self.assertTrue(spawned.success, spawned.message)
        zoe = spawned.id
        state = self.state.wait(lambda m: human(m, zoe) is not None)
        h = human(state, zoe)
        self.assertEqual((h.name, h.gender, h.mask, h.emotion), ("Zoe", 1, True, 1))
        self.assertAlmostEqual(h.age, 30.0)

        self.assertTrue(self.call["goal"](id=zoe, goal=Pose2D(6.0, 4.5, 1.57)).success)
        state = self.state.wait(lambda m: abs(human(m, zoe).pose.y - 4.5) < 0.05)
        self.assertEqual(human(state, zoe).motion_mode, 2)

        self.assertTrue(self.call["velocity"](id=zoe, vx=-0.5, vy=0.0, omega=0.0).success)
        state = self.state.wait(lambda m: human(m, zoe).pose.x < 5.5)
        self.assertAlmostEqual(human(state, zoe).velocity.linear.x, -0.5, places=2)

        self.assertTrue(self.call["pose"](id=zoe, pose=Pose2D(7.0, 3.0, 0.0)).success)
        self.assertTrue(self.call["remove"](id=zoe).success)
        self.state.wait(lambda m: human(m, zoe) is None)

    def test_04_groups_say_and_gaze(self):
        made = self.call["group"](id=0, members=[30], centre=Point(6.0, 3.0, 0.0), ospace_radius=0.0)
        self.assertTrue(made.success, made.message)
        self.assertTrue(self.call["members"](group_id=made.id, members=[20]).success)
        self.assertTrue(self.call["centre"](group_id=made.id, centre=Point(6.5, 3.5, 0.0)).success)
        # A state published between the two service calls has both members but the old centre:
        # wait for one that has both.
        state = self.state.wait(lambda m: any(g.id == made.id and sorted(g.members) == [20, 30]
                                              and abs(g.centre.x - 6.5) < 1e-9
                                              for g in m.groups))
        group = next(g for g in state.groups if g.id == made.id)
        self.assertAlmostEqual(group.centre.y, 3.5)

        said = self.call["say"](speaker_id=1, act="QUESTION:HELP", content="Can I help you")
        self.assertTrue(said.success, said.message)
        self.assertAlmostEqual(said.duration, 4 * 60.0 / 150.0)  # 4 words at 150 wpm
        state = self.state.wait(lambda m: m.ari.speech.is_speaking)
        self.assertEqual(state.ari.speech.act, "QUESTION:HELP")
        self.state.wait(lambda m: m.ari.speech.previous_act == "QUESTION:HELP")

        self.assertTrue(self.call["gaze"](id=10, targets=[1], probabilities=[1.0],
                                          mean_duration=5.0).success)
        self.state.wait(lambda m: human(m, 10).gaze.target_id == 1)

    def test_05_pause_and_step_exactly(self):
        self.assertTrue(self.call["pause"](True).success)
        time.sleep(0.3)
        before = self.clock.wait().clock.to_sec()
        time.sleep(0.3)
        self.assertEqual(self.clock.wait().clock.to_sec(), before)  # paused: time stands
        stepped = self.call["step"](steps=10)
        self.assertTrue(stepped.success, stepped.message)
        self.assertAlmostEqual(stepped.sim_time, before + 10 * STEP_S, places=6)
        self.clock.wait(lambda m: abs(m.clock.to_sec() - stepped.sim_time) < 1e-6)

    def test_06_cmd_vel_drives_ari(self):
        pub = rospy.Publisher("/mobile_base_controller/cmd_vel", Twist, queue_size=1)
        start = self.odom.wait().pose.pose.position.x
        limit = time.monotonic() + 10
        # ARI faces -x in the default scene: forward motion lowers x.
        while time.monotonic() < limit and self.odom.msg.pose.pose.position.x > start - 0.3:
            pub.publish(Twist(linear=Point(0.3, 0, 0)))
            time.sleep(0.05)
        self.assertLess(self.odom.msg.pose.pose.position.x, start - 0.3)
        self.assertEqual(self.odom.msg.header.frame_id, "odom")
        self.assertEqual(self.odom.msg.child_frame_id, "base_footprint")

    def test_07_malformed_requests_get_error_responses(self):
        overlapping = self.call["spawn"](id=0, pose=Pose2D(2.0, 3.0, 0.0))  # onto Marie
        self.assertFalse(overlapping.success)
        self.assertIn("overlap", overlapping.message)
        bad_gender = self.call["spawn"](id=0, pose=Pose2D(6.0, 2.0, 0.0), gender="robot")
        self.assertFalse(bad_gender.success)
        self.assertIn("gender", bad_gender.message)
        for response in [self.call["remove"](id=999), self.call["goal"](id=999, goal=Pose2D()),
                         self.call["members"](group_id=99, members=[10])]:
            self.assertFalse(response.success)
            self.assertIn("99", response.message)
        empty = self.call["say"](speaker_id=10, act="INFORM", content="   ")
        self.assertFalse(empty.success)
        self.assertIn("no words", empty.message)
        sums = self.call["gaze"](id=10, targets=[11, 1], probabilities=[0.5, 0.2], mean_duration=1.0)
        self.assertFalse(sums.success)
        self.assertIn("sum to 1", sums.message)
        running = self.call["step"](steps=3)
        self.assertFalse(running.success)
        self.assertIn("paused", running.message)
        # The world is intact after the refusals: still six people.
        self.assertEqual(len(self.state.wait().humans), 6)


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "world_node_contract", WorldNodeContract)
