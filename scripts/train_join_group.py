#!/usr/bin/env python3
"""Trains a join-group policy with PPO on ari_social_sim.learning (docs/learning.md).

Needs PyTorch and matplotlib, which the main set-up leaves out: run scripts/install_extras.sh
once (as root). Then, with the workspace sourced:

    scripts/train_join_group.py --minutes 30 --out train_out

Every --eval-every steps the deterministic policy (the mean action) plays the held-out seeds
(1,000,000 and up, never trained on); the run prints progress, saves a checkpoint
(checkpoint_<steps>.pt) and the policy for deployment (policy.yaml, read by social_mpc_node's
controller: policy), and plots the learning curve to curve.png. At the end it compares the final
policy with the random policy on the held-out seeds and writes summary.json.

Under srun (or torchrun) it trains on every task as one rank of a DD-PPO-like run, checkpoints
and requeues itself when told it will be preempted, and resumes (docs/cluster.md, section 7).
"""

import argparse
import json
import math
import os
import sys
import time

import numpy as np

try:
    import torch
    from torch import nn
except ImportError:
    sys.exit("train_join_group: PyTorch is missing; run scripts/install_extras.sh (as root)")
try:
    import matplotlib
    matplotlib.use("Agg")
    from matplotlib import pyplot
except ImportError:
    sys.exit("train_join_group: matplotlib is missing; run scripts/install_extras.sh (as root)")

from ari_social_sim import learning
from training_ranks import Ranks, parameter_hash, requeue, save_atomically

HELD_OUT_FIRST_SEED = 1_000_000
POLICY_FORMAT = "ari_social_sim/mlp_policy/1"


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--task", default="join_group", choices=learning.TASKS)
    parser.add_argument("--minutes", type=float, default=30.0,
                        help="wall-clock budget; training stops at it or at --steps (default 30)")
    parser.add_argument("--steps", type=int, default=50_000_000, help="environment steps at most")
    parser.add_argument("--envs", type=int, default=32, help="environments stepped together")
    parser.add_argument("--threads", type=int, default=2, help="threads of the environments")
    parser.add_argument("--rollout", type=int, default=128, help="steps per environment per update")
    parser.add_argument("--epochs", type=int, default=4)
    parser.add_argument("--minibatch", type=int, default=1024)
    parser.add_argument("--lr", type=float, default=3e-4)
    parser.add_argument("--gamma", type=float, default=0.99)
    parser.add_argument("--lam", type=float, default=0.95, help="GAE lambda")
    parser.add_argument("--clip", type=float, default=0.2)
    parser.add_argument("--hidden", type=int, default=128,
                        help="units of each hidden layer (at most 160: the exported policy must "
                             "stay under the 1 MiB that YAML files are read up to)")
    parser.add_argument("--eval-every", type=int, default=2_000_000, help="steps between evaluations")
    parser.add_argument("--print-every", type=int, default=250_000, help="steps between progress lines")
    parser.add_argument("--eval-seeds", type=int, default=100, help="held-out seeds per evaluation")
    parser.add_argument("--seed", type=int, default=1, help="seeds the network and the episodes")
    parser.add_argument("--out", default="train_out", help="folder for checkpoints, policy, curve")
    parser.add_argument("--updates", type=int, default=0,
                        help="stop after this many updates (0: at --steps or --minutes)")
    parser.add_argument("--segment", type=int, default=8,
                        help="updates between environment resets, where a preempted run stops "
                             "and resumes")
    parser.add_argument("--param-hashes", action="store_true",
                        help="write each rank's parameter hash after every update to "
                             "OUT/param_hashes_rank<R>.txt")
    args = parser.parse_args()
    for name in ("minutes", "steps", "envs", "threads", "rollout", "epochs", "minibatch", "lr",
                 "hidden", "eval_every", "print_every", "eval_seeds", "segment"):
        if getattr(args, name) <= 0:
            parser.error(f"--{name.replace('_', '-')}: expected a number > 0, "
                         f"got {getattr(args, name)}")
    if args.updates < 0:
        parser.error(f"--updates: expected a number >= 0, got {args.updates}")
    if args.hidden > 160:
        parser.error(f"--hidden: expected at most 160, got {args.hidden}")
    return args


