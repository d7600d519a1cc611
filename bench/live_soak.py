#!/usr/bin/python3
"""Memory soak of the live nodes (docs/PERFORMANCE.md, "Soak of the live nodes").

Runs navigation.launch (world_node, robot_state_publisher, hri_perception_node,
group_detection_node and social_mpc_node) on a hall of N people with ARI in the middle
(scripts/make_crowd_scene.py --ari), the world as fast as it can go (real_time_factor 0), and keeps
everything moving for the whole run, so that a node whose memory follows the run's length rather
than the scene would show it:
  - ARI is sent to random places in the hall (move_base) and, every third goal, to approach a
    random tracked person (/social_mpc/approach); a goal not finished after 90 sim-s is cancelled;
  - every 10 sim-s the oldest walker leaves and a newcomer, with a new world id, walks in;
  - every 5 sim-s five walkers get new goals; every 2 sim-s someone says a sentence.
Every minute of wall time it prints the resident set (VmRSS) of each node. At the end it prints,
per node, the RSS at the end of the warm-up, the lowest and highest after it, and the trend: how
much the least-squares line through the samples after the warm-up rises over the run, as a share
of where it starts; it exits 1 if a trend is beyond --tolerance percent either way.

Usage (after a build, with the package sourced):
  bench/live_soak.py [--minutes 60] [--warmup 10] [--humans 200] [--seed 1] [--port 11411]
                     [--tolerance 5] [--report FILE.md]
  bench/live_soak.py --analyse FILE.md [--warmup 10] [--tolerance 5]   # verdict of a saved run
"""
import argparse
import math
import os
import random
import signal
import subprocess
import sys
import tempfile
import time

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE = os.path.dirname(HERE)
NODES = ["world_node", "robot_state_publisher", "hri_perception", "group_detection",
         "social_mpc_node"]
SENTENCES = ["could you tell me where the pharmacy is please",
             "we have been waiting here for almost an hour now",
             "the doctor said she would call us after lunch",
             "is this the queue for the blood tests"]
LEAVE_EVERY_S = 10.0
REGOAL_EVERY_S = 5.0
SPEAK_EVERY_S = 2.0
GOAL_TIMEOUT_S = 90.0


def int_in(low, high):
    def parse(text):
        value = int(text)
        if not low <= value <= high:
            raise argparse.ArgumentTypeError("expected %d to %d, got %d" % (low, high, value))
        return value
    return parse


def node_pids(launch_pid):
    """{node name: pid} of the processes roslaunch started, found by their __name:= argument
    among its children (another launch on the machine may run nodes of the same names)."""
    pids = {}
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % pid) as stat:
                parent = int(stat.read().rsplit(")", 1)[1].split()[1])
            with open("/proc/%s/cmdline" % pid, "rb") as cmdline:
                args = cmdline.read().split(b"\0")
        except OSError:
            continue
        if parent != launch_pid:
            continue
        for node in NODES:
            if ("__name:=" + node).encode() in args:
                pids[node] = int(pid)
    return pids


def rss_kib(pid):
    try:
        with open("/proc/%d/status" % pid) as status:
            for line in status:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
    except OSError:
        pass
    return None


