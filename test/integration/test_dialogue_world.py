#!/usr/bin/python3
"""rostest, dialogue_node mode 1 (world): a patient and a companion of the waiting room converse
with a scripted ARI through /tts; every utterance plays in the world word by word at 150 words per
minute (0.4 s a word), in turn, with the turn timing's gaps, and hri_perception_node's voices hear
them as ROS4HRI LiveSpeech."""
import threading
import time
import unittest

import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from std_msgs.msg import String
from std_srvs.srv import SetBool

from ari_social_sim.msg import (DialogueUtterance, IdsList, LiveSpeech, TtsActionFeedback,
                                TtsActionResult, TtsFeedback, WorldState)
from ari_social_sim.srv import StepSimulation

WORD_S = 0.4  # 150 wpm, the waiting room's default rate and the dialogue's seconds_per_word
STEP_S = 0.05  # world_node's step
ROBOT_SILENCE_S = 3.0  # dialogue_world.test
EPS = 1e-6
# dialogue_node reacts to the world state it has processed, calls /sim/say, and the world steps on
# meanwhile (a step is 20 ms of wall time at real_time_factor 2.5): a start or an end is seen a
# few steps late, more on a loaded machine. The measured latencies are printed; the bound is 10
# steps.
LATENCY_S = 10 * STEP_S


class WorldSpeech:
    """Every act each speaker played, from /sim/world_state: its start, every (stamp, word index,
    word) sample seen while it played, and the stamp at which the speaker was first seen no
    longer playing it. On a loaded machine a slow subscriber may miss states (world_node queues
    10), so checks use the samples seen, not the moments a word was first seen."""

    def __init__(self):
        self.acts = {}  # (speaker id, content, start time) -> dict
        self.current = {}  # speaker id -> key of the act being played
        self.now = 0.0
        self.states = 0
        self.first_stamp = None
        self.lock = threading.Lock()
        self.subscriber = rospy.Subscriber("/sim/world_state", WorldState, self.on_state,
                                           queue_size=1000)

    def follow(self, speaker_id, speech, stamp):
        key = (speaker_id, speech.content, round(speech.start_time, 6)) if speech.is_speaking \
            else None
        previous = self.current.get(speaker_id)
        if previous is not None and previous != key:
            self.acts[previous]["end"] = stamp
        if key is not None:
            act = self.acts.setdefault(key, {"start": speech.start_time, "samples": [], "end": None})
            act["samples"].append((stamp, speech.word_index, speech.current_word))
        self.current[speaker_id] = key

    def on_state(self, state):
        stamp = state.header.stamp.to_sec()
        with self.lock:
            self.now = stamp
            self.states += 1
            self.first_stamp = stamp if self.first_stamp is None else self.first_stamp
            if state.has_ari:
                self.follow(state.ari.id, state.ari.speech, stamp)
            for human in state.humans:
                self.follow(human.id, human.speech, stamp)

    def played(self, speaker_id, content, not_before):
        """The act of `speaker_id` saying `content` that started first at or after `not_before`."""
        with self.lock:
            found = [(k, a) for k, a in self.acts.items()
                     if k[0] == speaker_id and k[1] == content and a["start"] >= not_before - EPS]
        return min(found, key=lambda ka: ka[1]["start"])[1] if found else None


class Voices:
    """What hri_perception_node reports hearing: LiveSpeech per voice id (subscribed as each id
    appears in /humans/voices/tracked) and every voice id persons human10 and human11 had (a
    voice id is transient: a voice silent for a while comes back under a new one)."""

    def __init__(self):
        self.speech = {}
        self.subscribers = {}
        self.person_voice = {}
        rospy.Subscriber("/humans/voices/tracked", IdsList, self.on_tracked, queue_size=10)
        for person in ("human10", "human11"):
            rospy.Subscriber("/humans/persons/%s/voice_id" % person, String,
                             lambda m, p=person: self.person_voice.setdefault(p, set()).add(
                                 m.data))

    def on_tracked(self, msg):
        for voice in msg.ids:
            if voice not in self.subscribers:
                self.speech[voice] = []
                self.subscribers[voice] = rospy.Subscriber(
                    "/humans/voices/%s/speech" % voice, LiveSpeech, self.speech[voice].append,
                    queue_size=1000)