class RunningNormaliser:
    """Mean and standard deviation of the observations seen so far (parallel Welford)."""

    def __init__(self, size):
        self.mean = np.zeros(size)
        self.var = np.ones(size)
        self.count = 1e-4

    def update(self, batch):
        self.update_stats(batch.mean(0), batch.var(0), batch.shape[0])

    def update_stats(self, mean, var, count):
        delta = mean - self.mean
        total = self.count + count
        self.mean = self.mean + delta * count / total
        self.var = (self.var * self.count + var * count
                    + delta ** 2 * self.count * count / total) / total
        self.count = total

    def update_moments(self, count, total, total_of_squares):
        """Takes a batch given as its size, sum and sum of squares (summed over the ranks)."""
        mean = total / count
        self.update_stats(mean, np.maximum(total_of_squares / count - mean ** 2, 0.0), count)

    def std(self):
        return np.sqrt(self.var) + 1e-6

    def __call__(self, observations):
        return np.clip((observations - self.mean) / self.std(), -10.0, 10.0).astype(np.float32)


class ActorCritic(nn.Module):
    """A Gaussian policy whose mean, in [-1, 1] per action, maps linearly onto ARI's limits,
    and a value function; separate tanh networks."""

    def __init__(self, observation_size, action_size, hidden):
        super().__init__()
        self.actor = nn.Sequential(nn.Linear(observation_size, hidden), nn.Tanh(),
                                   nn.Linear(hidden, hidden), nn.Tanh(),
                                   nn.Linear(hidden, action_size))
        self.critic = nn.Sequential(nn.Linear(observation_size, hidden), nn.Tanh(),
                                    nn.Linear(hidden, hidden), nn.Tanh(), nn.Linear(hidden, 1))
        self.log_std = nn.Parameter(torch.full((action_size,), -0.5))
        nn.init.orthogonal_(self.actor[-1].weight, 0.01)
        nn.init.zeros_(self.actor[-1].bias)

    def distribution(self, observations):
        return torch.distributions.Normal(self.actor(observations), self.log_std.exp())

    def value(self, observations):
        return self.critic(observations).squeeze(-1)


def flatten(rollout):
    """(steps, envs, ...) of a rollout as one batch of rows."""
    array = np.asarray(rollout, dtype=np.float32)
    return torch.from_numpy(array.reshape(array.shape[0] * array.shape[1], -1))


def to_action(unit, low, high):
    """[-1, 1] per element onto ARI's limits (beyond is clipped, as the environment clips)."""
    return low + (np.clip(unit, -1.0, 1.0) + 1.0) * 0.5 * (high - low)


def evaluate(model, normaliser, env, seeds, low, high, random_policy=False, rng=None):
    """Success rate and mean metrics of the deterministic policy (or of uniformly random actions)
    over the given seeds, one episode each."""
    totals = {"success": 0.0, "reward": 0.0, "collisions": 0.0, "personal_space_time_s": 0.0,
              "path_length_m": 0.0, "ospace_intrusions": 0.0, "time_s": 0.0,
              "gcff_includes_ari": 0.0}
    for seed in seeds:
        observation, info = env.reset(seed=int(seed))
        episode_reward = 0.0
        while True:
            if random_policy:
                action = rng.uniform(low, high).astype(np.float32)
            else:
                with torch.no_grad():
                    mean = model.actor(torch.from_numpy(normaliser(observation[None])))[0].numpy()
                action = to_action(mean, low, high)
            observation, reward, terminated, truncated, info = env.step(action)
            episode_reward += reward
            if terminated or truncated:
                break
        totals["success"] += float(info["success"])
        totals["reward"] += episode_reward
        for key in ("collisions", "personal_space_time_s", "path_length_m",
                    "ospace_intrusions", "time_s"):
            totals[key] += info[key]
        totals["gcff_includes_ari"] += max(info["gcff_includes_ari"], 0)
    return {key: value / len(seeds) for key, value in totals.items()}