class Driver:
    """Keeps the hall moving and ARI navigating; every action is seeded."""

    def __init__(self, side, seed):
        import actionlib
        import rospy
        from ari_social_sim.msg import ApproachAction, IdsList
        from ari_social_sim.srv import RemoveHuman, Say, SetGoal, SpawnHuman
        from move_base_msgs.msg import MoveBaseAction

        self.rospy = rospy
        self.side = side
        self.rng = random.Random(seed)
        for name in ("/sim/spawn_human", "/sim/remove_human", "/sim/set_goal", "/sim/say"):
            rospy.wait_for_service(name, timeout=60)
        self.spawn = rospy.ServiceProxy("/sim/spawn_human", SpawnHuman, persistent=True)
        self.remove = rospy.ServiceProxy("/sim/remove_human", RemoveHuman, persistent=True)
        self.set_goal = rospy.ServiceProxy("/sim/set_goal", SetGoal, persistent=True)
        self.say = rospy.ServiceProxy("/sim/say", Say, persistent=True)
        self.move_base = actionlib.SimpleActionClient("move_base", MoveBaseAction)
        self.approach = actionlib.SimpleActionClient("/social_mpc/approach", ApproachAction)
        # wait_for_server's timeout is in ROS time, which here runs a hundred times faster than
        # the wall clock; wait on the wall clock instead.
        deadline = time.monotonic() + 60.0
        while not (self.move_base.wait_for_server(rospy.Duration(0.1))
                   and self.approach.wait_for_server(rospy.Duration(0.1))):
            if time.monotonic() > deadline:
                raise RuntimeError("social_mpc_node's actions did not come up within 60 s")
            time.sleep(0.1)
        self.tracked = []
        rospy.Subscriber("/humans/persons/tracked", IdsList, self._on_tracked, queue_size=1)
        self.walkers = []
        self.humans = []
        self.active = None
        self.goal_started = 0.0
        self.goals = {"sent": 0, "succeeded": 0, "aborted": 0, "cancelled": 0}
        self.arrivals = 0
        now = rospy.get_time()
        self.next = {"leave": now + LEAVE_EVERY_S, "regoal": now + REGOAL_EVERY_S,
                     "speak": now + SPEAK_EVERY_S}

    def _on_tracked(self, msg):
        self.tracked = list(msg.ids)

    def read_scene(self, scene_path):
        with open(scene_path) as scene:
            humans = yaml.safe_load(scene)["humans"]
        self.humans = [h["id"] for h in humans]
        self.walkers = [h["id"] for h in humans if "goal" in h]

    def _random_point(self):
        from geometry_msgs.msg import Pose2D
        return Pose2D(self.rng.uniform(1.0, self.side - 1.0), self.rng.uniform(1.0, self.side - 1.0),
                      self.rng.uniform(-math.pi, math.pi))

    def _replace_oldest_walker(self):
        from geometry_msgs.msg import Pose2D
        if self.walkers:
            leaving = self.walkers.pop(0)
            self.remove(id=leaving)
            self.humans.remove(leaving)
        for _ in range(50):  # a free spot along the west wall; the hall is crowded
            response = self.spawn(id=0, name="", role="visitor",
                                  pose=Pose2D(0.5, self.rng.uniform(1.0, self.side - 1.0), 0.0),
                                  age=self.rng.uniform(18, 90),
                                  gender=self.rng.choice(["female", "male"]),
                                  mask=self.rng.random() < 0.2,
                                  emotion=self.rng.choice(["neutral", "happy", "disturbed"]))
            if response.success:
                self.walkers.append(response.id)
                self.humans.append(response.id)
                self.set_goal(id=response.id, goal=self._random_point())
                self.arrivals += 1
                return

    def _next_ari_goal(self):
        from ari_social_sim.msg import ApproachGoal
        from move_base_msgs.msg import MoveBaseGoal
        self.goals["sent"] += 1
        if self.goals["sent"] % 3 == 0 and self.tracked:
            self.active = self.approach
            self.active.send_goal(ApproachGoal(target_type=ApproachGoal.TARGET_PERSON,
                                               target_id=self.rng.choice(self.tracked)))
        else:
            goal = MoveBaseGoal()
            goal.target_pose.header.frame_id = "map"
            point = self._random_point()
            goal.target_pose.pose.position.x = point.x
            goal.target_pose.pose.position.y = point.y
            goal.target_pose.pose.orientation.z = math.sin(point.theta / 2)
            goal.target_pose.pose.orientation.w = math.cos(point.theta / 2)
            self.active = self.move_base
            self.active.send_goal(goal)
        self.goal_started = self.rospy.get_time()

    def tick(self):
        from actionlib_msgs.msg import GoalStatus
        now = self.rospy.get_time()
        if self.active is None:
            self._next_ari_goal()
        else:
            state = self.active.get_state()
            if state == GoalStatus.SUCCEEDED:
                self.goals["succeeded"] += 1
                self._next_ari_goal()
            elif state in (GoalStatus.ABORTED, GoalStatus.REJECTED):
                self.goals["aborted"] += 1
                self._next_ari_goal()
            elif now - self.goal_started > GOAL_TIMEOUT_S:
                self.active.cancel_goal()
                self.goals["cancelled"] += 1
                self._next_ari_goal()
        if now >= self.next["leave"]:
            self._replace_oldest_walker()
            self.next["leave"] = now + LEAVE_EVERY_S
        if now >= self.next["regoal"] and self.walkers:
            for walker in self.rng.sample(self.walkers, min(5, len(self.walkers))):
                self.set_goal(id=walker, goal=self._random_point())
            self.next["regoal"] = now + REGOAL_EVERY_S
        if now >= self.next["speak"] and self.humans:
            self.say(speaker_id=self.rng.choice(self.humans), act="INFORM",
                     content=self.rng.choice(SENTENCES))
            self.next["speak"] = now + SPEAK_EVERY_S


