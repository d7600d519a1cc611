#!/usr/bin/python3
"""Live launches against run_episodes on the same scenarios and seeds (docs/scenario.md, "Live and
batch agree").

For each scenario and each of N seeds, plays the scenario twice: live, with its launch file
(`roslaunch ari_social_sim NAME.launch seed:=S real_time_factor:=R`: every node, scenario_node
printing the outcome), and in batch, with `run_episodes --scenario NAME --episodes N --seed S0
--no-bags` (episode i has seed S0 + i). It then compares, per scenario, the share of successful
episodes and the median duration of the successful ones (sim-s from the script's start to its end).
Live runs are not bit-for-bit the batch run of their seed (nodes run on their own timers and the
transport interleaves messages differently), so the runs agree when the success rates are within
--rate-points percentage points and the median durations within --duration-percent percent.
Exits 1 if a scenario disagrees.

Usage (after a build, with the package sourced):
  bench/live_vs_batch.py [--seeds 20] [--scenarios corridor,join_group,...] [--rtf 2]
                         [--port 11511] [--report FILE.json]
  bench/live_vs_batch.py --analyse FILE.json   # the verdict of a saved run
"""
import argparse
import csv
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE = os.path.dirname(HERE)
SCENARIOS = ["corridor", "group_discussion", "join_group", "waiting_room"]
OUTCOME = re.compile(r"^outcome: (success|failure) after ([0-9.]+) s")


def positive_int(text):
    value = int(text)
    if not 1 <= value <= 1000:
        raise argparse.ArgumentTypeError("expected 1 to 1000, got %d" % value)
    return value


def scenario_file(name):
    return os.path.join(PACKAGE, "scenarios", name + ".yaml")


def first_seed_and_limit(name):
    """The scenario file's seed (run_episodes' default first seed) and its sim-time limit (s)."""
    with open(scenario_file(name)) as text:
        scenario = yaml.safe_load(text)
    return int(scenario["seed"]), float(scenario["script"]["time_limit"])


def batch_runs(name, seeds, first_seed):
    """{seed: (success, duration_s)} of run_episodes' episodes."""
    with tempfile.TemporaryDirectory(prefix="live_vs_batch.") as out:
        run = subprocess.run(["rosrun", "ari_social_sim", "run_episodes", "--scenario", name,
                              "--episodes", str(seeds), "--seed", str(first_seed), "--no-bags",
                              "--out", out], stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, text=True)
        # 1: every episode ran and some failed, which the comparison counts; anything else is
        # an error.
        if run.returncode not in (0, 1):
            raise RuntimeError("run_episodes exited with %d: %s" % (run.returncode, run.stderr))
        with open(os.path.join(out, name + ".csv")) as table:
            return {int(row["seed"]): (row["success"] == "1", float(row["duration_s"]))
                    for row in csv.DictReader(table)}


def live_run(name, seed, rtf, port, wall_limit_s):
    """(success, duration_s) that scenario_node printed, or (False, None) when it printed no
    outcome within wall_limit_s."""
    env = dict(os.environ, ROS_MASTER_URI="http://localhost:%d" % port)
    with tempfile.TemporaryDirectory(prefix="live_vs_batch.log.") as logs:
        env["ROS_LOG_DIR"] = logs
        try:
            printed = subprocess.run(
                ["roslaunch", "-p", str(port), "ari_social_sim", name + ".launch",
                 "seed:=%d" % seed, "real_time_factor:=%g" % rtf],
                env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                timeout=wall_limit_s).stdout
        except subprocess.TimeoutExpired as expired:
            printed = expired.stdout or ""
            if isinstance(printed, bytes):
                printed = printed.decode(errors="replace")
    for line in printed.splitlines():
        match = OUTCOME.match(line.strip())
        if match:
            return match.group(1) == "success", float(match.group(2))
    return False, None


def summary(runs):
    """Success rate (%) and the median duration of the successful runs."""
    durations = [d for ok, d in runs if ok]
    rate = 100.0 * len(durations) / len(runs)
    return rate, statistics.median(durations) if durations else None


def judge(report, rate_points, duration_percent):
    print("| scenario | seeds | success live | success batch | median live (s) | median batch (s) "
          "| duration difference | agree |")
    print("|---|---:|---:|---:|---:|---:|---:|---|")
    all_agree = True
    for name, runs in report["scenarios"].items():
        live = [tuple(r) for r in runs["live"]]
        batch = [tuple(r) for r in runs["batch"]]
        live_rate, live_median = summary(live)
        batch_rate, batch_median = summary(batch)
        rate_ok = abs(live_rate - batch_rate) <= rate_points
        if live_median is None or batch_median is None:
            duration_text, duration_ok = "n/a", live_median == batch_median
        else:
            difference = 100.0 * (live_median - batch_median) / batch_median
            duration_text, duration_ok = "%+.1f %%" % difference, abs(difference) <= duration_percent
        agree = rate_ok and duration_ok
        all_agree &= agree
        median = lambda m: "n/a" if m is None else "%.2f" % m
        print("| %s | %d | %.0f %% | %.0f %% | %s | %s | %s | %s |" % (
            name, len(live), live_rate, batch_rate, median(live_median), median(batch_median),
            duration_text, "yes" if agree else "NO"))
    print("settings: %s" % json.dumps(report["settings"]))
    return all_agree


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seeds", type=positive_int, default=20)
    parser.add_argument("--scenarios", default=",".join(SCENARIOS))
    parser.add_argument("--rtf", type=float, default=2.0,
                        help="live runs' real-time factor (0 < R <= 10)")
    parser.add_argument("--port", type=int, default=11511)
    parser.add_argument("--report", help="write every run's outcome to this JSON file")
    parser.add_argument("--analyse", help="judge a saved report instead of running")
    parser.add_argument("--rate-points", type=float, default=10.0)
    parser.add_argument("--duration-percent", type=float, default=10.0)
    args = parser.parse_args()
    if args.analyse:
        with open(args.analyse) as saved:
            sys.exit(0 if judge(json.load(saved), args.rate_points, args.duration_percent) else 1)
    if not 0.0 < args.rtf <= 10.0:
        parser.error("--rtf: expected 0 < R <= 10, got %g" % args.rtf)
    names = args.scenarios.split(",")
    for name in names:
        if name not in SCENARIOS:
            parser.error("--scenarios: unknown scenario %r (expected some of %s)"
                         % (name, ",".join(SCENARIOS)))
    report = {"settings": {"seeds": args.seeds, "rtf": args.rtf}, "scenarios": {}}
    for name in names:
        first_seed, limit_s = first_seed_and_limit(name)
        batch = batch_runs(name, args.seeds, first_seed)
        live = {}
        for seed in range(first_seed, first_seed + args.seeds):
            started = time.time()
            live[seed] = live_run(name, seed, args.rtf, args.port, limit_s / args.rtf + 120.0)
            print("%s seed %d: live %s, batch %s (%.0f s wall)" % (
                name, seed, live[seed], batch[seed], time.time() - started), flush=True)
        seeds = sorted(batch)
        report["scenarios"][name] = {"seeds": seeds,
                                     "live": [live[s] for s in seeds],
                                     "batch": [batch[s] for s in seeds]}
        if args.report:
            with open(args.report, "w") as out:
                json.dump(report, out, indent=1)
    sys.exit(0 if judge(report, args.rate_points, args.duration_percent) else 1)


if __name__ == "__main__":
    main()
