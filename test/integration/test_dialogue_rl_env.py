#!/usr/bin/python3
"""rostest, dialogue_node mode 2 (rl_env): /sim/dialogue/reset and /sim/dialogue/step behave as
a Gymnasium environment: numbers per step, same seed -> same observations, bad requests refused
with the field named, the episode untouched and the node still answering."""
import unittest

import rospy
import rostest

from ari_social_sim.srv import DialogueReset, DialogueStep

GREETING = ["greet()", "inform(ari(name))", "offer-help()"]
MAX_TURNS = 40  # config/dialogue/simulation.yaml: reward.max_turns


def heard_key(observation):
    return [(h.dropped, h.speaker, tuple(h.addressees), h.text, tuple(h.acts),
             round(h.confidence, 9)) for h in observation.heard]


def answer(observation):
    """A tiny policy: greet first, then answer each request heard with the domain's answer form
    for places (inform(directions(x))) and drinks, cant-help() for anything else asked."""
    acts = []
    for heard in observation.heard:
        if heard.dropped or "ARI" not in heard.addressees:
            continue
        for act in heard.acts:
            if act.startswith("request(location(") or act.startswith("request(directions("):
                acts.append("inform(directions(%s" % act.split("(", 2)[2])
            elif act.startswith("request(beverage("):
                acts.append("inform(" + act[len("request("):])
            elif act.startswith("request("):
                acts.append("cant-help()")
    return sorted(set(acts))


class DialogueRlEnv(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("dialogue_rl_env_test")
        rospy.wait_for_service("/sim/dialogue/reset", timeout=30)
        rospy.wait_for_service("/sim/dialogue/step", timeout=30)
        cls.reset = rospy.ServiceProxy("/sim/dialogue/reset", DialogueReset)
        cls.step = rospy.ServiceProxy("/sim/dialogue/step", DialogueStep)

    def episode(self, seed):
        """Runs one episode of the tiny policy; returns the observations, rewards and last step."""
        start = self.reset(seed)
        self.assertTrue(start.success)
        observations = [heard_key(start.observation)]
        rewards = []
        acts = GREETING
        last = None
        for turn in range(1, MAX_TURNS + 1):
            last = self.step(acts, [], "")
            self.assertTrue(last.success, last.message)
            self.assertEqual(last.info.robot_turns, turn)
            self.assertEqual(last.observation.robot_turn, turn)
            observations.append(heard_key(last.observation))
            rewards.append(last.reward)
            if last.terminated or last.truncated:
                break
            acts = answer(last.observation)
        return observations, rewards, last

    def test_0_step_before_reset_is_refused(self):
        refused = self.step(GREETING, [], "")
        self.assertFalse(refused.success)
        self.assertIn("reset", refused.message)

    def test_1_reset_gives_goals_patience_and_the_opening(self):
        start = self.reset(4)
        self.assertTrue(start.success)
        self.assertEqual(start.info.roles, ["patient", "companion"])
        self.assertEqual(start.info.robot_turns, 0)
        self.assertGreaterEqual(len(start.info.goals), 1)
        self.assertEqual(len(start.info.patience), 2)
        self.assertTrue(all(3 <= p <= 5 for p in start.info.patience))  # min/max_patience
        self.assertEqual(start.observation.robot_turn, 0)
        self.assertEqual(start.info.utterances, len(start.observation.heard))

    def test_2_rewards_add_up_and_the_episode_ends_by_the_cap(self):
        observations, rewards, last = self.episode(4)
        turns = len(rewards)
        self.assertLessEqual(turns, MAX_TURNS)
        self.assertTrue(last.terminated != last.truncated)
        self.assertEqual(last.truncated, turns == MAX_TURNS and not last.terminated)
        # -1 a turn; the last step adds +80 on success or -40 otherwise (reward: in simulation.yaml).
        self.assertTrue(all(r == -1.0 for r in rewards[:-1]))
        self.assertEqual(rewards[-1], -1.0 + (80.0 if last.info.success else -40.0))
        self.assertEqual(last.info.complete or not last.info.success, True)
        # Stepping a finished episode is refused until the next reset.
        again = self.step([], [], "")
        self.assertFalse(again.success)
        self.assertIn("reset", again.message)

    def test_3_same_seed_same_observations_other_seed_others(self):
        first = self.episode(7)
        second = self.episode(7)
        self.assertEqual(first[0], second[0])
        self.assertEqual(first[1], second[1])
        self.assertGreaterEqual(sum(len(o) for o in first[0]), 5)
        other = self.episode(8)
        self.assertNotEqual(first[0], other[0])

    def test_4_success_rate_of_the_tiny_policy(self):
        # 20 episodes: the tiny policy answers places and drinks; numbers go to docs/dialogue.md.
        results = [self.episode(seed)[2] for seed in range(100, 120)]
        complete = sum(r.info.complete for r in results)
        success = sum(r.info.success for r in results)
        rospy.loginfo("tiny policy: complete %d/20, success %d/20", complete, success)
        self.assertGreaterEqual(complete, success)
        self.assertGreaterEqual(complete, 5)

    def test_5_bad_requests_are_refused_with_the_reason(self):
        self.reset(4)
        bad_intent = self.step(["requets(location(toilet))"], [], "")
        self.assertFalse(bad_intent.success)
        self.assertIn("acts[0]", bad_intent.message)
        self.assertIn("unknown intent 'requets'", bad_intent.message)
        bad_addressee = self.step(["thank()"], ["visitor"], "")
        self.assertFalse(bad_addressee.success)
        self.assertIn("addressees[0]", bad_addressee.message)
        self.assertIn("'visitor'", bad_addressee.message)
        # The episode is untouched by refused steps: the next good one is turn 1.
        good = self.step(GREETING, ["patient"], "")
        self.assertTrue(good.success)
        self.assertEqual(good.info.robot_turns, 1)

    def test_6_every_bad_field_is_named_and_the_node_goes_on(self):
        start = self.reset(4)
        self.assertTrue(start.success)
        cases = [
            # (acts, addressees, text), the start of the message
            (["greet()"] * 17, [], "", "acts: expected at most 16 acts, got 17"),
            (["greet()", "inform(ari(name)"], [], "", "acts[1]: dialogue act 'inform(ari(name)'"),
            (["greet()", "thank(\x00)"], [], "",
             "acts[1]: expected UTF-8 text without control characters, got byte 0x00 at 6"),
            (["greet()"], ["patient", "patient"], "",
             "addressees[1]: expected each role once, got 'patient' again"),
            (["greet()"], ["ARI"], "", "addressees[0]: expected one of the humans' roles"),
            (["greet()"], [], "x" * 5000, "text: expected at most 4096 bytes, got 5000"),
            (["greet()"], [], "Hello\athere",
             "text: expected UTF-8 text without control characters, got byte 0x07 at 5"),
        ]
        for acts, addressees, text, message in cases:
            refused = self.step(acts, addressees, text)
            self.assertFalse(refused.success, message)
            self.assertTrue(refused.message.startswith(message), refused.message)
        # Every refusal left the episode as it was: the next good step is turn 1, and text in any
        # script (UTF-8) with tabs and newlines is fine.
        good = self.step(GREETING, ["patient", "companion"], "Hello,\tI am ARI.\nBonjour, ça va ?")
        self.assertTrue(good.success, good.message)
        self.assertEqual(good.info.robot_turns, 1)
        # Seeds take the whole uint64 range.
        for seed in (0, 2 ** 63, 2 ** 64 - 1):
            self.assertTrue(self.reset(seed).success)


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "dialogue_rl_env", DialogueRlEnv)
