"""Batch plans on a real SLURM cluster of one host (scripts/slurm_cluster.sh: Debian's munge,
slurmctld and slurmd on ports of their own, state in a temporary folder, stopped at the end),
submitted with scripts/slurm_batch.py (docs/cluster.md):
  - a run_episodes plan as 4 shards and the merge: the CSV, its settings and every bag
    byte-identical to one process running the plan;
  - an export_dataset plan as 3 shards and the merge: annotations.json and every PNG the same;
  - a dialogue_corpus plan as 3 shards and the merge: the corpus the same;
  - a nav_benchmark plan as 2 shards and the merge: the CSV the same but for the solve times;
  - a shard cancelled with scancel mid-run and another killed with SIGKILL: the merge does not
    run, the plan's folder holds no partial file (not even the killed task's: its bag had no
    name), and the plan resubmitted with --resume runs those two shards only and merges to the same bytes;
  - bad plans refused before anything is submitted.
The tools come from the build this test belongs to (ARI_DEVEL_DIR)."""
import csv
import io
import json
import os
import subprocess
import sys
import time
from pathlib import Path

from conftest import DEVEL, HANG_GUARD_S, SCRIPTS

TOOLS = DEVEL / "lib" / "ari_social_sim"


def batch(env, *args):
    return subprocess.run([sys.executable, str(SCRIPTS / "slurm_batch.py")] + list(args),
                          env=env, capture_output=True, text=True)


def submitted(env, out, shards, plan, *options):
    result = batch(env, "submit", "--shards", str(shards), "--out", str(out), *options, "--", *plan)
    assert result.returncode == 0, result.stderr
    return json.loads((out / "slurm" / "jobs.json").read_text())[-1]


def queued(env, job_ids):
    listed = subprocess.run(["squeue", "-h", "-o", "%i", "-j", ",".join(job_ids)], env=env,
                            capture_output=True, text=True).stdout.split()
    return [job for job in listed if job.split("_")[0] in job_ids]


def wait_for_jobs(env, jobs):
    ids = [jobs[key] for key in ("array", "merge") if jobs.get(key)]
    limit = time.monotonic() + HANG_GUARD_S
    while queued(env, ids):
        assert time.monotonic() < limit, "jobs %s still queued" % ids
        time.sleep(0.5)


def one_process(tool, args, out):
    result = subprocess.run([str(TOOLS / tool)] + args + ["--out", str(out)],
                            capture_output=True, text=True)
    # run_episodes exits 1 when an episode failed (waiting_room's seed 7): its output is whole.
    assert result.returncode in (0, 1), result.stderr


def files_of(folder):
    """Every file under `folder` but the plan's own (slurm/), by relative path, with its bytes."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*"))
            if p.is_file() and p.relative_to(folder).parts[0] != "slurm"}


def expect_same_files(merged, whole):
    got, expected = files_of(merged), files_of(whole)
    assert sorted(got) == sorted(expected)
    different = [name for name in expected if got[name] != expected[name]]
    assert not different, "differ from one process: %s" % different
    return len(expected)


def test_run_episodes_shards_merge_into_the_bytes_of_one_process(cluster, tmp_path):
    plan = ["run_episodes", "--scenario", "join_group", "--episodes", "8", "--seed", "2"]
    jobs = submitted(cluster, tmp_path / "array", 4, plan)
    assert jobs["shards"] == [1, 2, 3, 4]
    one_process(plan[0], plan[1:], tmp_path / "whole")
    wait_for_jobs(cluster, jobs)
    files = expect_same_files(tmp_path / "array", tmp_path / "whole")
    assert files == 10  # the CSV, its settings and 8 bags
    report = json.loads((tmp_path / "array" / "slurm" / "merged.json").read_text())
    assert report["episodes"] == 8 and report["episodes_per_minute"] > 0
    status = batch(cluster, "status", "--out", str(tmp_path / "array"))
    assert "merged; 4 of 4 shards done, 8 of 8 episodes" in status.stdout, status.stdout


def test_export_dataset_shards_merge_into_the_bytes_of_one_process(cluster, tmp_path):
    plan = ["export_dataset", "--scenario", "join_group", "--episodes", "3", "--seed", "2",
            "--cameras", "head", "--every", "4"]
    jobs = submitted(cluster, tmp_path / "array", 3, plan)
    one_process(plan[0], plan[1:], tmp_path / "whole")
    wait_for_jobs(cluster, jobs)
    files = expect_same_files(tmp_path / "array", tmp_path / "whole")
    assert files > 4  # annotations.json and the PNGs of 3 episodes


def test_dialogue_corpus_shards_merge_into_the_bytes_of_one_process(cluster, tmp_path):
    plan = ["dialogue_corpus", "--dialogues", "12", "--seed", "3"]
    jobs = submitted(cluster, tmp_path / "array", 3, plan)
    (tmp_path / "whole").mkdir()
    one_process(plan[0], plan[1:], tmp_path / "whole" / "corpus.jsonl")
    wait_for_jobs(cluster, jobs)
    assert expect_same_files(tmp_path / "array", tmp_path / "whole") == 1
    refused = batch(cluster, "submit", "--shards", "3", "--out", str(tmp_path / "other"), "--",
                    *plan, "--compare")
    assert refused.returncode == 2 and "--compare: not for a job array" in refused.stderr


def without_solve_times(csv_text):
    """nav_benchmark's CSV without its two solve-time columns: CPU times, never the same twice."""
    return [row[:19] + row[21:] for row in csv.reader(io.StringIO(csv_text))]