class DialogueWorld(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("dialogue_world_test")
        cls.sim_duration = rospy.get_param("~sim_duration")
        cls.lines = rospy.get_param("~lines")
        cls.world = WorldSpeech()
        cls.voices = Voices()
        cls.utterances = []
        cls.feedback = {}
        cls.results = []
        listeners = [
            cls.world.subscriber,
            rospy.Subscriber("/sim/dialogue/utterances", DialogueUtterance,
                             lambda m: cls.utterances.append(m), queue_size=100),
            rospy.Subscriber("/tts/feedback", TtsActionFeedback,
                             lambda m: cls.feedback.setdefault(m.status.goal_id.id, []).append(
                                 m.feedback), queue_size=100),
            rospy.Subscriber("/tts/result", TtsActionResult, lambda m: cls.results.append(m),
                             queue_size=100)]
        # The world starts paused. dialogue_node advertises once it has seen a world state: step
        # the world a step at a time until this test hears every publisher, then let it run, so
        # that nothing is said before the test listens.
        rospy.wait_for_service("/sim/step", timeout=60)
        step = rospy.ServiceProxy("/sim/step", StepSimulation)
        limit = time.monotonic() + 60.0
        while any(s.get_num_connections() == 0 for s in listeners):
            assert time.monotonic() < limit, "dialogue_node or world_node did not come up"
            step(1)
            time.sleep(0.2)
        rospy.ServiceProxy("/sim/pause", SetBool)(False)
        limit = time.monotonic() + 150.0
        while time.monotonic() < limit and cls.world.now < cls.sim_duration:
            time.sleep(0.1)
        cls.end_s = cls.world.now

    def finished_utterances(self):
        """Utterances whose playing must be over by the end of the run (2 steps of slack)."""
        return [u for u in self.utterances
                if u.header.stamp.to_sec() + len(u.text.split()) * WORD_S + 2 * STEP_S < self.end_s]

    def test_1_every_utterance_plays_word_by_word_at_150_wpm(self):
        finished = self.finished_utterances()
        humans = [u for u in finished if u.speaker != "ARI"]
        self.assertGreaterEqual(len(humans), 4)
        self.assertEqual({u.speaker for u in humans}, {"patient", "companion"})
        # Marie (10) is the waiting room's first patient, Jean (11) its first companion.
        self.assertEqual({u.speaker_id for u in humans}, {10, 11})
        self.assertEqual({u.person_id for u in humans}, {"human10", "human11"})
        latencies = []
        for u in finished:
            words = u.text.split()
            act = self.world.played(u.speaker_id, u.text, u.header.stamp.to_sec())
            self.assertIsNotNone(act, "not played: %s %r" % (u.speaker, u.text))
            # Played from the world time the node had seen when it called /sim/say.
            latency = act["start"] - u.header.stamp.to_sec()
            self.assertGreaterEqual(latency, -EPS)
            self.assertLessEqual(latency, LATENCY_S + EPS)
            latencies.append(latency)
            # Every sample shows the word the 150 wpm clock gives: word i is current during
            # [start + 0.4 i, start + 0.4 (i + 1)), evaluated at the step's time.
            for stamp, index, word in act["samples"]:
                elapsed = stamp - act["start"]
                self.assertIn(index, {int((elapsed - EPS) / WORD_S), int((elapsed + EPS) / WORD_S)},
                              "%s at +%.3f s: word %d" % (u.text, elapsed, index))
                self.assertEqual(word, words[index])
            # Every word was played, in order.
            indices = [index for _, index, _ in act["samples"]]
            self.assertEqual(sorted(set(indices)), list(range(len(words))), u.text)
            self.assertEqual(indices, sorted(indices))
            # The act lasts n x 0.4 s: still playing in its last word, silent from its end on.
            last_sample = act["samples"][-1][0] - act["start"]
            self.assertGreaterEqual(last_sample, (len(words) - 1) * WORD_S - EPS)
            self.assertLess(last_sample, len(words) * WORD_S - EPS)
            self.assertIsNotNone(act["end"], u.text)
            self.assertGreaterEqual(act["end"] - act["start"], len(words) * WORD_S - EPS)
        print("%d utterances (%d human) played word by word; say latency mean %.3f s, max %.3f s;"
              " %d of %d world states seen" % (
                  len(finished), len(humans), sum(latencies) / len(latencies), max(latencies),
                  self.world.states, round((self.world.now - self.world.first_stamp) / STEP_S) + 1))

    def test_2_turns_do_not_overlap_and_keep_the_drawn_gaps(self):
        finished = self.finished_utterances()
        played = []
        for u in finished:
            act = self.world.played(u.speaker_id, u.text, u.header.stamp.to_sec())
            # The world ends an act of n words n x 0.4 s after its start (a whole number of steps).
            played.append((act["start"], act["start"] + len(u.text.split()) * WORD_S, u))
        played.sort(key=lambda p: p[0])
        checked = 0
        errors = []
        for (start0, end0, u0), (start1, end1, u1) in zip(played, played[1:]):
            self.assertGreaterEqual(start1, end0 - EPS, "%r overlaps %r" % (u1.text, u0.text))
            if u1.speaker == "ARI" or u1.turn != u0.turn + 1:
                continue
            # A human follows the previous utterance after the gap drawn for it, or after ARI's
            # silence (a silent robot step); end and start are each seen to within a step.
            pause = start1 - end0
            drawn = u1.planned_start - u0.planned_end
            error = min(abs(pause - drawn), abs(pause - ROBOT_SILENCE_S))
            self.assertLessEqual(error, LATENCY_S + EPS,
                                 "pause %.3f s, drawn gap %.3f s: %r" % (pause, drawn, u1.text))
            self.assertGreaterEqual(pause, min(drawn, ROBOT_SILENCE_S) - EPS)
            errors.append(error)
            checked += 1
        self.assertGreaterEqual(checked, 3)
        print("%d pauses after a human or ARI: |pause - drawn gap or silence| mean %.3f s, max %.3f s"
              % (checked, sum(errors) / len(errors), max(errors)))

    def test_3_scripted_ari_lines_play_and_their_goals_succeed(self):
        self.assertEqual(len(self.results), self.lines)
        for result in self.results:
            self.assertEqual(result.status.status, GoalStatus.SUCCEEDED)
            feedback = self.feedback[result.status.goal_id.id]
            words = result.result.text.split()
            # One STARTED_PLAYING_WORD per word, text_said growing a word at a time.
            self.assertEqual([f.event_type for f in feedback],
                             [TtsFeedback.TTS_EVENT_STARTED_PLAYING_WORD] * len(words))
            self.assertEqual([f.text_said for f in feedback],
                             [" ".join(words[:i + 1]) for i in range(len(words))])
        ari = [u for u in self.utterances if u.speaker == "ARI"]
        self.assertEqual(len(ari), self.lines)
        self.assertEqual(ari[0].acts, ["greet()", "inform(ari(name))", "offer-help()"])
        self.assertEqual(ari[1].acts, ["inform(directions(toilet))"])
        self.assertEqual(ari[2].acts, ["inform(beverage(coffee))"])
        self.assertEqual(ari[3].acts, ["youre-welcome()"])

    def test_4_perception_voices_hear_the_humans(self):
        # ARI goes next to Marie and Jean before its first line (within the microphones' 5 m);
        # from then on every human utterance is heard by the perception under the speaker's
        # person's voice, word for word (error models off). An utterance may start before this
        # test has subscribed to a new voice id: at most one per voice id is missed.
        ari_start = min(u.header.stamp.to_sec() for u in self.utterances if u.speaker == "ARI")
        heard = [u for u in self.finished_utterances()
                 if u.speaker != "ARI" and u.header.stamp.to_sec() > ari_start]
        self.assertGreaterEqual(len(heard), 4)
        received = 0
        voice_ids = 0
        for human_id in (10, 11):
            voices = self.voices.person_voice.get("human%d" % human_id, set()) - {""}
            self.assertTrue(voices, "no voice for human%d" % human_id)
            finals = [s.final for v in voices for s in self.voices.speech.get(v, []) if s.final]
            said = [u.text for u in heard if u.speaker_id == human_id]
            missed = [text for text in said if text not in finals]
            self.assertLessEqual(len(missed), len(voices), missed)
            # Nothing on this voice that its human did not say. An utterance that began before
            # ARI came within the microphones' range is heard from the first word in range: its
            # final is the end of what was said.
            spoken = [" %s " % u.text for u in self.utterances if u.speaker_id == human_id]
            unsaid = {f for f in finals if not any((" %s " % f) in text for text in spoken)}
            self.assertFalse(unsaid, "heard on human%d's voice but never said: %s"
                             % (human_id, unsaid))
            received += len(said) - len(missed)
            voice_ids += len(voices)
        print("perception heard %d of %d human utterances said with ARI nearby, word for word,"
              " on %d voice ids" % (received, len(heard), voice_ids))


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "dialogue_world", DialogueWorld)
