#!/usr/bin/python3
"""audio_node on a live world (audio_node.test): what ARI's audio driver would publish. Chunks of
1024 16-bit samples, 16,000 samples per second of sim time on every channel; silence (the room's
noise) until Clara speaks; while she asks her question the array detects a voice and points at
her, 42.8 degrees to its left; ARI itself is silent on the playback channel.

The world starts paused and the test steps it, so every chunk since t = 0 arrives and the n-th
chunk covers the sim time [n, n + 1) x 64 ms. Nothing is timed by arrival: a loaded machine
delays the chunks, it does not change which ones there are. The first 4 s go in one request, a
burst of 62 chunks that must all arrive; Clara's question goes a world step at a time, as a
running world goes, so that the latest-only direction topics (queue 1, as the real driver's)
carry each chunk's direction."""
import math
import statistics
import struct
import threading
import time
import unittest

import rospy
import rostest
from std_msgs.msg import Bool, Int32

from ari_social_sim.msg import AudioData
from ari_social_sim.srv import Say, StepSimulation

CLARA_BEARING_DEG = math.degrees(math.atan2(5.5 - 4.0, 3.5 - (2.0 - 0.122)))
SAMPLE_RATE_HZ = 16000
CHUNK_SAMPLES = 1024
WORLD_STEP_S = 0.05  # world.launch's step
CATCH_UP_WALL_S = 60.0  # only a hung node takes this long


def rms_dbfs(msg):
    samples = struct.unpack("<%dh" % (len(msg.data) // 2), bytes(msg.data))
    mean_square = sum(s * s for s in samples) / max(len(samples), 1)
    return 10.0 * math.log10(mean_square / 32768.0 ** 2 + 1e-20)


def chunks_through(time_s):
    """How many whole chunks the stream holds once the world has reached time_s."""
    return int(round(time_s * SAMPLE_RATE_HZ)) // CHUNK_SAMPLES


def chunk_at(time_s):
    """The index of the chunk that holds the sample at time_s."""
    return int(time_s * SAMPLE_RATE_HZ) // CHUNK_SAMPLES


def world_steps(seconds):
    return int(math.ceil(seconds / WORLD_STEP_S - 1e-9))


class AudioNodeTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_audio_node")
        cls.lock = threading.Lock()
        cls.chunks = {c: [] for c in range(6)}
        cls.voice = []
        cls.directions = []
        cls.channel_subscribers = [
            rospy.Subscriber("/audio/channel%d" % c, AudioData, cls.on_chunk, c, queue_size=1000)
            for c in range(6)]
        rospy.Subscriber("/audio/voice_detected", Bool, lambda m: cls.record(cls.voice, m.data))
        rospy.Subscriber("/audio/sound_direction", Int32,
                         lambda m: cls.record(cls.directions, m.data))
        cls.step_world = rospy.ServiceProxy("/sim/step", StepSimulation)
        cls.say = rospy.ServiceProxy("/sim/say", Say)

    @classmethod
    def on_chunk(cls, msg, channel):
        cls.record(cls.chunks[channel], msg)

    @classmethod
    def record(cls, into, item):
        with cls.lock:
            into.append(item)

    def wait_until(self, condition, what):
        deadline = time.monotonic() + CATCH_UP_WALL_S
        while not condition():
            self.assertLess(time.monotonic(), deadline, "waited %.0f s for %s" %
                            (CATCH_UP_WALL_S, what))
            time.sleep(0.005)

    def step(self, seconds):
        answer = self.step_world(steps=world_steps(seconds))
        self.assertTrue(answer.success, answer.message)
        return answer.sim_time

    def step_with_audio(self, seconds):
        """Steps one world step at a time, each once its audio has arrived, as a running world."""
        for _ in range(world_steps(seconds)):
            self.wait_for_audio_through(self.step(WORLD_STEP_S))

    def wait_for_audio_through(self, time_s):
        expected = chunks_through(time_s)
        self.wait_until(lambda: all(len(self.chunks[c]) >= expected for c in range(6)),
                        "%d chunks on every channel" % expected)

    def received_chunks(self):
        with self.lock:
            return {c: list(self.chunks[c]) for c in range(6)}

    def test_audio(self):
        self.wait_until(lambda: all(s.get_num_connections() > 0 for s in self.channel_subscribers),
                        "audio_node's channels")
        self.step_world.wait_for_service(CATCH_UP_WALL_S)
        self.say.wait_for_service(CATCH_UP_WALL_S)

        quiet_until = self.step(4.0)
        self.wait_for_audio_through(quiet_until)
        chunks = self.received_chunks()
        for channel, received in chunks.items():
            self.assertEqual(len(received), chunks_through(quiet_until),
                             "channel %d: chunks in %.2f s" % (channel, quiet_until))
        quiet = chunks[0]
        self.assertTrue(all(len(m.data) == 2 * CHUNK_SAMPLES for m in quiet),
                        "chunks of 1024 16-bit samples")
        rate = len(chunks[1]) * CHUNK_SAMPLES / quiet_until
        print("%d chunks in %.2f s of sim time: %.0f samples/s" % (len(chunks[1]), quiet_until,
                                                                   rate))
        self.assertAlmostEqual(rate, SAMPLE_RATE_HZ, delta=CHUNK_SAMPLES / quiet_until)
        self.assertLess(max(rms_dbfs(m) for m in quiet), -55.0)

        with self.lock:
            voice_before, directions_before = len(self.voice), len(self.directions)
        spoken = self.say(speaker_id=10, act="QUESTION:TOILET",
                          content="excuse me where is the toilet please")
        self.assertTrue(spoken.success, spoken.message)
        self.step_with_audio(spoken.duration + 2.0)
        chunks = self.received_chunks()
        # voice_detected changes twice, as she starts and as she ends, long before the last chunk.
        self.wait_until(lambda: len(self.voice) >= voice_before + 2,
                        "the voice's start and end on /audio/voice_detected")
        with self.lock:
            voice = self.voice[voice_before:]
            directions = self.directions[directions_before:]
        speech = chunks[0][chunk_at(quiet_until):chunk_at(quiet_until + spoken.duration) + 1]
        playback = chunks[5][chunk_at(quiet_until):]
        loud = max(rms_dbfs(m) for m in speech)
        print("Clara's question: loudest chunk %.1f dBFS on channel 0; ARI's playback %.1f dBFS"
              % (loud, max(rms_dbfs(m) for m in playback)))
        self.assertGreater(loud, -45.0)
        self.assertLess(max(rms_dbfs(m) for m in playback), -80.0)
        self.assertIn(True, voice, "no voice detected")
        self.assertFalse(voice[-1], "the voice is still detected after the question")
        self.assertGreater(len(directions), 5)
        median = statistics.median(directions)
        print("sound_direction while she spoke: median %d deg of %d, Clara at %.1f deg" %
              (median, len(directions), CLARA_BEARING_DEG))
        self.assertLess(abs(median - CLARA_BEARING_DEG), 8.0)


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "audio_topics", AudioNodeTest)