def test_nav_benchmark_shards_merge_into_what_one_process_writes(cluster, tmp_path):
    plan = ["nav_benchmark", "--episodes", "4", "--types", "pose,approach", "--controllers",
            "social,baseline"]
    jobs = submitted(cluster, tmp_path / "array", 2, plan)
    whole = tmp_path / "whole.csv"
    subprocess.run([str(TOOLS / plan[0])] + plan[1:] + ["--csv", str(whole)], check=True,
                   capture_output=True)
    wait_for_jobs(cluster, jobs)
    merged = (tmp_path / "array" / "nav.csv").read_text()
    assert len(merged.splitlines()) == 1 + 16  # 4 episodes of 2 types with 2 controllers
    assert without_solve_times(merged) == without_solve_times(whole.read_text())
    # The shards' records were merged and removed.
    assert sorted(p.name for p in (tmp_path / "array").iterdir()) == ["nav.csv", "slurm"]


def rows_in(stage):
    return sum(max(0, table.read_text().count("\n") - 1) for table in stage.glob("*.csv"))


def wait_for_rows(stage, rows):
    limit = time.monotonic() + HANG_GUARD_S
    while not stage.is_dir() or rows_in(stage) < rows:
        assert time.monotonic() < limit, "%s never reached %d rows" % (stage, rows)
        time.sleep(0.05)


def test_cancelled_and_killed_shards_run_again_alone_and_merge_the_same(cluster, tmp_path):
    # waiting_room episodes take about a second: a shard of four is stopped between its first
    # and its last.
    plan = ["run_episodes", "--scenario", "waiting_room", "--episodes", "12", "--seed", "1"]
    out = tmp_path / "array"
    first = submitted(cluster, out, 3, plan)
    stage = out / "slurm" / "stage"
    wait_for_rows(stage / "shard2", 1)
    subprocess.run(["scancel", "%s_2" % first["array"]], env=cluster, check=True)
    wait_for_rows(stage / "shard3", 1)
    subprocess.run(["scancel", "--full", "--signal=KILL", "%s_3" % first["array"]], env=cluster,
                   check=True)
    wait_for_jobs(cluster, first)
    assert not (out / "slurm" / "merged.json").exists()  # the merge never ran
    # Even the killed task's episode under way left nothing: its bag had no name yet.
    partial = [str(p.relative_to(out)) for p in out.rglob("*")
               if p.name.endswith((".active", ".part"))]
    assert not partial, partial
    assert not list(out.glob("*.csv")) and not list(out.glob("*.bag"))

    again = submitted(cluster, out, 3, plan, "--resume")
    assert again["shards"] == [2, 3]  # shard 1 is done and not run again
    one_process(plan[0], plan[1:], tmp_path / "whole")
    wait_for_jobs(cluster, again)
    expect_same_files(out, tmp_path / "whole")
    assert not [p for p in out.rglob("*") if p.name.endswith((".active", ".part"))]


def test_bad_plans_are_refused_before_anything_is_submitted(cluster, tmp_path):
    plan = ["--", "run_episodes", "--scenario", "join_group", "--episodes", "8"]
    out = str(tmp_path / "plan")
    cases = [
        (["--shards", "3", "--out", out] + plan, "--shards 3: expected a count that divides"),
        (["--shards", "4", "--partition", "nowhere", "--out", out] + plan,
         "--partition: expected one of the cluster's partitions (debug), got 'nowhere'"),
        (["--shards", "4", "--cpus-per-task", "999", "--out", out] + plan,
         "--cpus-per-task"),
        (["--shards", "4", "--out", out, "--", "run_episodes", "--scenario", "join_group"],
         "--episodes: expected the plan's count"),
        (["--shards", "4", "--out", out] + plan + ["--out", "elsewhere"],
         "--out: set by slurm_batch.py"),
        (["--shards", "4", "--out", out, "--", "render_cameras", "--episodes", "8"],
         "expected the tool after --"),
    ]
    for args, message in cases:
        result = batch(cluster, "submit", *args)
        assert result.returncode == 2 and message in result.stderr, (args, result.stderr)
    assert not Path(out).exists()  # nothing written, nothing submitted
    # A plan's folder is not taken twice without --resume or --overwrite.
    submitted(cluster, Path(out), 4, plan[1:])
    refused = batch(cluster, "submit", "--shards", "4", "--out", out, *plan)
    assert refused.returncode == 2 and "holds a plan already" in refused.stderr
    other = batch(cluster, "submit", "--shards", "2", "--resume", "--out", out, *plan)
    assert other.returncode == 2 and "shards: 4 there, 2 now" in other.stderr, other.stderr
