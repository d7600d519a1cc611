#!/usr/bin/python3
"""rostest, dialogue_node mode 3 (user bot): the simulated patient and companion speak to a
minimal robot as ASR would (ROS4HRI LiveSpeech per voice, voice and person ids) and hear its /tts
goals; their goals complete."""
import time
import unittest

import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from std_msgs.msg import String

from ari_social_sim.msg import (DialogueOutcome, DialogueUtterance, IdsList, LiveSpeech,
                                TtsActionGoal, TtsActionResult)

IDS = [10, 11]  # dialogue_user_bot.test: human_ids, patient then companion


class DialogueUserBot(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("dialogue_user_bot_test")
        cls.dialogues = rospy.get_param("~dialogues")
        cls.outcomes, cls.utterances, cls.goals, cls.results = [], [], [], []
        cls.speech = {i: [] for i in IDS}
        cls.latest = {}
        rospy.Subscriber("/sim/dialogue/outcome", DialogueOutcome, cls.outcomes.append)
        rospy.Subscriber("/sim/dialogue/utterances", DialogueUtterance, cls.utterances.append,
                         queue_size=100)
        rospy.Subscriber("/tts/goal", TtsActionGoal, cls.goals.append, queue_size=100)
        rospy.Subscriber("/tts/result", TtsActionResult, cls.results.append, queue_size=100)
        for i in IDS:
            rospy.Subscriber("/humans/voices/voice%d/speech" % i, LiveSpeech,
                             cls.speech[i].append, queue_size=1000)
        for topic, msg_type in [("/humans/voices/tracked", IdsList),
                                ("/humans/persons/tracked", IdsList),
                                ("/humans/persons/human10/voice_id", String),
                                ("/humans/persons/human11/voice_id", String)]:
            rospy.Subscriber(topic, msg_type, lambda m, t=topic: cls.latest.__setitem__(t, m))
        limit = time.monotonic() + 200.0
        while time.monotonic() < limit and len(cls.outcomes) < cls.dialogues:
            time.sleep(0.1)
        # The minimal robot may still be answering the last words of the last dialogue (a
        # farewell with thanks gets two sentences): wait for the results of the goals seen.
        limit = time.monotonic() + 10.0
        time.sleep(1.0)
        while time.monotonic() < limit and not cls.every_goal_has_a_result():
            time.sleep(0.1)

    @classmethod
    def every_goal_has_a_result(cls):
        results = {r.status.goal_id.id for r in cls.results}
        return all(g.goal_id.id in results for g in cls.goals)

    def test_1_every_dialogue_ends_with_its_goals_complete(self):
        self.assertEqual([o.dialogue for o in self.outcomes], list(range(self.dialogues)))
        self.assertEqual(len({o.seed for o in self.outcomes}), self.dialogues)
        for outcome in self.outcomes:
            self.assertTrue(outcome.complete, outcome)
            self.assertFalse(outcome.truncated)
            self.assertGreaterEqual(len(outcome.goals), 1)
            self.assertGreaterEqual(outcome.robot_turns, 1)

    def test_2_users_speak_as_asr_live_speech_per_voice(self):
        humans = [u for u in self.utterances if u.speaker != "ARI"]
        self.assertGreaterEqual(len(humans), 3 * self.dialogues)
        for human_id, role in zip(IDS, ["patient", "companion"]):
            said = [u for u in humans if u.speaker_id == human_id]
            self.assertTrue(all(u.speaker == role and u.person_id == "human%d" % human_id
                                for u in said))
            # No error layer here: each utterance is heard once, whole, under its own voice. The
            # node starts once something listens to a voice, so this test may have missed the
            # first utterances on either topic: the transcript and the finals agree from where
            # both were heard.
            finals = [s for s in self.speech[human_id] if s.final]
            common = min(len(finals), len(said))
            self.assertGreaterEqual(common, len(said) - 2)
            self.assertEqual([s.final for s in finals[-common:]], [u.text for u in said[-common:]])
            for s in finals:
                self.assertEqual(s.language, "en-GB")
                self.assertEqual(s.incremental, "")
                self.assertGreaterEqual(s.confidence, 0.0)
                self.assertLessEqual(s.confidence, 1.0)
            # Before each final, its words one at a time as incremental hypotheses (n - 1 of
            # them), counted from the first final this test heard whole.
            partial = []
            expected = []
            first_final = next(i for i, s in enumerate(self.speech[human_id]) if s.final)
            for s in self.speech[human_id][first_final + 1:]:
                if s.final:
                    words = s.final.split()
                    expected.extend(" ".join(words[:k]) for k in range(1, len(words)))
                else:
                    partial.append(s.incremental)
            self.assertEqual(partial, expected)

    def test_3_voice_and_person_ids(self):
        self.assertEqual(self.latest["/humans/voices/tracked"].ids, ["voice10", "voice11"])
        self.assertEqual(self.latest["/humans/persons/tracked"].ids, ["human10", "human11"])
        self.assertEqual(self.latest["/humans/persons/human10/voice_id"].data, "voice10")
        self.assertEqual(self.latest["/humans/persons/human11/voice_id"].data, "voice11")

    def test_4_the_robot_goals_are_heard_and_succeed(self):
        # Every goal the robot sent succeeded with its own text as the text spoken (goals sent
        # before this test subscribed have a result but no goal here).
        texts = {g.goal_id.id: g.goal.rawtext.text for g in self.goals}
        results = {r.status.goal_id.id: r for r in self.results}
        self.assertGreaterEqual(len(results), self.dialogues)
        self.assertTrue(set(texts) <= set(results))
        for goal_id, result in results.items():
            self.assertEqual(result.status.status, GoalStatus.SUCCEEDED)
            if goal_id in texts:
                self.assertEqual(result.result.text, texts[goal_id])
        # What ARI said inside a dialogue is in the transcript with the acts understood.
        said = {r.result.text for r in self.results}
        ari = [u for u in self.utterances if u.speaker == "ARI"]
        self.assertGreaterEqual(len(ari), self.dialogues)
        self.assertTrue(all(u.text in said and u.acts for u in ari))


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "dialogue_user_bot", DialogueUserBot)
