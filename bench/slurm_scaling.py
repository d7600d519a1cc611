#!/usr/bin/python3
"""Throughput of a batch plan on a SLURM cluster with 1 and with 2 tasks at once
(docs/cluster.md, "Scaling"; docs/PERFORMANCE.md, "Cluster").

    bench/slurm_scaling.py [--episodes 120] [--scenario join_group] [--work DIR]

Starts a cluster of this host (scripts/slurm_cluster.sh), submits the same run_episodes plan as
1 shard and as 2 shards (scripts/slurm_batch.py), waits for each merge, and prints episodes per
minute over the array (first task's start to last task's end), the ratio of the two, the merge's
wall time, and the time from submission to the merged output. Needs the package's setup.bash
sourced and root (the cluster's daemons)."""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

SCRIPTS = Path(__file__).resolve().parents[1] / "scripts"


def run_plan(env, out, shards, scenario, episodes):
    started = time.monotonic()
    subprocess.run([sys.executable, str(SCRIPTS / "slurm_batch.py"), "submit", "--shards",
                    str(shards), "--out", str(out), "--", "run_episodes", "--scenario", scenario,
                    "--episodes", str(episodes), "--seed", "1"], env=env, check=True,
                   capture_output=True)
    merged = out / "slurm" / "merged.json"
    while not merged.exists():
        jobs = subprocess.run(["squeue", "-h"], env=env, capture_output=True, text=True).stdout
        if not jobs.strip() and not merged.exists():
            sys.exit("slurm_scaling: the plan in %s ended without a merge: see its slurm/logs"
                     % out)
        time.sleep(0.2)
    report = json.loads(merged.read_text())
    report["submission_to_output_s"] = time.monotonic() - started
    return report


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--episodes", type=int, default=120)
    parser.add_argument("--scenario", default="join_group")
    parser.add_argument("--work", default=None, help="folder for the cluster and the outputs")
    args = parser.parse_args()
    work = Path(args.work or tempfile.mkdtemp(prefix="slurm_scaling_"))
    cluster = work / "cluster"
    subprocess.run(["bash", str(SCRIPTS / "slurm_cluster.sh"), "start", str(cluster), "18817"],
                   check=True, capture_output=True)
    env = dict(os.environ, SLURM_CONF=str(cluster / "slurm.conf"))
    try:
        reports = {shards: run_plan(env, work / ("shards%d" % shards), shards, args.scenario,
                                    args.episodes) for shards in (1, 2)}
    finally:
        subprocess.run(["bash", str(SCRIPTS / "slurm_cluster.sh"), "stop", str(cluster)])
    for shards, r in reports.items():
        print("%d task(s): %.1f episodes per minute over the array (%d episodes in %.1f s), "
              "merge %.2f s, submission to merged output %.1f s" % (
                  shards, r["episodes_per_minute"], r["episodes"], r["array_wall_s"],
                  r["merge_wall_s"], r["submission_to_output_s"]))
    print("2 tasks / 1 task: %.2f" % (reports[2]["episodes_per_minute"] /
                                      reports[1]["episodes_per_minute"]))


if __name__ == "__main__":
    main()
