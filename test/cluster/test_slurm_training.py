"""Training on 2 ranks under srun on the one-host SLURM cluster (conftest.py), in the manner of
DD-PPO (scripts/train_join_group.py with scripts/training_ranks.py; docs/cluster.md, "Training"):
  - both ranks hold the same parameters after every update (each rank writes their hash);
  - the same seed gives the same parameters on a rerun;
  - a run told it will be preempted (SIGUSR1 to its tasks) checkpoints at the next segment,
    requeues itself, resumes, and ends with the parameters of an uninterrupted run, update by
    update.
PyTorch is an optional extra (scripts/install_extras.sh): without it these are skipped."""
import subprocess
import sys
import time

import pytest

from conftest import HANG_GUARD_S, SCRIPTS

pytest.importorskip("torch", reason="PyTorch is an optional extra: scripts/install_extras.sh")

UPDATES = 6
# The preempted run is long enough (30 updates of 4 x 128 steps, about 10 s on this machine) for
# the signal, sent once its first update is written, to arrive before its last segment: six short
# updates were all done before scancel's signal reached them on a loaded machine (a CI run).
PREEMPTED_UPDATES = 30


def train_command(updates, rollout):
    return [sys.executable, str(SCRIPTS / "train_join_group.py"), "--updates", str(updates),
            "--envs", "4", "--rollout", str(rollout), "--minibatch", "64", "--eval-seeds", "2",
            "--segment", "2", "--param-hashes"]


def train_job(env, out, updates=UPDATES, rollout=32):
    """Submits the training on 2 ranks; its job id."""
    out.mkdir(parents=True, exist_ok=True)
    command = " ".join(["srun"] + train_command(updates, rollout) + ["--out", str(out)])
    return subprocess.run(["sbatch", "--parsable", "--ntasks", "2", "--output",
                           str(out / "job.out"), "--open-mode", "append", "--wrap", command],
                          env=env, check=True, capture_output=True, text=True).stdout.strip()


def state_of(env, job):
    """The job's state; "" once it has ended; "unknown" while squeue cannot say (slurmctld busy
    requeueing it, say)."""
    listed = subprocess.run(["squeue", "-h", "-j", job, "-o", "%T"], env=env, capture_output=True,
                            text=True)
    return listed.stdout.strip() if listed.returncode == 0 else "unknown"


def wait_until(condition, what):
    limit = time.monotonic() + HANG_GUARD_S
    while not condition():
        assert time.monotonic() < limit, what
        time.sleep(0.2)


def hashes(out, rank):
    path = out / ("param_hashes_rank%d.txt" % rank)
    return path.read_text().split("\n")[:-1] if path.exists() else []


def finished_run(env, out, **run):
    job = train_job(env, out, **run)
    wait_until(lambda: not state_of(env, job), "training job %s never ended" % job)
    return hashes(out, 0), hashes(out, 1)


def test_two_ranks_hold_the_same_parameters_and_a_rerun_gives_them_again(cluster, tmp_path):
    rank0, rank1 = finished_run(cluster, tmp_path / "first")
    assert len(rank0) == UPDATES, (tmp_path / "first" / "job.out").read_text()
    assert rank0 == rank1  # after every update
    assert len(set(line.split()[1] for line in rank0)) == UPDATES  # and they did change
    again, _ = finished_run(cluster, tmp_path / "again")
    assert again == rank0


def test_a_preempted_run_resumes_to_the_parameters_of_an_uninterrupted_one(cluster, tmp_path):
    out = tmp_path / "preempted"
    run = {"updates": PREEMPTED_UPDATES, "rollout": 128}
    job = train_job(cluster, out, **run)
    wait_until(lambda: len(hashes(out, 0)) >= 1 or not state_of(cluster, job),
               "the first update never came")
    assert hashes(out, 0), (out / "job.out").read_text()
    # What SLURM's --signal=USR1@T sends before preempting a job: to its tasks, not the shell.
    subprocess.run(["scancel", "--signal=USR1", job], env=cluster, check=True)
    wait_until(lambda: "requeued" in (out / "job.out").read_text() or not state_of(cluster, job),
               "the run neither requeued nor ended")
    assert "requeued" in (out / "job.out").read_text(), (
        "the run ended without requeueing: the signal came after its last segment had begun\n" +
        (out / "job.out").read_text())
    # SLURM holds a requeued job for two minutes; let it start in a few seconds instead (a
    # restart within the second of the requeue is refused: "Job credential revoked").
    wait_until(lambda: state_of(cluster, job) == "PENDING", "the job was not requeued")
    subprocess.run(["scontrol", "update", "JobId=%s" % job, "StartTime=now+3"], env=cluster,
                   check=True)
    wait_until(lambda: not state_of(cluster, job), "the requeued job never ended")
    log = (out / "job.out").read_text()
    assert "preempted: checkpoint at update" in log and "resumed from" in log, log
    uninterrupted, _ = finished_run(cluster, tmp_path / "uninterrupted", **run)
    assert len(uninterrupted) == PREEMPTED_UPDATES
    assert hashes(out, 0) == uninterrupted
    assert hashes(out, 1) == uninterrupted
