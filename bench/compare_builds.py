#!/usr/bin/python3
"""Compares the benchmarks of two builds of the package, e.g. before and after a change.

Runs each benchmark program of both builds in turn, ROUNDS times (old, new, old, new, ...), so
that whatever else the machine does falls on both alike, pinned to one core, and prints per
benchmark the median CPU time per iteration of each build and the ratio new / old. Exits 1 when a
ratio is beyond --tolerance percent slower. Episode benchmarks (those reporting real_time_factor)
also get a row "... per sim s": CPU time per simulated second, which stays comparable when a
change makes the episodes longer or shorter, and are judged by it.

Usage:
  old=$(mktemp -d) && git worktree add "$old" REV
  (cd "$old" && bash scripts/build.sh --target benchmarks)
  bench/compare_builds.py "$old/_build/bench" _build/bench \\
      [--programs bench_world,bench_perception,bench_navigation,bench_scenario] \\
      [--filter REGEX] [--rounds 3] [--cpu 0] [--tolerance 5]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys

PROGRAMS = "bench_world,bench_perception,bench_navigation,bench_scenario"


def run(program, cpu, benchmark_filter):
    """{benchmark name: CPU time per iteration (ns)} of one run of `program`."""
    command = ["taskset", "-c", str(cpu), program, "--benchmark_format=json"]
    if benchmark_filter:
        command.append("--benchmark_filter=" + benchmark_filter)
    printed = subprocess.run(command, check=True, stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, text=True).stdout
    times = {}
    for entry in json.loads(printed)["benchmarks"]:
        scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[entry["time_unit"]]
        times[entry["name"]] = entry["cpu_time"] * scale
        # An episode benchmark runs seeds 1, 2, ... until its time is up: when a change alters
        # what the episodes do (their length, their number), the time per episode compares
        # different work. Its time per simulated second (1 / real_time_factor) compares the same.
        if "real_time_factor" in entry:
            times[entry["name"] + " per sim s"] = 1e9 / entry["real_time_factor"]
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("old", help="the old build's bench folder")
    parser.add_argument("new", help="the new build's bench folder")
    parser.add_argument("--programs", default=PROGRAMS)
    parser.add_argument("--filter", default="")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--cpu", type=int, default=0)
    parser.add_argument("--tolerance", type=float, default=5.0)
    args = parser.parse_args()
    if not 1 <= args.rounds <= 100:
        parser.error("--rounds: expected 1 to 100, got %d" % args.rounds)
    for folder in (args.old, args.new):
        if not os.path.isdir(folder):
            parser.error("%s: not a folder" % folder)
    slower = []
    print("| benchmark | old (us) | new (us) | new / old |")
    print("|---|---:|---:|---:|")
    for program in args.programs.split(","):
        samples = {"old": {}, "new": {}}
        for _ in range(args.rounds):
            for build, folder in (("old", args.old), ("new", args.new)):
                for name, ns in run(os.path.join(folder, program), args.cpu, args.filter).items():
                    samples[build].setdefault(name, []).append(ns)
        for name in samples["new"]:
            if name not in samples["old"]:
                continue
            old = statistics.median(samples["old"][name])
            new = statistics.median(samples["new"][name])
            ratio = new / old
            print("| %s | %.1f | %.1f | %.3f |" % (name, old / 1e3, new / 1e3, ratio), flush=True)
            # An episode benchmark is judged by its time per simulated second.
            judged = name + " per sim s" not in samples["new"]
            if judged and ratio > 1.0 + args.tolerance / 100.0:
                slower.append(name)
    if slower:
        print("slower than old by more than %g %%: %s" % (args.tolerance, ", ".join(slower)))
    sys.exit(1 if slower else 0)


if __name__ == "__main__":
    main()
