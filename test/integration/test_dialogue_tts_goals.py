#!/usr/bin/python3
"""rostest, dialogue_node's /tts (user_bot mode, no robot listening): each field of a bad goal is
refused (aborted) with the field named, and the node goes on to speak the next good goal."""
import math
import unittest

import actionlib
import rospy
import rostest
from actionlib_msgs.msg import GoalStatus

from ari_social_sim.msg import TtsAction, TtsGoal


def goal(text="Hello there.", wait=0.0, key=""):
    g = TtsGoal()
    g.rawtext.text = text
    g.rawtext.lang_id = "en_GB"
    g.text.key = key
    g.wait_before_speaking = wait
    return g


class DialogueTtsGoals(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("dialogue_tts_goals_test")
        cls.tts = actionlib.SimpleActionClient("/tts", TtsAction)
        assert cls.tts.wait_for_server(rospy.Duration(30))

    def send(self, tts_goal, timeout_s=20.0):
        self.tts.send_goal(tts_goal)
        self.assertTrue(self.tts.wait_for_result(rospy.Duration(timeout_s)))
        return self.tts.get_state(), self.tts.get_result()

    def test_bad_fields_are_named_and_the_node_still_speaks(self):
        cases = [
            (goal(wait=math.nan), "wait_before_speaking: expected a number of seconds in [0, 60], got nan"),
            (goal(wait=math.inf), "wait_before_speaking: expected a number of seconds in [0, 60], got inf"),
            (goal(wait=-1.0), "wait_before_speaking: expected a number of seconds in [0, 60], got -1"),
            (goal(wait=61.0), "wait_before_speaking: expected a number of seconds in [0, 60], got 61"),
            (goal(text=""), "rawtext.text: expected the words to say, got ''"),
            (goal(text="   "), "rawtext.text: expected the words to say, got '   '"),
            (goal(text="", key="greeting"), "text: I18nText lookup (section/key) is not simulated"),
            (goal(text="word " * 1000), "rawtext.text: expected at most 4096 bytes, got 5000"),
            (goal(text="Hello\x00there"),
             "rawtext.text: expected UTF-8 text without control characters, got byte 0x00 at 5"),
        ]
        for bad, message in cases:
            state, result = self.send(bad)
            self.assertEqual(state, GoalStatus.ABORTED, message)
            self.assertTrue(result.msg.startswith(message), result.msg)
        state, result = self.send(goal(text="Hello, I am ARI. ça va ?", wait=0.5))
        self.assertEqual(state, GoalStatus.SUCCEEDED, result.msg)
        self.assertEqual(result.text, "Hello, I am ARI. ça va ?")


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "dialogue_tts_goals", DialogueTtsGoals)
