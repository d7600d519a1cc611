#!/usr/bin/python3
"""Must-show 4 of issue 28: rogue transforms, a second world publisher, a reset late in a run."""

import math
import time
import unittest

import actionlib
import rospy
import rostest
import tf2_msgs.msg
import tf2_ros
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import Pose2D, TransformStamped, Twist
from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal
from nav_msgs.msg import OccupancyGrid
from rosgraph_msgs.msg import Clock, Log
from std_srvs.srv import Trigger
from visualization_msgs.msg import MarkerArray

from ari_social_sim.msg import IdsList, WorldState
from ari_social_sim.srv import SetPose

ARI_START = (1.5, 4.0)  # social_navigation_scene.yaml
GOAL = (3.0, 3.0)  # m, map frame: free, between ARI's start and Ana
ANA, ANA_MOVED = 20, (4.5, 3.0)  # before the reset Ana stands there, ahead of ARI at GOAL
NUDGE = (3.3, 3.4)  # a short goal from GOAL, Ana's place (moved or not) in view
GHOST_RADIUS_M = 0.7  # of a body frame; a personal-space ring's centre lies ahead of the person:
RING_GHOST_RADIUS_M = 1.0
LATE_S = 60.0  # sim time the run reaches before the reset
CMD_VEL_DROPS = "dropped /mobile_base_controller/cmd_vel linear.x"
FLOOD_MESSAGES, FLOOD_BURST = 3000, 100  # NaN commands, sent 100 at a time every 0.1 s (1 kHz)


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


def near(xy, target, radius=GHOST_RADIUS_M):
    return math.hypot(xy[0] - target[0], xy[1] - target[1]) < radius


