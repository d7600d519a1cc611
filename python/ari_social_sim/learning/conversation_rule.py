"""The rule baseline of join_conversation (docs/learning.md): a navigation policy drives, and ARI
speaks only in a pause, to answer a question or, near its place in the group, to greet once. With
`wait_for_pause` it also stops short of the group while a member speaks, to enter in a pause."""

import numpy as np

PAUSE_S = 0.5           # no member heard, and this long since a member's line ended
GREETING_RANGE_M = 0.5  # goal distance under which ARI greets
# Goal distances (m) over which ARI waits while a member speaks: the formation takes ARI in
# within 0.8 m of its o-space's edge, and at the place (under 0.3 m) ARI is already in.
WAIT_RANGE_M = (0.3, 2.5)


class PauseSpeaker:
    """Wraps a navigation policy (an act(obs) of the first part of the observation, such as
    learning.load_policy's) into join_conversation's 4-element action. Call reset() at each
    episode's start: it greets once per episode."""

    def __init__(self, driver, layout, wait_for_pause=True):
        self._driver = driver
        self._navigation = slice(0, layout["conversation"].start)
        self._conversation = layout["conversation"]
        self._goal_distance = layout["goal"].stop - 1
        self._wait_for_pause = wait_for_pause
        self._greeted = False
        self.always_speak = False  # a contrast for evaluations: speak at every step

    def reset(self):
        self._greeted = False

    def act(self, observation):
        heard, addressed, silence_s, speaking = observation[self._conversation]
        distance = observation[self._goal_distance]
        pause = silence_s > PAUSE_S and heard < 0.5 and speaking < 0.5
        greet = not self._greeted and distance < GREETING_RANGE_M
        speak = self.always_speak or (pause and (addressed > 0.5 or greet))
        self._greeted = self._greeted or (speak and greet)
        drive = list(self._driver.act(observation[self._navigation]))
        member_speaks = heard > 0.5 or silence_s == 0.0
        if self._wait_for_pause and member_speaks and WAIT_RANGE_M[0] < distance < WAIT_RANGE_M[1]:
            drive[0] = drive[1] = 0.0  # the head keeps turning
        return np.array(drive + [1.0 if speak else 0.0], np.float32)