def trend(points):
    """Least-squares line through (minute, kib) points: its value at the first and last minute."""
    n = len(points)
    mean_x = sum(x for x, _ in points) / n
    mean_y = sum(y for _, y in points) / n
    sxx = sum((x - mean_x) ** 2 for x, _ in points)
    slope = sum((x - mean_x) * (y - mean_y) for x, y in points) / sxx if sxx else 0.0
    first, last = points[0][0], points[-1][0]
    return mean_y + slope * (first - mean_x), mean_y + slope * (last - mean_x)


def flatness_table(samples, warmup, tolerance):
    """Lines of the verdict table and whether every node stayed flat. A node is flat when the
    least-squares line through its samples after the warm-up rises (or falls) by at most
    `tolerance` percent over the run: growth with the run's length shows there, while the range
    (also printed) includes what a node holds only for moments, such as social_mpc_node's 3 MB
    geodesic field of a new goal, and the moment a sample falls on."""
    lines = ["| node | RSS at minute %d (MiB) | lowest, highest after (MiB) | range | trend over "
             "the run |" % warmup, "|---|---|---|---|---|"]
    flat = True
    for node in NODES:
        points = [(minute, row[node]) for minute, row in samples
                  if minute >= warmup and row.get(node)]
        if len(points) < 2 or points[0][0] != warmup:
            lines.append("| %s | not running | | | |" % node)
            flat = False
            continue
        values = [kib for _, kib in points]
        start, end = trend(points)
        change = 100.0 * (end - start) / start
        flat = flat and abs(change) <= tolerance
        lines.append("| %s | %.1f | %.1f, %.1f | %.1f %% | %+.1f %% |"
                     % (node, values[0] / 1024, min(values) / 1024, max(values) / 1024,
                        100.0 * (max(values) - min(values)) / values[0], change))
    return lines, flat