def export_policy(path, model, normaliser, env):
    """The policy for social_mpc_node's controller/policy_file (docs/learning.md, "Deploying a
    policy"): plain YAML, read without PyTorch."""
    layers = [module for module in model.actor if isinstance(module, nn.Linear)]

    def row_list(array):
        return "[" + ", ".join(f"{value:.7g}" for value in array) + "]"

    with open(path + ".tmp", "w") as out:
        out.write(f"format: {POLICY_FORMAT}\n")
        out.write(f"task: {env.task}\n")
        out.write(f"control_rate: {1.0 / env.step_s:.9g}\n")
        out.write("arrival:\n")
        out.write(f"  position_tolerance: {env.arrival[0]:.9g}\n")
        out.write(f"  heading_tolerance: {env.arrival[1]:.9g}\n")
        out.write("observation:\n")
        for key, value in env.observation_config.items():
            out.write(f"  {key}: {value}\n")
        out.write(f"observation_mean: {row_list(normaliser.mean)}\n")
        out.write(f"observation_std: {row_list(normaliser.std())}\n")
        out.write("observation_clip: 10.0\n")
        out.write(f"action_low: {row_list(env.action_space.low)}\n")
        out.write(f"action_high: {row_list(env.action_space.high)}\n")
        out.write("layers:\n")
        for index, layer in enumerate(layers):
            weight = layer.weight.detach().numpy()
            out.write(f"  - activation: {'tanh' if index + 1 < len(layers) else 'none'}\n")
            out.write(f"    inputs: {weight.shape[1]}\n")
            out.write(f"    outputs: {weight.shape[0]}\n")
            out.write(f"    bias: {row_list(layer.bias.detach().numpy())}\n")
            out.write(f"    weight: {row_list(weight.reshape(-1))}\n")
    os.replace(path + ".tmp", path)


def plot_curve(path, history, random_success):
    steps = [h["steps"] / 1e6 for h in history]
    figure, axes = pyplot.subplots(1, 3, figsize=(13, 3.8))
    axes[0].plot(steps, [100 * h["success"] for h in history], "o-", label="trained policy")
    axes[0].axhline(100 * random_success, color="grey", linestyle="--", label="random policy")
    axes[0].axhline(70, color="green", linestyle=":", label="70 %")
    axes[0].set_ylabel("success on held-out seeds (%)")
    axes[0].set_ylim(0, 100)
    axes[0].legend(loc="lower right")
    axes[1].plot(steps, [h["reward"] for h in history], "o-")
    axes[1].set_ylabel("episode reward")
    axes[2].plot(steps, [h["personal_space_time_s"] for h in history], "o-",
                 label="time in personal space (s)")
    axes[2].plot(steps, [h["collisions"] for h in history], "s-", label="collisions")
    axes[2].plot(steps, [h["ospace_intrusions"] for h in history], "^-",
                 label="o-space intrusions")
    axes[2].set_ylabel("per episode")
    axes[2].legend(loc="upper right")
    for axis in axes:
        axis.set_xlabel("environment steps (millions)")
        axis.grid(alpha=0.3)
    figure.suptitle("PPO on join_group (perception with its error models), 2 CPU cores")
    figure.tight_layout()
    figure.savefig(path, dpi=90)
    pyplot.close(figure)


def segment_seed(seed, rank, segment):
    """The seed the environments of `rank` are reset with at the start of `segment`: every rank
    its own episodes, never a held-out seed."""
    return (seed * 1_000_003 + rank * 7_777_793 + segment * 99_991) % HELD_OUT_FIRST_SEED


class Progress:
    """Where a run is: what a checkpoint keeps besides the networks."""

    def __init__(self):
        self.update, self.steps = 0, 0
        self.history, self.random_result = [], None
        self.next_eval, self.next_print = 0, 0


