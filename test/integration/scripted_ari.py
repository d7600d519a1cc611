#!/usr/bin/python3
"""A scripted ARI for rostests: says its lines over /tts, one each time the humans of the world
have been quiet for ~quiet seconds of sim time, waiting for each goal to finish first."""
import actionlib
import rospy

from ari_social_sim.msg import TtsAction, TtsGoal, WorldState


class ScriptedAri:
    def __init__(self):
        self.lines = rospy.get_param("~lines")
        self.quiet_s = rospy.get_param("~quiet", 1.0)
        self.last_voice_s = None
        self.client = actionlib.SimpleActionClient("/tts", TtsAction)
        rospy.Subscriber("/sim/world_state", WorldState, self.on_state, queue_size=100)

    def on_state(self, state):
        now = state.header.stamp.to_sec()
        if any(h.speech.is_speaking for h in state.humans) or self.last_voice_s is None:
            self.last_voice_s = now
        self.now_s = now

    def quiet(self):
        return self.last_voice_s is not None and self.now_s - self.last_voice_s >= self.quiet_s

    def run(self):
        self.client.wait_for_server()
        for line in self.lines:
            while not rospy.is_shutdown() and not self.quiet():
                rospy.sleep(0.05)
            goal = TtsGoal()
            goal.rawtext.text = line
            goal.rawtext.lang_id = "en_GB"
            self.client.send_goal(goal)
            self.client.wait_for_result()
            self.last_voice_s = self.now_s  # quiet counts from the end of ARI's line
        rospy.spin()


if __name__ == "__main__":
    rospy.init_node("scripted_ari")
    ScriptedAri().run()
