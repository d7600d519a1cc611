#!/usr/bin/python3
"""rostest, must-show 2 of issue 30 (group_discussion_audio.test): group_discussion succeeds
with ARI hearing through its microphone array and pocketsphinx. The final transcripts come from
speech_recognition_node's voices only (no simulated voice is published), one of them shares most
of its words with Irene's question, and ARI answers the time only after that transcript arrived.
When pocketsphinx gives words ARI cannot take for a line, ARI asks Irene to say it again
(`not_understood`) and she asks "What is the time?", which counts as her question too."""
import threading
import unittest

import rospy
import rostest
import scenario_start

from ari_social_sim.msg import IdsList, LiveSpeech, ScenarioStatus, WorldState
from ari_social_sim.srv import SetGroupConversation

QUESTION = {"hello", "yes", "what", "is", "the", "time"}
ANSWER = "It is 14:30."


class Recorder:
    """Final transcripts with their voice and sim time, when ARI began its answer, the
    publishers of /humans/voices/tracked, and the scenario's last status."""

    def __init__(self):
        self.lock = threading.Lock()
        self.finals = []  # (sim time, voice id, text)
        self.followed = {}
        self.answer_s = None
        self.status = None
        rospy.Subscriber("/sim/world_state", WorldState, self.on_world, queue_size=100)
        rospy.Subscriber("/humans/voices/tracked", IdsList, self.on_voices, queue_size=10)
        rospy.Subscriber("/scenario/status", ScenarioStatus, self.on_status, queue_size=10)

    def on_world(self, msg):
        if self.answer_s is None and msg.has_ari and msg.ari.speech.content == ANSWER:
            with self.lock:
                self.answer_s = msg.header.stamp.to_sec()

    def on_voices(self, msg):
        for voice in msg.ids:
            if voice not in self.followed:
                self.followed[voice] = rospy.Subscriber(
                    "/humans/voices/%s/speech" % voice, LiveSpeech,
                    lambda speech, v=voice: self.on_speech(v, speech), queue_size=10)

    def on_speech(self, voice, msg):
        if msg.final:
            with self.lock:
                self.finals.append((rospy.get_time(), voice, msg.final))

    def on_status(self, msg):
        with self.lock:
            self.status = msg


def overlap(text):
    words = set(text.lower().split())
    return len(words & QUESTION) / float(len(QUESTION))


class GroupDiscussionAudio(unittest.TestCase):
    def test_ari_answers_what_it_heard(self):
        recorder = Recorder()
        warnings = scenario_start.NodeWarnings()
        # Issue 30's measure: the scripted exchange heard through the array, without Paul and
        # Irene's small talk (issue 31, checked by scenario_suite). With it, pocketsphinx took
        # Irene's question and a later line for one utterance in 1 of 2 runs of seed 2 ("oh yes
        # we're a bit not to worry"), finding no utterance end between them.
        rospy.wait_for_service("/sim/set_group_conversation", 60.0)
        self.assertTrue(rospy.ServiceProxy("/sim/set_group_conversation", SetGroupConversation)(
            group_id=1, enabled=False).success)
        self.assertTrue(
            scenario_start.unpause_when_scenario_node_listens("/test_group_discussion_audio"))
        scenario_start.wait_until_finished(recorder, 240.0)
        with recorder.lock:
            status, finals, answer_s = recorder.status, list(recorder.finals), recorder.answer_s
        publishers = rospy.get_master().getSystemState()[2][0]
        print("final transcripts: %s; ARI answered at %s s" % (finals, answer_s))
        self.assertIsNotNone(status, "no /scenario/status")
        self.assertTrue(status.finished, "not finished in state %s" % status.state)
        self.assertTrue(status.success, "%s (warnings: %s)" % (status.reason, warnings.text()))
        voice_publishers = [p for topic, p in publishers if topic == "/humans/voices/tracked"]
        self.assertEqual(voice_publishers, [["/speech_recognition"]])
        heard = [(t, text) for t, _, text in finals if overlap(text) >= 0.5]
        self.assertTrue(heard, "no transcript with half of Irene's words: %s" % finals)
        self.assertIsNotNone(answer_s, "ARI never said the time")
        self.assertLessEqual(heard[0][0], answer_s)


if __name__ == "__main__":
    rospy.init_node("test_group_discussion_audio")
    rostest.rosrun("ari_social_sim", "group_discussion_audio", GroupDiscussionAudio)