def collect_rollout(args, envs, model, normaliser, observations, low, high, recent,
                    episode_rewards):
    """One rollout of args.rollout steps of every environment, the normaliser fixed; returns the
    buffer, the last observations and the observation moments (count, sum, sum of squares)."""
    buffer = {key: [] for key in ("obs", "action", "logp", "reward", "done", "value",
                                  "final_value")}
    moments = [0.0, np.zeros(observations.shape[1]), np.zeros(observations.shape[1])]
    for _ in range(args.rollout):
        normalised = normaliser(observations)
        with torch.no_grad():
            tensor = torch.from_numpy(normalised)
            distribution = model.distribution(tensor)
            unit = distribution.sample()
            logp = distribution.log_prob(unit).sum(-1)
            value = model.value(tensor)
        next_observations, rewards, terminated, truncated, infos = envs.step(
            to_action(unit.numpy(), low, high))
        # A truncated episode is bootstrapped from its last observation's value.
        final_value = np.zeros(args.envs, np.float32)
        if truncated.any():
            with torch.no_grad():
                final = normaliser(infos["final_observation"][truncated])
                final_value[truncated] = model.value(torch.from_numpy(final)).numpy()
        episode_rewards += rewards
        for i in np.flatnonzero(terminated | truncated):
            recent.append((infos["final_info"][i]["success"], episode_rewards[i]))
            episode_rewards[i] = 0.0
        for key, item in (("obs", normalised), ("action", unit.numpy()),
                          ("logp", logp.numpy()), ("reward", rewards),
                          ("done", terminated | truncated), ("value", value.numpy()),
                          ("final_value", final_value)):
            buffer[key].append(item)
        moments[0] += observations.shape[0]
        moments[1] += observations.sum(0)
        moments[2] += (observations.astype(np.float64) ** 2).sum(0)
        observations = next_observations
    return buffer, observations, moments


def ppo_update(args, ranks, model, optimiser, normaliser, buffer, observations):
    """PPO's epochs over the rollout, each gradient averaged over the ranks."""
    with torch.no_grad():
        last_value = model.value(torch.from_numpy(normaliser(observations))).numpy()
    rewards = np.array(buffer["reward"]) + args.gamma * np.array(buffer["final_value"])
    dones = np.array(buffer["done"], dtype=np.float32)
    values = np.array(buffer["value"])
    advantages = np.zeros_like(rewards)
    gae = np.zeros(args.envs)
    for t in reversed(range(args.rollout)):
        next_value = last_value if t + 1 == args.rollout else values[t + 1]
        delta = rewards[t] + args.gamma * next_value * (1.0 - dones[t]) - values[t]
        gae = delta + args.gamma * args.lam * (1.0 - dones[t]) * gae
        advantages[t] = gae
    returns = advantages + values

    batch_obs, batch_action = flatten(buffer["obs"]), flatten(buffer["action"])
    batch_logp = flatten(buffer["logp"])[:, 0]
    batch_adv, batch_ret = flatten(advantages)[:, 0], flatten(returns)[:, 0]
    batch_adv = (batch_adv - batch_adv.mean()) / (batch_adv.std() + 1e-8)
    size = batch_obs.shape[0]
    for _ in range(args.epochs):
        order = torch.randperm(size)
        for start in range(0, size, args.minibatch):
            index = order[start:start + args.minibatch]
            distribution = model.distribution(batch_obs[index])
            logp = distribution.log_prob(batch_action[index]).sum(-1)
            ratio = (logp - batch_logp[index]).exp()
            policy_loss = -torch.min(
                ratio * batch_adv[index],
                ratio.clamp(1 - args.clip, 1 + args.clip) * batch_adv[index]).mean()
            value_loss = 0.5 * (model.value(batch_obs[index]) - batch_ret[index]).pow(2).mean()
            loss = policy_loss + 0.5 * value_loss
            optimiser.zero_grad()
            loss.backward()
            ranks.average_gradients(model)
            nn.utils.clip_grad_norm_(model.parameters(), 0.5)
            optimiser.step()


