#!/usr/bin/python3
"""rostest: world_node's topics and services behave as documented (README, world_node)."""
import math
import threading
import time
import unittest

import genpy.dynamic
import rospy
import rostest
from geometry_msgs.msg import Point, Pose2D, Twist
from nav_msgs.msg import OccupancyGrid, Odometry
from rosgraph_msgs.msg import Clock
from std_srvs.srv import SetBool, Trigger
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

from ari_social_sim.msg import HumanState, WorldState
from ari_social_sim.srv import (AddGroupMembers, CreateGroup, CreateWalkingGroup, JoinGroup,
                                LeaveGroup, RemoveHuman, Say, SetGazeTargets, SetGoal,
                                SetGroupArrangement, SetGroupCentre, SetPose, SetPosture,
                                SetReaction, SetVelocity,
                                SpawnHuman, StepSimulation)

STEP_S = 0.05  # world_node's default step
NAN = float("nan")
INF = float("inf")
MAX_STEPS = 100000  # world_node's most steps per /sim/step request (README)


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


class LatestDiagnostics(Latest):
    """The last /diagnostics message as a dict of its values, decoded without diagnostic_msgs'
    Python package (Debian's python3-diagnostic-msgs is not installed here): the class is built
    from the message definition the publisher sends in its connection header."""

    def __init__(self):
        self._classes = {}
        super().__init__("/diagnostics", rospy.AnyMsg)

    def _on_msg(self, raw):
        header = raw._connection_header
        msg_type = header["type"]
        if msg_type not in self._classes:
            self._classes.update(genpy.dynamic.generate_dynamic(msg_type,
                                                               header["message_definition"]))
        array = self._classes[msg_type]().deserialize(raw._buff)
        values = {}
        for status in array.status:
            if status.name == "world_node: inputs":
                values.update({kv.key: int(kv.value) for kv in status.values})
        super()._on_msg(values)


def finite_world(state):
    """True when every number of ARI, the humans and the groups in a world state is finite."""
    numbers = [state.ari.pose.x, state.ari.pose.y, state.ari.pose.theta, state.ari.head_pan,
               state.ari.linear_velocity, state.ari.angular_velocity]
    for h in state.humans:
        numbers += [h.pose.x, h.pose.y, h.pose.theta, h.velocity.linear.x, h.velocity.linear.y,
                    h.velocity.angular.z, h.gaze.direction]
    for g in state.groups:
        numbers += [g.centre.x, g.centre.y, g.ospace_radius]
    return all(math.isfinite(x) for x in numbers)


