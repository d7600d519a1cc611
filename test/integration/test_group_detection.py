#!/usr/bin/python3
"""rostest: group_detection_node's contract.

On hri_perception_node's stream (group_detection.test, error models off) while world_node plays
test/integration/social_navigation_scene.yaml: the ground truth's group of three, all of whose
bodies perception tracks, is reported on /humans/interactions/groups with exactly those persons
within 15 s, in the map frame, under one id, its stamps advancing at the node's 20 Hz of sim time
(within 10 %); Ana, alone, is in no group; ~markers draws it at its o-space centre.

With the argument `alone` (group_detection_alone.test), nothing else runs: the node stays up and
publishes nothing.

With the argument `synthetic` (group_detection_synthetic.test, ~rate 10, wall time), the test
itself is the perception: tracked lists stamped every 0.05 s, latched body ids and static body
frames. Two people face to face form a group (a person without a body, or whose body frame tf
lacks, does not get in the way), reported 10 times a second; the body_id subscriptions of persons
gone for over 5 s of the lists' time are dropped; stamps going back start the group history
afresh (a fresh id at once).
"""
import math
import sys
import time
import unittest

import rosgraph
import rosnode
import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import TransformStamped
from std_msgs.msg import String
from visualization_msgs.msg import MarkerArray

from ari_social_sim.msg import Group, IdsList, WorldState
from topic_collector import Collector

NODE = "/group_detection"
GROUPS = "/humans/interactions/groups"
MARKERS = NODE + "/markers"
ALONE = 20  # Ana, standing apart


def person(human_id):
    return "human%d" % human_id