def save_resume_point(path, ranks, model, optimiser, normaliser, progress):
    """Everything a run needs to go on exactly where it stopped (at a segment's start): rank 0
    writes it, with every rank's random state."""
    states = ranks.gather(torch.get_rng_state())
    if ranks.main:
        save_atomically({"model": model.state_dict(), "optimiser": optimiser.state_dict(),
                         "mean": normaliser.mean, "var": normaliser.var,
                         "count": normaliser.count, "progress": vars(progress),
                         "rng_states": states, "ranks": ranks.size}, path)
    ranks.barrier()


def load_resume_point(path, ranks, model, optimiser, normaliser, progress):
    saved = torch.load(path)
    if saved["ranks"] != ranks.size:
        sys.exit(f"train_join_group: {path} was written by {saved['ranks']} ranks, this run has "
                 f"{ranks.size}: expected the same number to resume")
    model.load_state_dict(saved["model"])
    optimiser.load_state_dict(saved["optimiser"])
    normaliser.mean, normaliser.var, normaliser.count = saved["mean"], saved["var"], saved["count"]
    vars(progress).update(saved["progress"])
    torch.set_rng_state(saved["rng_states"][ranks.rank])


def evaluate_and_save(args, model, normaliser, eval_env, held_out, low, high, progress, started):
    result = evaluate(model, normaliser, eval_env, held_out, low, high)
    result["steps"] = progress.steps
    result["minutes"] = (time.monotonic() - started) / 60
    progress.history.append(result)
    print(f"  evaluation at {progress.steps / 1e6:.2f} M steps: success "
          f"{100 * result['success']:.0f} % on {args.eval_seeds} held-out seeds, reward "
          f"{result['reward']:.2f}, collisions {result['collisions']:.2f}, "
          f"in personal space {result['personal_space_time_s']:.2f} s", flush=True)
    torch.save({"model": model.state_dict(), "mean": normaliser.mean,
                "var": normaliser.var, "count": normaliser.count, "steps": progress.steps},
               os.path.join(args.out, f"checkpoint_{progress.steps}.pt"))
    export_policy(os.path.join(args.out, "policy.yaml"), model, normaliser, eval_env)
    plot_curve(os.path.join(args.out, "curve.png"), progress.history,
               progress.random_result["success"])