class WorldNodeContract(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("world_node_contract")
        cls.clock = Latest("/clock", Clock)
        cls.state = Latest("/sim/world_state", WorldState)
        cls.odom = Latest("/mobile_base_controller/odom", Odometry)
        cls.diagnostics = LatestDiagnostics()
        for name in ["spawn_human", "remove_human", "set_goal", "set_velocity", "set_pose",
                     "create_group", "add_group_members", "set_group_centre", "say",
                     "set_gaze_targets", "set_reaction", "reset", "pause", "step",
                     "create_walking_group", "set_group_arrangement", "join_group",
                     "leave_group", "set_posture"]:
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
            "reaction": rospy.ServiceProxy("/sim/set_reaction", SetReaction),
            "reset": rospy.ServiceProxy("/sim/reset", Trigger),
            "pause": rospy.ServiceProxy("/sim/pause", SetBool),
            "step": rospy.ServiceProxy("/sim/step", StepSimulation),
            "walk": rospy.ServiceProxy("/sim/create_walking_group", CreateWalkingGroup),
            "arrange": rospy.ServiceProxy("/sim/set_group_arrangement", SetGroupArrangement),
            "join": rospy.ServiceProxy("/sim/join_group", JoinGroup),
            "leave": rospy.ServiceProxy("/sim/leave_group", LeaveGroup),
            "posture": rospy.ServiceProxy("/sim/set_posture", SetPosture),
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
        # A node that comes up while the world is paused gets the last state (latched): a dialogue
        # node started late in CI once waited for a state that a paused world never sent. rospy
        # shares one connection among a process's subscribers of a topic and hands a new one the
        # last latched message this connection has read: wait until it has read the last state.
        self.state.wait(lambda m: abs(m.header.stamp.to_sec() - stepped.sim_time) < 1e-6)
        late = rospy.wait_for_message("/sim/world_state", WorldState, timeout=10)
        self.assertAlmostEqual(late.header.stamp.to_sec(), stepped.sim_time, places=6)

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

    def step_paused(self, steps):
        """Pauses, steps, and returns the world state of the last step."""
        self.assertTrue(self.call["pause"](True).success)
        stepped = self.call["step"](steps=steps)
        self.assertTrue(stepped.success, stepped.message)
        return self.state.wait(lambda m: abs(m.header.stamp.to_sec() - stepped.sim_time) < 1e-6)

    def test_08_non_finite_service_fields_are_refused_and_named(self):
        # The default scene: Marie (10) and her companion (11) are group 1; 20-22 are group 2.
        calls = [
            ("spawn_human: pose.x", lambda v: self.call["spawn"](id=0, pose=Pose2D(v, 2.0, 0.0))),
            ("spawn_human: pose.y", lambda v: self.call["spawn"](id=0, pose=Pose2D(6.0, v, 0.0))),
            ("spawn_human: pose.theta",
             lambda v: self.call["spawn"](id=0, pose=Pose2D(6.0, 2.0, v))),
            ("spawn_human: age",
             lambda v: self.call["spawn"](id=0, pose=Pose2D(6.0, 2.0, 0.0), age=v)),
            ("set_goal: goal.x", lambda v: self.call["goal"](id=10, goal=Pose2D(v, 3.0, 0.0))),
            ("set_goal: goal.y", lambda v: self.call["goal"](id=10, goal=Pose2D(3.0, v, 0.0))),
            ("set_goal: goal.theta",
             lambda v: self.call["goal"](id=10, goal=Pose2D(3.0, 3.0, v))),
            ("set_velocity: vx", lambda v: self.call["velocity"](id=10, vx=v, vy=0.0, omega=0.0)),
            ("set_velocity: vy", lambda v: self.call["velocity"](id=10, vx=0.0, vy=v, omega=0.0)),
            ("set_velocity: omega",
             lambda v: self.call["velocity"](id=10, vx=0.0, vy=0.0, omega=v)),
            ("set_pose: pose.x", lambda v: self.call["pose"](id=10, pose=Pose2D(v, 3.0, 0.0))),
            ("set_pose: pose.y", lambda v: self.call["pose"](id=1, pose=Pose2D(8.6, v, 0.0))),
            ("set_pose: pose.theta",
             lambda v: self.call["pose"](id=10, pose=Pose2D(2.0, 3.0, v))),
            ("create_group: centre.x", lambda v: self.call["group"](
                id=0, members=[30], centre=Point(v, 3.0, 0.0), ospace_radius=0.0)),
            ("create_group: centre.y", lambda v: self.call["group"](
                id=0, members=[30], centre=Point(6.0, v, 0.0), ospace_radius=0.0)),
            ("create_group: ospace_radius", lambda v: self.call["group"](
                id=0, members=[30], centre=Point(6.0, 3.0, 0.0), ospace_radius=v)),
            ("set_group_centre: centre.x",
             lambda v: self.call["centre"](group_id=1, centre=Point(v, 3.0, 0.0))),
            ("set_group_centre: centre.y",
             lambda v: self.call["centre"](group_id=1, centre=Point(3.0, v, 0.0))),
            ("set_gaze_targets: targets[0].probability", lambda v: self.call["gaze"](
                id=10, targets=[1], probabilities=[v], mean_duration=1.0)),
            ("set_gaze_targets: mean_duration", lambda v: self.call["gaze"](
                id=10, targets=[1], probabilities=[1.0], mean_duration=v)),
        ]
        refusals = 0
        for field, call in calls:
            for value in (NAN, INF, -INF):
                response = call(value)
                self.assertFalse(response.success, "%s = %s accepted" % (field, value))
                self.assertIn(field + ": expected", response.message)
                refusals += 1
        # Finite but far beyond a human's 1.3 m/s, and a goal off the 12.4 m floor.
        fast = self.call["velocity"](id=10, vx=1e300, vy=0.0, omega=0.0)
        self.assertFalse(fast.success)
        self.assertIn("at most 1.3 m/s", fast.message)
        far = self.call["goal"](id=10, goal=Pose2D(50.0, 3.0, 0.0))
        self.assertFalse(far.success)
        self.assertIn("set_goal: goal.x: expected a finite number inside the world [-0.2, 12.2], "
                      "got 50", far.message)
        rospy.loginfo("%d non-finite service fields refused", refusals)
        # 40 steps later every pose, velocity, gaze and centre is finite; both groups are intact.
        state = self.step_paused(40)
        self.assertTrue(finite_world(state))
        self.assertEqual(len(state.humans), 6)
        self.assertEqual(sorted(g.id for g in state.groups), [1, 2])
        self.assertEqual(human(state, 10).group_id, 1)

    def test_09_non_finite_topic_messages_are_dropped_and_counted(self):
        cmd_vel = rospy.Publisher("/mobile_base_controller/cmd_vel", Twist, queue_size=10)
        head = rospy.Publisher("/head_controller/command", JointTrajectory, queue_size=10)
        limit = time.monotonic() + 10
        while time.monotonic() < limit and (cmd_vel.get_num_connections() == 0 or
                                            head.get_num_connections() == 0):
            time.sleep(0.05)
        before = self.diagnostics.wait()
        # 50 ms apart: world_node keeps one message per topic between two looks at its callbacks
        # (every 12.5 ms at this real-time factor), so none is superseded unseen.
        for _ in range(5):
            cmd_vel.publish(Twist(linear=Point(NAN, 0, 0)))
            time.sleep(0.05)
            cmd_vel.publish(Twist(angular=Point(0, 0, INF)))
            head.publish(JointTrajectory(joint_names=["head_1_joint"], points=[
                JointTrajectoryPoint(positions=[NAN], time_from_start=rospy.Duration(0.5))]))
            time.sleep(0.05)
        state = self.state.wait(lambda m: m.header.stamp.to_sec() > 0.5)
        self.assertTrue(finite_world(state))
        # The next valid commands still drive ARI (forward is -x in this scene) and pan its head.
        start = self.odom.wait().pose.pose.position.x
        limit = time.monotonic() + 10
        while time.monotonic() < limit and self.odom.msg.pose.pose.position.x > start - 0.3:
            cmd_vel.publish(Twist(linear=Point(0.3, 0, 0)))
            head.publish(JointTrajectory(joint_names=["head_1_joint"], points=[
                JointTrajectoryPoint(positions=[0.5], time_from_start=rospy.Duration(0.5))]))
            time.sleep(0.05)
        self.assertLess(self.odom.msg.pose.pose.position.x, start - 0.3)
        state = self.state.wait(lambda m: abs(m.ari.head_pan - 0.5) < 1e-6)
        self.assertTrue(finite_world(state))
        # A finite command beyond ARI's 1 m/s is clamped, and counted as such.
        cmd_vel.publish(Twist(linear=Point(3.0, 0, 0)))
        # Every NaN and infinity is counted under its topic and field (1 Hz diagnostics).
        cmd_x = "dropped /mobile_base_controller/cmd_vel linear.x"
        cmd_z = "dropped /mobile_base_controller/cmd_vel angular.z"
        pan = "dropped /head_controller/command points[last].positions[head_1_joint]"
        after = self.diagnostics.wait(lambda d: d.get(pan, 0) >= before[pan] + 5 and
                                      d.get(cmd_z, 0) >= before[cmd_z] + 5)
        self.assertEqual(after[cmd_x] - before[cmd_x], 5)
        self.assertEqual(after[cmd_z] - before[cmd_z], 5)
        self.assertEqual(after[pan] - before[pan], 5)
        after = self.diagnostics.wait(
            lambda d: d["clamped /mobile_base_controller/cmd_vel"] > before[
                "clamped /mobile_base_controller/cmd_vel"])
        self.assertEqual(after["clamped /mobile_base_controller/cmd_vel"] -
                         before["clamped /mobile_base_controller/cmd_vel"], 1)
        rospy.loginfo("/diagnostics: %s", after)

    def test_10_step_requests_have_a_maximum(self):
        self.assertTrue(self.call["pause"](True).success)
        for steps in (MAX_STEPS + 1, 4294967295, 0):
            refused = self.call["step"](steps=steps)
            self.assertFalse(refused.success)
            self.assertIn("step: steps: expected an integer in [1, 100000] per request",
                          refused.message)
            self.assertIn("got %d" % steps, refused.message)
        # The node still serves requests at once.
        stepped = self.call["step"](steps=2)
        self.assertTrue(stepped.success, stepped.message)

    def test_11_reset_restarts_the_pacing(self):
        # At a real-time factor of 4, sim time runs 4 s per wall second from the reset on. Before
        # the fix a reset ran the world as fast as possible until it was back at its old time.
        self.clock.wait(lambda m: m.clock.to_sec() > 8.0)
        self.assertTrue(self.call["reset"]().success)
        reset_wall = time.monotonic()
        time.sleep(1.0)
        latest = self.clock.wait().clock.to_sec()
        elapsed = time.monotonic() - reset_wall
        rospy.loginfo("%.2f s of sim time in %.2f s of wall time after a reset", latest, elapsed)
        self.assertLess(latest, 4.0 * elapsed + 0.5)
        self.assertGreater(latest, 4.0 * 1.0 - 1.0)

    def test_12_set_reaction_shows_in_the_world_state(self):
        self.state.wait(lambda m: human(m, 10).reaction == "ignore")  # the scene's default
        made = self.call["reaction"](id=10, profile="curious")
        self.assertTrue(made.success, made.message)
        self.state.wait(lambda m: human(m, 10).reaction == "curious")
        unknown = self.call["reaction"](id=10, profile="shy")
        self.assertFalse(unknown.success)
        self.assertIn("set_reaction: profile: expected ignore, yield, curious, avoid or block, "
                      "got 'shy'", unknown.message)
        nobody = self.call["reaction"](id=999, profile="yield")
        self.assertFalse(nobody.success)
        self.assertIn("set_reaction: id: no human with id 999", nobody.message)
        # The refusals changed nothing.
        self.assertEqual(human(self.state.wait(), 10).reaction, "curious")

    def test_13_walking_groups(self):
        # Paul and Irene leave the visitors' group 2 and walk abreast to the middle of the room.
        bad = self.call["walk"](id=0, members=[20, 21], formation="abreast",
                                goal=Pose2D(6.0, 3.0, 0.0))
        self.assertFalse(bad.success)
        self.assertEqual(bad.message, "create_walking_group: formation: expected side-by-side or "
                                      "line, got 'abreast'")
        bad = self.call["walk"](id=0, members=[20, 21], goal=Pose2D(NAN, 3.0, 0.0))
        self.assertFalse(bad.success)
        self.assertIn("create_walking_group: goal.x: expected", bad.message)
        made = self.call["walk"](id=0, members=[20, 21], goal=Pose2D(6.0, 3.0, 0.0))
        self.assertTrue(made.success, made.message)
        self.assertEqual(made.id, 3)  # one past the scene's groups 1 and 2
        state = self.state.wait(lambda m: any(w.id == made.id for w in m.walking_groups))
        walking = next(w for w in state.walking_groups if w.id == made.id)
        self.assertEqual(list(walking.members), [20, 21])
        self.assertEqual(walking.formation, "side-by-side")
        self.assertEqual(walking.on_arrival, "stop")
        self.assertEqual(human(state, 20).group_id, made.id)
        self.assertEqual(list(next(g for g in state.groups if g.id == 2).members), [22])
        # 4.3 m at 1.05 m/s: arrived within 10 s of sim time.
        self.state.wait(lambda m: any(w.id == made.id and w.arrived for w in m.walking_groups))

    def test_14_arrangements_joining_and_leaving(self):
        # Group 1 (humans 10 and 11) stands side by side; ARI joining turns it into a circle of
        # three, and leaving gives the row back.
        made = self.call["arrange"](group_id=1, arrangement="side-by-side", has_heading=True,
                                    heading=0.5)
        self.assertTrue(made.success, made.message)
        state = self.state.wait(lambda m: any(g.id == 1 and g.arrangement == "side-by-side"
                                              for g in m.groups))
        self.assertAlmostEqual(next(g for g in state.groups if g.id == 1).heading, 0.5)
        joined = self.call["join"](group_id=1, agent_id=1)
        self.assertTrue(joined.success, joined.message)
        self.state.wait(lambda m: any(g.id == 1 and g.robot_joining == 1
                                      and g.arrangement == "circle" for g in m.groups))
        left = self.call["leave"](agent_id=1)
        self.assertTrue(left.success, left.message)
        self.state.wait(lambda m: any(g.id == 1 and g.robot_joining == 0
                                      and g.arrangement == "side-by-side" for g in m.groups))
        bad = self.call["arrange"](group_id=1, arrangement="triangle", has_heading=False,
                                   heading=0.0)
        self.assertFalse(bad.success)
        self.assertEqual(bad.message, "set_group_arrangement: arrangement: expected circle, "
                                      "vis-a-vis, l-shape or side-by-side, got 'triangle'")
        bad = self.call["leave"](agent_id=999)
        self.assertFalse(bad.success)
        self.assertEqual(bad.message, "leave_group: agent_id: no human or ARI with id 999")
        bad = self.call["group"](id=0, members=[10], centre=Point(2.0, 2.0, 0.0),
                                 ospace_radius=0.0, arrangement="line")
        self.assertFalse(bad.success)
        self.assertIn("create_group: arrangement: expected circle", bad.message)

    def test_15_set_posture_sits_a_human_down_and_up_in_place(self):
        # Paused and stepped: the group's members still walk to their places after the reset.
        self.assertTrue(self.call["pause"](True).success)
        stepped = self.call["step"](steps=1)
        before = human(self.state.wait(
            lambda m: abs(m.header.stamp.to_sec() - stepped.sim_time) < 1e-6), 10)
        self.assertEqual(before.posture, HumanState.POSTURE_STANDING)
        made = self.call["posture"](id=10, posture="sitting")
        self.assertTrue(made.success, made.message)
        stepped = self.call["step"](steps=int(math.ceil(1.8 / STEP_S)))  # 1.7 s to sit down
        seated = human(self.state.wait(
            lambda m: abs(m.header.stamp.to_sec() - stepped.sim_time) < 1e-6), 10)
        self.assertEqual(seated.posture, HumanState.POSTURE_SITTING)
        self.assertEqual(seated.posture_progress, 1.0)
        # Sitting down carries the position 0.45 m back, onto the seat behind.
        moved = math.hypot(seated.pose.x - before.pose.x, seated.pose.y - before.pose.y)
        self.assertAlmostEqual(moved, 0.45, delta=0.01)
        made = self.call["posture"](id=10, posture="standing")
        self.assertTrue(made.success, made.message)
        stepped = self.call["step"](steps=int(math.ceil(1.8 / STEP_S)))
        up = human(self.state.wait(
            lambda m: abs(m.header.stamp.to_sec() - stepped.sim_time) < 1e-6), 10)
        self.assertEqual(up.posture, HumanState.POSTURE_STANDING)
        self.assertEqual(up.posture_progress, 1.0)
        bad = self.call["posture"](id=10, posture="lying")
        self.assertFalse(bad.success)
        self.assertEqual(bad.message, "set_posture: posture: expected standing or sitting, "
                                      "got 'lying'")
        bad = self.call["posture"](id=999, posture="sitting")
        self.assertFalse(bad.success)
        self.assertEqual(bad.message, "set_posture: id: no human with id 999")


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "world_node_contract", WorldNodeContract)
