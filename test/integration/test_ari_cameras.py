#!/usr/bin/python3
"""rostest: ari_physics_node publishes ARI's cameras and, in mapping mode, /map and the .bt file."""
import math
import os
import threading
import time
import unittest

import rospy
import rostest
from nav_msgs.msg import OccupancyGrid
from sensor_msgs.msg import CameraInfo, CompressedImage, Image
from std_srvs.srv import Trigger


class Stamps:
    """Every message of a topic, by arrival."""

    def __init__(self, topic, msg_type):
        self.messages = []
        self._lock = threading.Lock()
        rospy.Subscriber(topic, msg_type, self._on_msg, queue_size=50)

    def _on_msg(self, msg):
        with self._lock:
            self.messages.append(msg)

    def wait(self, count=1, timeout=60.0):
        limit = time.monotonic() + timeout
        while time.monotonic() < limit:
            with self._lock:
                if len(self.messages) >= count:
                    return self.messages[count - 1]
            time.sleep(0.01)
        raise AssertionError("timed out waiting on messages")


class AriCamerasContract(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("ari_cameras_contract")
        cls.head = Stamps("/head_front_camera/color/image_raw", Image)
        cls.head_info = Stamps("/head_front_camera/color/camera_info", CameraInfo)
        cls.head_compressed = Stamps("/head_front_camera/color/image_raw/compressed",
                                     CompressedImage)
        cls.depth = Stamps("/torso_front_camera/aligned_depth_to_color/image_raw", Image)

    def test_1_head_camera_images_and_info(self):
        image = self.head.wait(2)
        info = self.head_info.wait(2)
        self.assertEqual((image.width, image.height, image.encoding), (1280, 960, "rgb8"))
        self.assertEqual(image.header.frame_id, "head_front_camera_color_optical_frame")
        # 62.2 degrees across 1280 pixels: fx = 640 / tan(31.1 deg) = 1060.9.
        self.assertAlmostEqual(info.K[0], 640 / math.tan(math.radians(31.1)), delta=0.5)
        self.assertGreater(len(self.head_compressed.wait(1).data), 1000)
        # 10 Hz of sim time: every frame on the 0.1 s grid (a frame the publisher's queue drops
        # under load leaves a gap, never an off-grid stamp).
        self.head.wait(12)
        stamps = [m.header.stamp.to_sec() for m in self.head.messages[:12]]
        for stamp in stamps:
            self.assertAlmostEqual(stamp * 10.0, round(stamp * 10.0), delta=0.011)
        self.assertEqual(len(set(round(s * 10.0) for s in stamps)), 12)

    def test_2_torso_depth_sees_the_floor(self):
        depth = self.depth.wait(2)
        self.assertEqual((depth.width, depth.height, depth.encoding), (848, 480, "32FC1"))
        # The camera looks 42.5 degrees down from 1.105 m: the image centre meets the floor about
        # 1.105 / sin(42.5 deg) = 1.64 m away along the optical axis.
        import struct
        row, col = depth.height // 2, depth.width // 2
        offset = row * depth.step + col * 4
        centre = struct.unpack("<f", bytes(depth.data[offset:offset + 4]))[0]
        rospy.loginfo("torso depth at the image centre: %.3f m", centre)
        self.assertAlmostEqual(centre, 1.105 / math.sin(math.radians(42.5)), delta=0.05)

    def test_3_mapping_publishes_map_and_saves_octomap(self):
        grid = rospy.wait_for_message("/map", OccupancyGrid, timeout=60)
        # room_6x6's floor: 6.4 m at 0.05 m = 128 cells a side.
        self.assertEqual((grid.info.width, grid.info.height), (128, 128))
        self.assertGreater(sum(1 for c in grid.data if c >= 0), 100)  # observed cells
        rospy.wait_for_service("/ari_physics_node/save_map", timeout=30)
        reply = rospy.ServiceProxy("/ari_physics_node/save_map", Trigger)()
        self.assertTrue(reply.success, reply.message)
        self.assertGreater(os.path.getsize("/tmp/ari_cameras_test.bt"), 100)


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "ari_cameras_contract", AriCamerasContract)