def main():
    args = parse_arguments()
    ranks = Ranks()
    os.makedirs(args.out, exist_ok=True)
    # The same network on every rank; each then samples its own actions.
    torch.manual_seed(args.seed)
    # The networks are small: one thread is faster than two (thread start-up outweighs the work).
    torch.set_num_threads(1)
    envs = learning.make_vector(args.task, args.envs, threads=args.threads)
    eval_env = learning.make(args.task)
    low, high = eval_env.action_space.low, eval_env.action_space.high
    observation_size = envs.single_observation_space.shape[0]
    model = ActorCritic(observation_size, len(low), args.hidden)
    ranks.broadcast_parameters(model)
    optimiser = torch.optim.Adam(model.parameters(), lr=args.lr, eps=1e-5)
    normaliser = RunningNormaliser(observation_size)
    held_out = range(HELD_OUT_FIRST_SEED, HELD_OUT_FIRST_SEED + args.eval_seeds)
    progress = Progress()
    resume_path = os.path.join(args.out, "resume.pt")
    started = time.monotonic()
    if os.path.exists(resume_path):
        load_resume_point(resume_path, ranks, model, optimiser, normaliser, progress)
        if ranks.main:
            print(f"resumed from {resume_path} at update {progress.update}", flush=True)
    else:
        torch.manual_seed(args.seed * 100_003 + ranks.rank)
        progress.next_eval, progress.next_print = args.eval_every, args.print_every
        if ranks.main:
            progress.random_result = evaluate(model, normaliser, eval_env, held_out, low, high,
                                              random_policy=True,
                                              rng=np.random.default_rng(args.seed))
            print(f"random policy: success {100 * progress.random_result['success']:.0f} % on "
                  f"{args.eval_seeds} held-out seeds", flush=True)
    hashes = (open(os.path.join(args.out, f"param_hashes_rank{ranks.rank}.txt"), "a")
              if args.param_hashes else None)
    recent, budget_s = [], 60.0 * args.minutes
    while True:
        if progress.update % args.segment == 0:
            # Each segment starts from reset environments, so that a run resumed at a segment's
            # start steps exactly what an uninterrupted one would.
            observations, _ = envs.reset(seed=segment_seed(args.seed, ranks.rank,
                                                           progress.update // args.segment))
            episode_rewards = np.zeros(args.envs)
        buffer, observations, moments = collect_rollout(
            args, envs, model, normaliser, observations, low, high, recent, episode_rewards)
        ppo_update(args, ranks, model, optimiser, normaliser, buffer, observations)
        # The normaliser takes every rank's observations of the rollout, so that it stays the
        # same on every rank.
        total = ranks.sum(np.concatenate([[moments[0]], moments[1], moments[2]]))
        normaliser.update_moments(total[0], total[1:1 + observation_size],
                                  total[1 + observation_size:])
        progress.update += 1
        progress.steps += args.rollout * args.envs * ranks.size
        if hashes:
            hashes.write(f"{progress.update} {parameter_hash(model)}\n")
            hashes.flush()
        elapsed = time.monotonic() - started
        if ranks.main:
            report(args, model, normaliser, eval_env, held_out, low, high, progress, recent,
                   started, elapsed >= budget_s)
        # Rank 0's clock decides for every rank.
        over_budget = ranks.sum(np.array([1.0 if ranks.main and elapsed >= budget_s else 0.0]))
        finished = (progress.steps >= args.steps or over_budget[0] > 0 or
                    (args.updates and progress.update >= args.updates))
        if finished:
            break
        if progress.update % args.segment == 0 and ranks.any_preempted():
            save_resume_point(resume_path, ranks, model, optimiser, normaliser, progress)
            if ranks.main:
                print(f"preempted: checkpoint at update {progress.update} in {resume_path}; "
                      f"{'requeued' if requeue() else 'rerun the same command to go on'}",
                      flush=True)
            return
    if ranks.main:
        finish(args, progress, held_out, started)
        if os.path.exists(resume_path):
            os.remove(resume_path)


def report(args, model, normaliser, eval_env, held_out, low, high, progress, recent, started,
           out_of_time):
    """Rank 0's progress lines and evaluations."""
    elapsed = time.monotonic() - started
    if recent and progress.steps >= progress.next_print:
        progress.next_print += args.print_every
        print(f"{progress.steps / 1e6:6.2f} M steps  {elapsed / 60:5.1f} min  "
              f"{progress.steps / elapsed:7.0f} steps/s  training episodes: success "
              f"{100 * np.mean([s for s, _ in recent]):3.0f} %  reward "
              f"{np.mean([r for _, r in recent]):6.2f}", flush=True)
        recent.clear()
    last_update = args.updates and progress.update >= args.updates
    if (progress.steps >= progress.next_eval or progress.steps >= args.steps or out_of_time or
            last_update):
        progress.next_eval += args.eval_every
        evaluate_and_save(args, model, normaliser, eval_env, held_out, low, high, progress,
                          started)


def finish(args, progress, held_out, started):
    random_result = progress.random_result
    summary = {"task": args.task, "steps": progress.steps, "updates": progress.update,
               "minutes": (time.monotonic() - started) / 60, "random_policy": random_result,
               "history": progress.history,
               "held_out_seeds": [held_out.start, held_out.stop - 1], "arguments": vars(args)}
    with open(os.path.join(args.out, "summary.json"), "w") as out:
        json.dump(summary, out, indent=1)
    final = progress.history[-1] if progress.history else {"success": math.nan}
    print(f"done: {progress.steps} steps in {summary['minutes']:.1f} min; held-out success "
          f"{100 * random_result['success']:.0f} % (random) -> {100 * final['success']:.0f} % "
          f"(trained); policy in {os.path.join(args.out, 'policy.yaml')}")


if __name__ == "__main__":
    main()
