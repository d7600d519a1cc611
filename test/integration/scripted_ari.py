#!/usr/bin/python3
"""A scripted ARI for rostests: first goes to ~pose ([x, y, theta] in the map, when given), then
says its lines over /tts, one each time the humans of the world have been quiet for ~quiet seconds
of sim time, waiting for each goal to finish first."""
import actionlib
import math

import rospy
from geometry_msgs.msg import Pose2D

from ari_social_sim.msg import TtsAction, TtsGoal, WorldState
from ari_social_sim.srv import SetPose


class ScriptedAri:
    def __init__(self):
        self.lines = rospy.get_param("~lines")
        self.quiet_s = rospy.get_param("~quiet", 1.0)
        self.pose = rospy.get_param("~pose", None)
        self.ari_id = None
        self.last_voice_s = None
        self.client = actionlib.SimpleActionClient("/tts", TtsAction)
        rospy.Subscriber("/sim/world_state", WorldState, self.on_state, queue_size=100)

    def on_state(self, state):
        now = state.header.stamp.to_sec()
        self.ari_id = state.ari.id
        # The people it talks with, not a group chatting across the room.
        near = [h for h in state.humans
                if math.hypot(h.pose.x - state.ari.pose.x, h.pose.y - state.ari.pose.y) < 3.0]
        if any(h.speech.is_speaking for h in near) or self.last_voice_s is None:
            self.last_voice_s = now
        self.now_s = now

    def quiet(self):
        return self.last_voice_s is not None and self.now_s - self.last_voice_s >= self.quiet_s

    def run(self):
        self.client.wait_for_server()
        if self.pose is not None:
            while not rospy.is_shutdown() and self.ari_id is None:
                rospy.sleep(0.05)
            rospy.wait_for_service("/sim/set_pose")
            placed = rospy.ServiceProxy("/sim/set_pose", SetPose)(self.ari_id, Pose2D(*self.pose))
            if not placed.success:
                rospy.logerr("scripted_ari: %s", placed.message)
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
