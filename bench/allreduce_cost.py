#!/usr/bin/python3
"""Cost of one gradient all-reduce between 2 ranks on this machine (gloo over loopback), the
size of train_join_group.py's network (--hidden 128): what training on 2 ranks pays per
minibatch (docs/cluster.md, "Training"). Run: bench/allreduce_cost.py [--hidden 128]."""
import argparse
import os
import time

try:
    import torch
    import torch.distributed as dist
    import torch.multiprocessing as mp
except ImportError:
    raise SystemExit("allreduce_cost: PyTorch is missing; run scripts/install_extras.sh (as root)")

OBSERVATIONS, ACTIONS, CALLS = 323, 3, 2000  # join_group's observation and action sizes


def parameters(hidden):
    actor = OBSERVATIONS * hidden + hidden + hidden * hidden + hidden + hidden * ACTIONS + ACTIONS
    critic = OBSERVATIONS * hidden + hidden + hidden * hidden + hidden + hidden + 1
    return actor + critic + ACTIONS


def rank_main(rank, size, count, results):
    os.environ.update(MASTER_ADDR="127.0.0.1", MASTER_PORT="29533")
    dist.init_process_group("gloo", rank=rank, world_size=size)
    torch.set_num_threads(1)
    flat = torch.ones(count)
    for _ in range(100):  # connections up, caches warm
        dist.all_reduce(flat)
    dist.barrier()
    started = time.perf_counter()
    for _ in range(CALLS):
        dist.all_reduce(flat)
    if rank == 0:
        results.put((time.perf_counter() - started) / CALLS)
    dist.destroy_process_group()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--hidden", type=int, default=128)
    count = parameters(parser.parse_args().hidden)
    results = mp.get_context("spawn").SimpleQueue()
    mp.spawn(rank_main, args=(2, count, results), nprocs=2)
    print("all-reduce of %d floats between 2 ranks: %.3f ms" % (count, 1000 * results.get()))


if __name__ == "__main__":
    main()
