#!/usr/bin/python3
"""Live measurement of hri_perception_node (docs/PERFORMANCE.md): world_node steps at 30 Hz in real
time with N people in the hospital waiting room (scenes/perception_demo.yaml plus people spawned
at seeded random places, some in groups, someone always talking), and hri_perception_node perceives
every world state. Reports, over the measurement window in wall time:
  - the rates of /sim/world_state and /humans/bodies/tracked (Hz);
  - the lag of each tracked list behind the world state it was computed from (same stamp): the
    arrival time of the list minus the arrival time of the state, at this subscriber (ms);
  - the CPU time hri_perception_node used, as a share of one core.
Both topics are taken raw (rospy.AnyMsg, no deserialisation) and with TCP_NODELAY, so the
measurement adds as little as possible to either arrival.

Usage (after a build, with the package sourced):
  bench/perception_live.py [--people 50] [--seconds 30] [--port 11398] [--seed 1]
"""
import argparse
import os
import random
import signal
import statistics
import struct
import subprocess
import sys
import threading
import time

import rospy
from geometry_msgs.msg import Point, Pose2D

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE = os.path.dirname(HERE)
SENTENCES = ["could you tell me where the pharmacy is please",
             "we have been waiting here for almost an hour now",
             "the doctor said she would call us after lunch"]


def stamp_of(raw):
    """(secs, nsecs) of a message starting with std_msgs/Header (seq, stamp, frame_id)."""
    _, secs, nsecs = struct.unpack_from("<3I", raw._buff, 0)
    return secs, nsecs


class Arrivals:
    """Wall arrival time of each stamp on a topic."""

    def __init__(self, topic):
        self.times = {}
        self.count = 0
        self._lock = threading.Lock()
        rospy.Subscriber(topic, rospy.AnyMsg, self._on_msg, queue_size=100,
                         tcp_nodelay=True)

    def _on_msg(self, raw):
        now = time.monotonic()
        with self._lock:
            self.times.setdefault(stamp_of(raw), now)
            self.count += 1

    def since(self, start):
        with self._lock:
            return {s: t for s, t in self.times.items() if t >= start}


def cpu_seconds(parent, name):
    """User + system CPU seconds of the child process of `parent` called `name`."""
    ticks = os.sysconf("SC_CLK_TCK")
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % pid) as stat:
                fields = stat.read().rsplit(")", 1)[1].split()
            with open("/proc/%s/comm" % pid) as comm:
                command = comm.read().strip()
        except OSError:
            continue
        # After the command: state, ppid, ..., utime (12th), stime (13th); comm is cut at 15.
        if int(fields[1]) == parent and name.startswith(command):
            return (int(fields[11]) + int(fields[12])) / ticks
    return float("nan")


def populate(people, seed):
    from ari_social_sim.srv import CreateGroup, Say, SpawnHuman
    rospy.wait_for_service("/sim/spawn_human", timeout=30)
    spawn = rospy.ServiceProxy("/sim/spawn_human", SpawnHuman)
    group = rospy.ServiceProxy("/sim/create_group", CreateGroup)
    say = rospy.ServiceProxy("/sim/say", Say)
    rng = random.Random(seed)
    spawned = []
    already = 8  # the people of scenes/perception_demo.yaml
    while already + len(spawned) < people:
        pose = Pose2D(rng.uniform(0.5, 11.5), rng.uniform(0.5, 8.5), rng.uniform(-3.14, 3.14))
        response = spawn(id=0, name="", role="visitor", pose=pose, age=rng.uniform(18, 90),
                         gender=rng.choice(["female", "male"]), mask=rng.random() < 0.2,
                         emotion=rng.choice(["neutral", "happy", "angry", "disturbed"]))
        if response.success:
            spawned.append((response.id, pose))
    # Groups of three among the newcomers, gathering around their mean position.
    for i in range(0, len(spawned) - 2, 6):
        members = spawned[i:i + 3]
        centre = Point(sum(p.x for _, p in members) / 3, sum(p.y for _, p in members) / 3, 0)
        group(id=0, members=[m for m, _ in members], centre=centre, ospace_radius=0.0)
    return [m for m, _ in spawned] + [10, 20, 21, 22, 40, 41], say


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--people", type=int, default=50)
    parser.add_argument("--seconds", type=float, default=30.0)
    parser.add_argument("--port", type=int, default=11398)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()

    os.environ["ROS_MASTER_URI"] = "http://localhost:%d" % args.port
    launch = subprocess.Popen(
        ["roslaunch", "-p", str(args.port), "ari_social_sim", "world_perception.launch",
         "scene:=%s/scenes/perception_demo.yaml" % PACKAGE, "step:=%.10f" % (1.0 / 30.0)],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    try:
        time.sleep(5.0)
        rospy.init_node("perception_live_measurement", disable_signals=True)
        speakers, say = populate(args.people, args.seed)
        states = Arrivals("/sim/world_state")
        lists = Arrivals("/humans/bodies/tracked")
        time.sleep(5.0)  # warm up: groups forming, trackers filled

        rng = random.Random(args.seed)
        cpu_start = cpu_seconds(launch.pid, "hri_perception_node")
        start = time.monotonic()
        next_utterance = start
        while time.monotonic() - start < args.seconds:
            if time.monotonic() >= next_utterance:
                say(speaker_id=rng.choice(speakers), act="INFORM", content=rng.choice(SENTENCES))
                next_utterance += 3.0
            time.sleep(0.05)
        end = time.monotonic()
        cpu_used = cpu_seconds(launch.pid, "hri_perception_node") - cpu_start

        state_times = {s: t for s, t in states.since(start).items() if t <= end}
        list_times = {s: t for s, t in lists.since(start).items() if t <= end}
        lags_ms = [1000.0 * (list_times[s] - state_times[s]) for s in list_times
                   if s in state_times]
        window = end - start
        print("people %d, window %.1f s wall" % (args.people, window))
        print("/sim/world_state       %.1f Hz" % (len(state_times) / window))
        print("/humans/bodies/tracked %.1f Hz (%d of %d states perceived)"
              % (len(list_times) / window, len(lags_ms), len(state_times)))
        if lags_ms:
            lags_ms.sort()
            print("lag behind /sim/world_state: median %.2f ms, p95 %.2f ms, max %.2f ms"
                  % (statistics.median(lags_ms), lags_ms[int(0.95 * (len(lags_ms) - 1))],
                     lags_ms[-1]))
        print("hri_perception_node CPU: %.1f %% of one core" % (100.0 * cpu_used / window))
        print("load average (1 min) %.2f on %d cores" % (os.getloadavg()[0], os.cpu_count()))
    finally:
        os.killpg(launch.pid, signal.SIGINT)
        launch.wait(timeout=30)


if __name__ == "__main__":
    sys.exit(main())