class HostileInputs(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("hostile_inputs")
        cls.bodies = []
        cls.non_finite_markers = 0
        cls.rings = []  # centres of social_mpc's personal-space rings
        cls.errors = []  # (node, text) of ERROR and above
        cls.tf_drops = {}  # social_mpc_node's "dropped tf ..." counters
        cls.cmd_vel_drops = None  # world_node's count of NaN linear.x in cmd_vel
        rospy.Subscriber("/humans/bodies/tracked", IdsList, cls.on_bodies)
        rospy.Subscriber("/social_mpc/markers", MarkerArray, cls.on_markers)
        rospy.Subscriber("/rosout", Log, cls.on_log)
        rospy.Subscriber("/diagnostics", DiagnosticArray, cls.on_diagnostics)
        cls.tf_pub = rospy.Publisher("/tf", tf2_msgs.msg.TFMessage, queue_size=10)
        cls.move_base = actionlib.SimpleActionClient("move_base", MoveBaseAction)
        assert cls.move_base.wait_for_server(rospy.Duration(30.0))
        cls.wait_for_bodies(4, 30.0)

    @classmethod
    def wait_for_bodies(cls, count, timeout_s):
        deadline = time.time() + timeout_s
        while len(cls.bodies) < count and time.time() < deadline:
            time.sleep(0.1)

    @classmethod
    def on_bodies(cls, msg):
        cls.bodies = list(msg.ids)

    @classmethod
    def on_markers(cls, msg):
        if not finite_markers(msg):
            cls.non_finite_markers += 1
        for m in msg.markers:
            if m.ns == "personal_space" and m.action == m.ADD and m.points:
                cls.rings.append((sum(p.x for p in m.points) / len(m.points),
                                  sum(p.y for p in m.points) / len(m.points)))

    @classmethod
    def on_log(cls, msg):
        if msg.level >= Log.ERROR:
            cls.errors.append((msg.name, msg.msg))

    @classmethod
    def on_diagnostics(cls, msg):
        for status in msg.status:
            for kv in status.values:
                if status.name.startswith("social_mpc_node") and kv.key.startswith("dropped tf"):
                    cls.tf_drops[kv.key] = int(kv.value)
                if status.name.startswith("world_node") and kv.key == CMD_VEL_DROPS:
                    cls.cmd_vel_drops = int(kv.value)

    def drive_to(self, xy, timeout_s=40.0):
        """Sim seconds the goal took."""
        start = rospy.Time.now()
        self.move_base.send_goal(MoveBaseGoal(target_pose=self.goal_pose(xy)))
        self.assertTrue(self.move_base.wait_for_result(rospy.Duration(timeout_s)))
        self.assertEqual(self.move_base.get_state(), actionlib.GoalStatus.SUCCEEDED,
                         self.move_base.get_goal_status_text())
        return (rospy.Time.now() - start).to_sec()

    def rogue_for(self, seconds, make):
        deadline = time.time() + seconds
        while time.time() < deadline:
            self.tf_pub.publish(tf2_msgs.msg.TFMessage(make()))
            time.sleep(0.02)

    def set_pose(self, human_id, xy):
        set_pose = rospy.ServiceProxy("/sim/set_pose", SetPose)
        self.assertTrue(set_pose(human_id, Pose2D(x=xy[0], y=xy[1], theta=0.0)).success)

    def test_1_rogue_transforms_leave_markers_finite_and_goals_working(self):
        self.assertGreaterEqual(len(self.bodies), 1, "perception tracks nobody")
        body = "body_" + self.bodies[0]
        self.move_base.send_goal(MoveBaseGoal(target_pose=self.goal_pose((6.0, 1.5))))
        for x in (float("inf"), 1e300):
            self.rogue_for(1.0, lambda: [transform("base_footprint", body, x)])
        self.rogue_for(1.0, lambda: [transform("map", "odom", 1e300)])
        self.move_base.cancel_all_goals()
        time.sleep(2.0)  # a diagnostics period or two
        drops = sum(self.tf_drops.values())
        print("[hostile] social_mpc_node's tf drops on /diagnostics: %s" % self.tf_drops)
        self.assertGreater(drops, 0)
        took = self.drive_to(GOAL)
        print("[hostile] goal after the rogue transforms took %.1f s (sim)" % took)
        self.assertEqual(self.non_finite_markers, 0)
        self.assertFalse([e for _, e in self.errors if "e+300" in e and len(e) > 2000])

    def test_2_second_world_publisher_is_refused(self):
        states = rospy.Publisher("/sim/world_state", WorldState, queue_size=1)
        maps = rospy.Publisher("/map", OccupancyGrid, queue_size=1, latch=True)
        clock = rospy.Publisher("/clock", Clock, queue_size=1)  # registered: never publishes
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
        clock.unregister()
        print("[hostile] perception tracked at least %d bodies while a second publisher ran" %
              fewest)
        self.assertGreaterEqual(fewest, 1)
        refused = {}  # (node, topic) -> its error naming both publishers
        for node, text in self.errors:
            if (("second publisher" in text or "2 publishers" in text) and
                    "/hostile_inputs" in text and "/world_node" in text):
                refused.setdefault((node, text.split(":")[0]), text)
        for (node, _), text in sorted(refused.items()):
            print("[hostile] %s: %s" % (node, text))
        for expected in (("/hri_perception_node", "/map"),
                         ("/hri_perception_node", "/sim/world_state"),
                         ("/social_mpc_node", "/map"),
                         ("/social_mpc_node", "/clock")):
            self.assertIn(expected, refused)

    def bodies_near(self, xy):
        """The bodies perception places within GHOST_RADIUS_M of `xy`, with where it places them."""
        found = []
        self.placed = {}
        for body in self.bodies:
            try:
                t = self.tf_buffer.lookup_transform("map", "body_" + body, rospy.Time(0))
            except tf2_ros.TransformException:
                continue
            at = (t.transform.translation.x, t.transform.translation.y)
            self.placed[body] = "(%.2f, %.2f)" % at
            if near(at, xy):
                found.append((body, self.placed[body]))
        return found

    def test_3_reset_late_in_a_run_leaves_no_ghost(self):
        # A listener of its own started after test 1: tf2 would have kept its rogue map -> odom.
        self.tf_buffer = tf2_ros.Buffer()
        self.tf_listener = tf2_ros.TransformListener(self.tf_buffer)
        self.set_pose(1, ARI_START)  # ARI, by its id
        time.sleep(1.0)
        before = self.drive_to(GOAL)
        self.set_pose(ANA, ANA_MOVED)
        seen = []
        while rospy.Time.now().to_sec() < LATE_S or not seen:
            seen = self.bodies_near(ANA_MOVED)
            self.assertLess(rospy.Time.now().to_sec(), LATE_S + 30.0,
                            "perception does not see Ana moved: %s" % self.placed)
            time.sleep(0.2)
        self.rings.clear()  # the class's list, which on_markers fills
        self.drive_to(NUDGE)
        rings_before = len(self.rings)
        seen_rings = [c for c in self.rings if near(c, ANA_MOVED, RING_GHOST_RADIUS_M)]
        late_s = rospy.Time.now().to_sec()
        self.tf_listener.unregister()  # it would complain about every transform after the reset
        reset = rospy.ServiceProxy("/sim/reset", Trigger)
        self.assertTrue(reset().success)
        time.sleep(1.0)
        self.rings.clear()  # the class's list, which on_markers fills
        after = self.drive_to(GOAL)
        self.drive_to(NUDGE)
        ghosts = [c for c in self.rings if near(c, ANA_MOVED, RING_GHOST_RADIUS_M)]
        # A listener started after the reset: the test's own would keep the frames from before it.
        self.tf_buffer = tf2_ros.Buffer()
        self.tf_listener = tf2_ros.TransformListener(self.tf_buffer)
        time.sleep(1.0)
        ghost_bodies = self.bodies_near(ANA_MOVED)
        print("[hostile] reset at %.0f s of sim time; the same goal took %.1f s (sim) before it, "
              "%.1f s after (ratio %.2f)" % (late_s, before, after, after / before))
        print("[hostile] personal-space rings at Ana's moved place: %d of %d before the reset, "
              "%d of %d after; bodies there after it: %s (tracked: %s)" %
              (len(seen_rings), rings_before, len(ghosts), len(self.rings), ghost_bodies,
               self.placed))
        self.assertTrue(seen_rings, "social_mpc_node never drew Ana's personal space before the "
                        "reset: the ghost check below would prove nothing")
        self.assertFalse(ghosts, "social_mpc_node still sees Ana where she stood before the reset")
        self.assertEqual(ghost_bodies, [], "perception still places a body there")
        self.assertGreater(len(self.placed), 0, "perception places nobody after the reset")
        self.assertLess(after, 1.5 * before)

    def test_4_a_flood_of_bad_commands_is_counted_whole(self):
        """Every NaN cmd_vel of a 1 kHz flood is counted on /diagnostics, not only those that
        reached the callback once a spin (160 of 6,054 with a queue of one)."""
        deadline = time.time() + 10.0
        while self.cmd_vel_drops is None and time.time() < deadline:
            time.sleep(0.1)
        self.assertIsNotNone(self.cmd_vel_drops, "world_node publishes no cmd_vel counter")
        before = self.cmd_vel_drops
        publisher = rospy.Publisher("/mobile_base_controller/cmd_vel", Twist,
                                    queue_size=FLOOD_MESSAGES)
        deadline = time.time() + 10.0
        while publisher.get_num_connections() == 0 and time.time() < deadline:
            time.sleep(0.05)
        nan = Twist()
        nan.linear.x = float("nan")
        for _ in range(FLOOD_MESSAGES // FLOOD_BURST):
            for _ in range(FLOOD_BURST):
                publisher.publish(nan)
            time.sleep(0.1)
        deadline = time.time() + 15.0
        while self.cmd_vel_drops - before < FLOOD_MESSAGES and time.time() < deadline:
            time.sleep(0.2)
        counted = self.cmd_vel_drops - before
        print("[hostile] NaN cmd_vel sent at 1 kHz: %d, counted by world_node: %d"
              % (FLOOD_MESSAGES, counted))
        publisher.unregister()
        self.assertEqual(counted, FLOOD_MESSAGES)

    @staticmethod
    def goal_pose(xy):
        goal = MoveBaseGoal().target_pose
        goal.header.frame_id = "map"
        goal.pose.position.x, goal.pose.position.y = xy
        goal.pose.orientation.w = 1.0
        return goal


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "hostile_inputs", HostileInputs)
