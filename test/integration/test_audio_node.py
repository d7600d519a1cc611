#!/usr/bin/python3
"""audio_node on a live world (audio_node.test): what ARI's audio driver would publish. Chunks of
1024 16-bit samples, 16,000 samples per second of sim time on every channel; silence (the room's
noise) until Clara speaks; while she asks her question the array detects a voice and points at
her, 42.8 degrees to its left; ARI itself is silent on the playback channel."""
import math
import statistics
import struct
import threading
import unittest

import rospy
import rostest
from std_msgs.msg import Bool, Int32

from ari_social_sim.msg import AudioData
from ari_social_sim.srv import Say

CLARA_BEARING_DEG = math.degrees(math.atan2(5.5 - 4.0, 3.5 - (2.0 - 0.122)))


def rms_dbfs(msg):
    samples = struct.unpack("<%dh" % (len(msg.data) // 2), bytes(msg.data))
    mean_square = sum(s * s for s in samples) / max(len(samples), 1)
    return 10.0 * math.log10(mean_square / 32768.0 ** 2 + 1e-20)


class AudioNodeTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_audio_node")
        cls.lock = threading.Lock()
        cls.chunks = {c: [] for c in range(6)}  # (sim time received, msg)
        cls.voice = []
        cls.directions = []
        for channel in range(6):
            rospy.Subscriber("/audio/channel%d" % channel, AudioData, cls.on_chunk, channel,
                             queue_size=1000)
        rospy.Subscriber("/audio/voice_detected", Bool,
                         lambda m: cls.record(cls.voice, (rospy.get_time(), m.data)))
        rospy.Subscriber("/audio/sound_direction", Int32,
                         lambda m: cls.record(cls.directions, (rospy.get_time(), m.data)))

    @classmethod
    def on_chunk(cls, msg, channel):
        cls.record(cls.chunks[channel], (rospy.get_time(), msg))

    @classmethod
    def record(cls, into, item):
        with cls.lock:
            into.append(item)

    def wait_sim(self, seconds):
        end = rospy.get_time() + seconds
        while rospy.get_time() < end and not rospy.is_shutdown():
            rospy.sleep(0.05)

    def test_audio(self):
        while rospy.get_time() < 1.0 and not rospy.is_shutdown():
            rospy.sleep(0.05)
        self.wait_sim(3.0)
        with self.lock:
            quiet = [m for _, m in self.chunks[0]]
            first_time, last_time = self.chunks[1][0][0], self.chunks[1][-1][0]
            count = len(self.chunks[1])
        self.assertTrue(all(len(m.data) == 2048 for m in quiet), "chunks of 1024 16-bit samples")
        rate = (count - 1) * 1024 / (last_time - first_time)
        print("%d chunks in %.2f s of sim time: %.0f samples/s" % (count, last_time - first_time,
                                                                   rate))
        self.assertAlmostEqual(rate, 16000, delta=16000 * 0.1)
        self.assertLess(max(rms_dbfs(m) for m in quiet), -55.0)

        say = rospy.ServiceProxy("/sim/say", Say)
        say.wait_for_service(10.0)
        spoken = say(speaker_id=10, act="QUESTION:TOILET",
                     content="excuse me where is the toilet please")
        self.assertTrue(spoken.success, spoken.message)
        asked_at = rospy.get_time()
        self.wait_sim(spoken.duration + 2.0)
        with self.lock:
            speech = [m for t, m in self.chunks[0] if asked_at <= t <= asked_at + spoken.duration]
            playback = [m for t, m in self.chunks[5] if t >= asked_at]
            voice = [(t, v) for t, v in self.voice if t >= asked_at - 0.2]
            directions = [d for t, d in self.directions if t >= asked_at]
        loud = max(rms_dbfs(m) for m in speech)
        print("Clara's question: loudest chunk %.1f dBFS on channel 0; ARI's playback %.1f dBFS"
              % (loud, max(rms_dbfs(m) for m in playback)))
        self.assertGreater(loud, -45.0)
        self.assertLess(max(rms_dbfs(m) for m in playback), -80.0)
        self.assertIn(True, [v for _, v in voice], "no voice detected")
        self.assertFalse(voice[-1][1], "the voice is still detected after the question")
        self.assertGreater(len(directions), 5)
        median = statistics.median(directions)
        print("sound_direction while she spoke: median %d deg of %d, Clara at %.1f deg" %
              (median, len(directions), CLARA_BEARING_DEG))
        self.assertLess(abs(median - CLARA_BEARING_DEG), 8.0)


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "audio_topics", AudioNodeTest)