class GroupDetectionOnPerception(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("group_detection_test")
        cls.groups = Collector(GROUPS, Group, 1000)
        cls.tracked = Collector("/humans/persons/tracked", IdsList, 1000)
        cls.markers = Collector(MARKERS, MarkerArray, 100)
        cls.state = Collector("/sim/world_state", WorldState, 5)
        cls.started = time.monotonic()

    def truth_group(self):
        """The ground truth's one group: its members' person ids and its o-space centre."""
        state = self.state.wait(lambda m: len(m.groups) == 1, what="the world's group")
        group = state.groups[0]
        return {person(h) for h in group.members}, (group.centre.x, group.centre.y)

    def test_the_group_is_reported_with_its_members_at_the_perception_rate(self):
        members, centre = self.truth_group()
        # Every member's body is tracked (errors off, all in ARI's fisheye), so all are expected.
        for member in members:
            body = rospy.wait_for_message("/humans/persons/%s/body_id" % member, String, 15)
            self.assertRegex(body.data, r"^[a-z]{5}$")
        first = self.groups.wait(lambda m: set(m.members) == members, 15.0,
                                 "a group of exactly %s" % sorted(members))
        rospy.loginfo("group %s %s after %.1f s of wall time", first.group_id, first.members,
                      time.monotonic() - self.started)
        self.assertEqual(first.header.frame_id, "map")

        # Three seconds of wall time (3 s of sim time at real_time_factor 1) of steady reports.
        time.sleep(3.0)
        reports = [m for m in self.groups.all() if m.header.stamp >= first.header.stamp]
        self.assertGreaterEqual(len(reports), 40)  # 20 Hz for ~3 s
        for m in reports:
            self.assertEqual(m.group_id, first.group_id)
            self.assertEqual(set(m.members), members)
            self.assertNotIn(person(ALONE), m.members)
            self.assertEqual(m.header.frame_id, "map")
        stamps = [m.header.stamp.to_sec() for m in reports]
        self.assertTrue(all(b > a for a, b in zip(stamps, stamps[1:])),
                        "stamps do not advance: %s" % stamps)
        span_s = stamps[-1] - stamps[0]
        groups_hz = (len(stamps) - 1) / span_s
        rospy.loginfo("groups %.2f Hz over %.2f s of sim time", groups_hz, span_s)
        self.assertGreater(groups_hz, 0.9 * 20.0)
        self.assertLess(groups_hz, 1.1 * 20.0)

        # ~markers: the o-space circle and the group's id near the truth's centre.
        array = self.markers.wait(
            lambda a: any(m.ns == "perception/groups/label" for m in a.markers), 10.0,
            "group markers")
        label = next(m for m in array.markers if m.ns == "perception/groups/label")
        self.assertEqual(label.text, "group " + first.group_id)
        self.assertEqual(label.header.frame_id, "map")
        offset = math.hypot(label.pose.position.x - centre[0], label.pose.position.y - centre[1])
        rospy.loginfo("perceived o-space centre %.2f m from the truth's", offset)
        self.assertLess(offset, 0.3)


class GroupDetectionAlone(unittest.TestCase):
    def test_stays_up_and_publishes_nothing(self):
        rospy.init_node("group_detection_alone_test")
        groups = Collector(GROUPS, Group)
        markers = Collector(MARKERS, MarkerArray)
        master = rosgraph.Master("/group_detection_alone_test")
        limit = time.monotonic() + 20.0
        while NODE not in rosnode.get_node_names() and time.monotonic() < limit:
            time.sleep(0.1)
        self.assertIn(NODE, rosnode.get_node_names())
        time.sleep(5.0)
        self.assertTrue(rosnode.rosnode_ping(NODE, max_count=1))
        published = {topic for topic, _ in master.getPublishedTopics("")}
        self.assertIn(GROUPS, published)
        self.assertIn(MARKERS, published)
        self.assertEqual(groups.all(), [])
        self.assertEqual(markers.all(), [])


def body_frame(body_id, x, y, yaw):
    t = TransformStamped()
    t.header.frame_id = "map"
    t.child_frame_id = "body_" + body_id
    t.transform.translation.x, t.transform.translation.y = x, y
    t.transform.rotation.z, t.transform.rotation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return t


class GroupDetectionOnSyntheticInput(unittest.TestCase):
    # person -> body id; hanna has no body frame in tf, ida no body at all (a face or a voice).
    BODIES = {"anna": "aaaaa", "bert": "bbbbb", "carl": "ccccc", "hanna": "hhhhh", "ida": ""}

    def setUp(self):
        rospy.init_node("group_detection_synthetic_test")
        self.groups = Collector(GROUPS, Group, 1000)
        self.master = rosgraph.Master("/group_detection_synthetic_test")
        # Anna at (0, 0) facing +x and Bert at (1.2, 0) facing -x share the candidate centre
        # (0.6, 0) at the 0.6 m stride; Carl stands 7 m away facing away.
        self.static_tf = tf2_ros.StaticTransformBroadcaster()
        self.static_tf.sendTransform([body_frame("aaaaa", 0.0, 0.0, 0.0),
                                      body_frame("bbbbb", 1.2, 0.0, math.pi),
                                      body_frame("ccccc", 5.0, 5.0, 0.0)])
        self.body_ids = {}
        for person_id, body_id in self.BODIES.items():
            pub = rospy.Publisher("/humans/persons/%s/body_id" % person_id, String, latch=True,
                                  queue_size=1)
            pub.publish(String(body_id))
            self.body_ids[person_id] = pub
        self.tracked = rospy.Publisher("/humans/persons/tracked", IdsList, queue_size=10)
        limit = time.monotonic() + 20.0
        while self.tracked.get_num_connections() == 0 and time.monotonic() < limit:
            time.sleep(0.05)

    def send(self, ids, first_stamp_s, count):
        """`count` tracked lists stamped first_stamp_s, + 0.05 s, ..., at 20 Hz of wall time."""
        for i in range(count):
            msg = IdsList(ids=ids)
            msg.header.stamp = rospy.Time(first_stamp_s) + rospy.Duration(0.05 * i)
            msg.header.frame_id = "map"
            self.tracked.publish(msg)
            time.sleep(0.05)
        time.sleep(0.3)  # the last group in flight

    def body_id_listeners(self):
        _, subscribers, _ = self.master.getSystemState()
        return {topic.split("/")[3] for topic, nodes in subscribers
                if topic.endswith("/body_id") and NODE in nodes}

    def test_groups_rate_persons_left_out_and_time_going_back(self):
        everyone = list(self.BODIES)
        self.send(everyone, 100.0, 40)  # stamps 100.00 .. 101.95
        first = [m for m in self.groups.all()]
        self.assertGreaterEqual(len(first), 15)  # 20 accepted lists less the first few before
        for m in first:                            # the latched body ids arrived
            self.assertEqual(m.group_id, "g1")
            self.assertEqual(sorted(m.members), ["anna", "bert"])
            self.assertEqual(m.header.frame_id, "map")
        stamps = [m.header.stamp.to_sec() for m in first]
        gaps = [b - a for a, b in zip(stamps, stamps[1:])]
        rospy.loginfo("%d groups in 2.3 s, gaps %.3f-%.3f s", len(first), min(gaps), max(gaps))
        self.assertAlmostEqual(sum(gaps) / len(gaps), 0.1, delta=0.01)  # ~rate 10
        self.assertEqual(self.body_id_listeners(), set(everyone))

        # Only Anna and Bert for 6 s more of the lists' time: the others' subscriptions go.
        self.send(["anna", "bert"], 108.0, 2)
        self.assertEqual(self.body_id_listeners(), {"anna", "bert"})
        self.assertEqual(self.groups.last().group_id, "g1")

        # Stamps going back: the pair is a group again at the next detection (a fresh membership
        # history decides on its first frame), under a fresh id, and g1 is never seen again.
        sent = len(self.groups.all())
        self.send(["anna", "bert"], 50.0, 20)  # stamps 50.00 .. 50.95, over 1.3 s
        after = [m.group_id for m in self.groups.all()[sent:]]
        self.assertGreaterEqual(after.count("g2"), 10)
        self.assertEqual(after[-1], "g2")
        self.assertNotIn("g1", after[after.index("g2"):])


if __name__ == "__main__":
    if "alone" in rospy.myargv(sys.argv):
        rostest.rosrun("ari_social_sim", "group_detection_alone", GroupDetectionAlone)
    elif "synthetic" in rospy.myargv(sys.argv):
        rostest.rosrun("ari_social_sim", "group_detection_synthetic",
                       GroupDetectionOnSyntheticInput)
    else:
        rostest.rosrun("ari_social_sim", "group_detection_on_perception",
                       GroupDetectionOnPerception)
