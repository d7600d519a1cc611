"""Training on several processes in the manner of DD-PPO (docs/cluster.md, "Training"): each rank
steps its own environments, gradients are averaged over the ranks with torch.distributed (gloo),
rank 0 writes checkpoints, and a run told it will be preempted checkpoints and asks SLURM to
requeue it. Used by train_join_group.py; one rank (no SLURM, no torchrun) needs nothing of it.
"""
import hashlib
import os
import signal
import subprocess

import sys

import numpy as np

try:
    import torch
    import torch.distributed as dist
except ImportError:
    sys.exit("training_ranks: PyTorch is missing; run scripts/install_extras.sh (as root)")

# The signals a scheduler sends before it stops a task: SLURM's --signal (USR1 by convention)
# and the SIGTERM of scancel and of a time limit.
PREEMPTION_SIGNALS = (signal.SIGUSR1, signal.SIGTERM)


def first_host(nodelist):
    """The first host of a SLURM node list, as `scontrol show hostnames` expands it."""
    hosts = subprocess.run(["scontrol", "show", "hostnames", nodelist], capture_output=True,
                           text=True, check=True).stdout.split()
    return hosts[0]


class Ranks:
    """This process's place among the training processes, from srun's or torchrun's variables."""

    def __init__(self):
        env = os.environ
        if "SLURM_PROCID" in env and int(env.get("SLURM_NTASKS", "1")) > 1:
            self.rank, self.size = int(env["SLURM_PROCID"]), int(env["SLURM_NTASKS"])
            env.setdefault("MASTER_ADDR", first_host(env["SLURM_JOB_NODELIST"]))
            # A port per job, so that two jobs on one node do not meet.
            env.setdefault("MASTER_PORT", str(20000 + int(env.get("SLURM_JOB_ID", "0")) % 20000))
        else:
            self.rank, self.size = int(env.get("RANK", "0")), int(env.get("WORLD_SIZE", "1"))
        if self.size > 1:
            dist.init_process_group("gloo", rank=self.rank, world_size=self.size)
        self.preempted = False
        for signum in PREEMPTION_SIGNALS:
            signal.signal(signum, self._on_preemption)

    def _on_preemption(self, _signum, _frame):
        self.preempted = True

    @property
    def main(self):
        return self.rank == 0

    def broadcast_parameters(self, model):
        """Every rank starts from rank 0's parameters."""
        if self.size > 1:
            for parameter in model.parameters():
                dist.broadcast(parameter.data, src=0)

    def average_gradients(self, model):
        """Each gradient replaced by its mean over the ranks: the same on every rank, bit for bit
        (gloo's all-reduce gives every rank the same sum)."""
        if self.size > 1:
            # One all-reduce of every gradient together: each call costs a round trip.
            gradients = [p.grad for p in model.parameters() if p.grad is not None]
            flat = torch.cat([g.reshape(-1) for g in gradients])
            dist.all_reduce(flat, op=dist.ReduceOp.SUM)
            flat /= self.size
            offset = 0
            for gradient in gradients:
                gradient.copy_(flat[offset:offset + gradient.numel()].view_as(gradient))
                offset += gradient.numel()

    def sum(self, array):
        """`array` (float64) summed over the ranks."""
        tensor = torch.from_numpy(np.ascontiguousarray(array, dtype=np.float64))
        if self.size > 1:
            dist.all_reduce(tensor, op=dist.ReduceOp.SUM)
        return tensor.numpy()

    def any_preempted(self):
        """Whether any rank was told it will be preempted: all stop at the same update."""
        return bool(self.sum(np.array([1.0 if self.preempted else 0.0]))[0] > 0)

    def gather(self, value):
        """`value` of every rank, in rank order (all ranks get the list)."""
        if self.size == 1:
            return [value]
        values = [None] * self.size
        dist.all_gather_object(values, value)
        return values

    def barrier(self):
        if self.size > 1:
            dist.barrier()


def parameter_hash(model):
    """SHA-256 of the parameters' bytes: equal hashes, equal parameters."""
    digest = hashlib.sha256()
    for parameter in model.parameters():
        digest.update(parameter.detach().numpy().tobytes())
    return digest.hexdigest()


def save_atomically(state, path):
    """torch.save to a temporary name, then renamed: a checkpoint is whole or absent."""
    temporary = path + ".part"
    torch.save(state, temporary)
    os.replace(temporary, path)


def requeue():
    """Asks SLURM to requeue this job (it restarts the job script, which resumes from the
    checkpoint); False outside SLURM."""
    job = os.environ.get("SLURM_JOB_ID")
    if not job:
        return False
    subprocess.run(["scontrol", "requeue", job], check=False)
    return True