def samples_of_report(path):
    """The (minute, {node: kib}) samples of a report this script wrote."""
    samples = []
    with open(path) as report:
        for line in report:
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) == len(NODES) + 1 and cells[0].isdigit():
                samples.append((int(cells[0]), {
                    node: float(cell) * 1024 for node, cell in zip(NODES, cells[1:])
                    if cell != "gone"}))
    return samples


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=int_in(2, 24 * 60), default=60)
    parser.add_argument("--warmup", type=int_in(1, 24 * 60), default=10)
    parser.add_argument("--humans", type=int_in(20, 1000), default=200)
    parser.add_argument("--seed", type=int_in(0, 2**31 - 1), default=1)
    parser.add_argument("--port", type=int_in(1024, 65535), default=11411)
    parser.add_argument("--tolerance", type=float, default=5.0, help="%% of spread allowed")
    parser.add_argument("--report", help="also write the tables to this Markdown file")
    parser.add_argument("--analyse", metavar="REPORT",
                        help="run nothing: print the verdict on the samples of an earlier report")
    args = parser.parse_args()
    if args.analyse:
        samples = samples_of_report(args.analyse)
        if not samples:
            parser.error("--analyse: no samples in %s" % args.analyse)
        lines, flat = flatness_table(samples, args.warmup, args.tolerance)
        print("\n".join(lines))
        return 0 if flat else 1
    if args.warmup >= args.minutes:
        parser.error("--warmup (%d) must be less than --minutes (%d)" % (args.warmup, args.minutes))
    if args.report and not os.access(os.path.dirname(os.path.abspath(args.report)), os.W_OK):
        parser.error("--report: cannot write into the folder of %s" % args.report)

    scene_dir = tempfile.mkdtemp(prefix="live_soak.")
    subprocess.run([sys.executable, os.path.join(PACKAGE, "scripts", "make_crowd_scene.py"),
                    "--humans", str(args.humans), "--seed", str(args.seed), "--ari",
                    "--out", scene_dir], check=True)
    with open(os.path.join(scene_dir, "world.yaml")) as world:
        hall = yaml.safe_load(world)
    side = hall["size"][0] + 2 * hall["origin"][0]  # the floor inside the walls

    os.environ["ROS_MASTER_URI"] = "http://localhost:%d" % args.port
    log = open(os.path.join(scene_dir, "launch.log"), "w")
    launch = subprocess.Popen(
        ["roslaunch", "-p", str(args.port), "ari_social_sim", "navigation.launch",
         "scene:=%s/scene.yaml" % scene_dir, "real_time_factor:=0", "seed:=%d" % args.seed],
        stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    interrupted = []
    for stop in (signal.SIGINT, signal.SIGTERM):  # either way, the launch is stopped below
        signal.signal(stop, lambda *_: interrupted.append(True))
    samples = []
    try:
        import rospy
        time.sleep(5.0)
        rospy.init_node("live_soak", disable_signals=True)
        driver = Driver(side, args.seed)
        driver.read_scene(os.path.join(scene_dir, "scene.yaml"))
        start = time.monotonic()
        sim_start = rospy.get_time()
        header = "minute  sim_s    " + "  ".join("%14s" % n[:14] for n in NODES) + \
            "   goals(sent/ok/abort/cancel)  arrivals"
        print("live soak: %d people, %d minutes, nodes' RSS in MiB (launch log: %s)"
              % (args.humans, args.minutes, log.name))
        print(header, flush=True)
        next_sample = start
        minute = 0
        while minute <= args.minutes and not interrupted:
            if time.monotonic() >= next_sample:
                pids = node_pids(launch.pid)
                row = {node: rss_kib(pid) for node, pid in pids.items()}
                samples.append((minute, row))
                print("%6d %7.0f    " % (minute, rospy.get_time() - sim_start)
                      + "  ".join("%14s" % ("%.1f" % (row[n] / 1024) if row.get(n) else "gone")
                                  for n in NODES)
                      + "   %5d/%d/%d/%d %18d" % (driver.goals["sent"], driver.goals["succeeded"],
                                                  driver.goals["aborted"],
                                                  driver.goals["cancelled"], driver.arrivals),
                      flush=True)
                minute += 1
                next_sample = start + 60.0 * minute
            if launch.poll() is not None:
                print("live soak: roslaunch exited with %d; see %s" % (launch.returncode, log.name))
                return 1
            driver.tick()
            time.sleep(0.02)
    finally:
        os.killpg(launch.pid, signal.SIGINT)
        try:
            launch.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(launch.pid, signal.SIGKILL)
    if interrupted:
        print("live soak: interrupted after %d minutes; no verdict" % (len(samples) - 1))
        return 130
    lines, flat = flatness_table(samples, args.warmup, args.tolerance)
    print("\n".join(lines))
    print("live soak: every node's RSS %s flat within %.1f %% after minute %d"
          % ("stayed" if flat else "did NOT stay", args.tolerance, args.warmup))
    if args.report:
        with open(args.report, "w") as report:
            report.write("| minute | " + " | ".join(NODES) + " |\n|" + "---|" * (len(NODES) + 1)
                         + "\n")
            for minute, row in samples:
                report.write("| %d | " % minute + " | ".join(
                    "%.1f" % (row[n] / 1024) if row.get(n) else "gone" for n in NODES) + " |\n")
            report.write("\n" + "\n".join(lines) + "\n")
    return 0 if flat else 1


if __name__ == "__main__":
    sys.exit(main())
