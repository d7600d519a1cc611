#!/usr/bin/python3
"""rostest, must-show 1 of issue 3: a subscriber that knows nothing of ari_social_sim, declaring
the upstream type hri_msgs/IdsList with its upstream MD5 (hri_msgs 0.9.0), receives
/humans/bodies/tracked from hri_perception_node. Run with the argument `wrong-md5`, the same
subscriber declaring another MD5 must receive nothing (the negative control; in its own process,
since rospy shares one connection among a node's subscribers to a topic)."""
import struct
import sys
import time
import unittest

import genpy
import rospy
import rostest
from std_msgs.msg import Header

from topic_collector import Collector

UPSTREAM_IDS_LIST_MD5 = "84a63f55b5676f78b625e8a8bb809fe5"
UPSTREAM_IDS_LIST_TEXT = """std_msgs/Header header
string[] ids

================================================================================
MSG: std_msgs/Header
uint32 seq
time stamp
string frame_id
"""


def read_string(buffer, offset):
    (length,) = struct.unpack_from("<I", buffer, offset)
    offset += 4
    return buffer[offset:offset + length].decode("utf-8"), offset + length


class UpstreamIdsList(genpy.Message):
    """hri_msgs/IdsList as an hri_msgs user would have it, written by hand from the 0.9.0 layout:
    Header (seq, stamp, frame_id) then a length-prefixed list of length-prefixed strings."""

    _md5sum = UPSTREAM_IDS_LIST_MD5
    _type = "hri_msgs/IdsList"
    _has_header = True
    _full_text = UPSTREAM_IDS_LIST_TEXT
    __slots__ = ["header", "ids"]
    _slot_types = ["std_msgs/Header", "string[]"]

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.header = Header()
        self.ids = []

    def serialize(self, buff):
        raise NotImplementedError("this test only subscribes")

    def deserialize(self, data):
        seq, secs, nsecs = struct.unpack_from("<3I", data, 0)
        self.header.seq = seq
        self.header.stamp = genpy.Time(secs, nsecs)
        self.header.frame_id, offset = read_string(data, 12)
        (count,) = struct.unpack_from("<I", data, offset)
        offset += 4
        self.ids = []
        for _ in range(count):
            text, offset = read_string(data, offset)
            self.ids.append(text)
        return self


class WrongMd5IdsList(UpstreamIdsList):
    _md5sum = "0123456789abcdef0123456789abcdef"


class UpstreamSubscriber(unittest.TestCase):
    def test_upstream_md5_subscriber_receives_tracked_bodies(self):
        rospy.init_node("hri_wire_test")
        upstream = Collector("/humans/bodies/tracked", UpstreamIdsList)
        deadline = time.monotonic() + 60.0
        while time.monotonic() < deadline:
            messages = upstream.all()
            if len(messages) >= 20 and any(m.ids for m in messages):
                break
            time.sleep(0.1)
        messages = upstream.all()
        self.assertGreaterEqual(len(messages), 20, "too few /humans/bodies/tracked messages")
        with_ids = [m for m in messages if m.ids]
        self.assertTrue(with_ids, "no body ever tracked in the default scene")
        for m in with_ids:
            for body_id in m.ids:
                self.assertRegex(body_id, r"^[a-z]{5}$")
        # Stamps are sim time and increase.
        stamps = [m.header.stamp.to_sec() for m in messages]
        self.assertEqual(stamps, sorted(stamps))
        self.assertGreater(stamps[-1], 0.0)
        self.assertEqual(messages[-1].header.frame_id, "base_footprint")
        print("[ measured ] upstream-MD5 subscriber: %d messages, %d with ids, e.g. %s"
              % (len(messages), len(with_ids), with_ids[-1].ids))


class WrongMd5Subscriber(unittest.TestCase):
    def test_wrong_md5_subscriber_is_refused(self):
        rospy.init_node("hri_wire_wrong_md5_test")
        wrong = Collector("/humans/bodies/tracked", WrongMd5IdsList)
        deadline = time.monotonic() + 30.0
        while time.monotonic() < deadline:
            if "/humans/bodies/tracked" in dict(rospy.get_published_topics()):
                break
            time.sleep(0.1)
        self.assertIn("/humans/bodies/tracked", dict(rospy.get_published_topics()))
        time.sleep(10.0)  # hri_perception_node publishes 20 lists a second meanwhile
        self.assertEqual(wrong.all(), [])


if __name__ == "__main__":
    if "wrong-md5" in rospy.myargv(sys.argv):
        rostest.rosrun("ari_social_sim", "hri_wire_wrong_md5", WrongMd5Subscriber)
    else:
        rostest.rosrun("ari_social_sim", "hri_wire", UpstreamSubscriber)
