#!/usr/bin/python3
"""A minimal conversational robot for the user-bot rostest: it listens to every tracked voice's
final LiveSpeech and answers over /tts from a keyword table (the user_bot_domain's places and
drink, greetings, thanks, farewells); anything else gets no answer."""
import queue

import actionlib
import rospy

from ari_social_sim.msg import IdsList, LiveSpeech, TtsAction, TtsGoal

# Keyword in what a human said -> ARI's sentence; every matching keyword adds its sentence.
ANSWERS = [
    ("hello", "Hello. How can I help you?"),
    ("toilets", "The toilets are down the corridor, second door on the left."),
    ("coffee", "There's coffee at the cafeteria on the ground floor."),
    ("cafeteria", "The cafeteria is on the ground floor: enter the second building behind you."),
    ("lifts", "The lifts are at the entrance on the left."),
    ("thank", "You're welcome."),
    ("goodbye", "See you around, have a nice day."),
]


def answer(text):
    heard = text.lower()
    sentences = []
    for keyword, sentence in ANSWERS:
        # coffee is served at the cafeteria: one answer, not two
        if keyword == "cafeteria" and "coffee" in heard:
            continue
        if keyword in heard:
            sentences.append(sentence)
    return " ".join(sentences)


class MinimalRobot:
    def __init__(self):
        self.voices = {}
        self.heard = queue.Queue()
        self.client = actionlib.SimpleActionClient("/tts", TtsAction)
        rospy.Subscriber("/humans/voices/tracked", IdsList, self.on_voices, queue_size=10)

    def on_voices(self, msg):
        for voice in msg.ids:
            if voice not in self.voices:
                self.voices[voice] = rospy.Subscriber(
                    "/humans/voices/%s/speech" % voice, LiveSpeech, self.on_speech, queue_size=100)

    def on_speech(self, msg):
        if msg.final:
            self.heard.put(msg.final)

    def run(self):
        self.client.wait_for_server()
        while not rospy.is_shutdown():
            try:
                text = self.heard.get(timeout=0.1)
            except queue.Empty:
                continue
            reply = answer(text)
            if reply:
                goal = TtsGoal()
                goal.rawtext.text = reply
                goal.rawtext.lang_id = "en_GB"
                self.client.send_goal(goal)
                self.client.wait_for_result()


if __name__ == "__main__":
    rospy.init_node("minimal_robot")
    MinimalRobot().run()
