#!/usr/bin/env python3
"""Plays a trained policy file (docs/learning.md, section 10) on seeded episodes of a learning task
and prints its success rate and social metrics. The policy runs through the same C++ code as in
social_mpc_node (learning.load_policy), so this measures what is deployed. Needs no PyTorch.

    scripts/evaluate_policy.py --policy config/policies/join_group.yaml --task join_group \\
        --seeds 100 --first-seed 1000000
    scripts/evaluate_policy.py --policy ... --task scenario:join_group --seeds 100 --first-seed 1
"""

import argparse
import json
import sys

from ari_social_sim import learning


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--policy", required=True, help="a policy.yaml")
    parser.add_argument("--task", default="join_group",
                        help="a learning task (join_group, scenario:join_group, ...)")
    parser.add_argument("--seeds", type=int, default=100, help="episodes, one per seed")
    parser.add_argument("--first-seed", type=int, default=1_000_000,
                        help="the first seed (1,000,000 and up are never trained on)")
    parser.add_argument("--json", help="also write the figures to this file")
    args = parser.parse_args()
    if args.seeds < 1 or args.first_seed < 0:
        parser.error("--seeds: expected an integer >= 1; --first-seed: an integer >= 0")
    try:
        policy = learning.load_policy(args.policy)
        env = learning.make(args.task)
    except ValueError as error:
        sys.exit(f"evaluate_policy: {error}")
    keys = ("success", "collisions", "personal_space_time_s", "ospace_intrusions",
            "path_length_m", "time_s")
    totals = dict.fromkeys(keys, 0.0)
    gcff = []
    for seed in range(args.first_seed, args.first_seed + args.seeds):
        observation, info = env.reset(seed=seed)
        terminated = truncated = False
        while not (terminated or truncated):
            observation, _, terminated, truncated, info = env.step(policy.act(observation))
        for key in keys:
            totals[key] += float(info[key])
        if info["gcff_includes_ari"] >= 0:
            gcff.append(info["gcff_includes_ari"])
    figures = {key: value / args.seeds for key, value in totals.items()}
    figures["gcff_includes_ari"] = sum(gcff) / len(gcff) if gcff else None
    print(f"{args.task}, {args.seeds} seeds from {args.first_seed}: success "
          f"{100 * figures['success']:.0f} %, collisions {figures['collisions']:.2f}, "
          f"personal space {figures['personal_space_time_s']:.2f} s, o-space intrusions "
          f"{figures['ospace_intrusions']:.2f}, path {figures['path_length_m']:.2f} m, "
          f"time {figures['time_s']:.2f} s per episode"
          + (f", GCFF counts ARI in the group in {100 * figures['gcff_includes_ari']:.0f} %"
             if gcff else ""))
    if args.json:
        with open(args.json, "w") as out:
            json.dump({"task": args.task, "policy": args.policy, "seeds": args.seeds,
                       "first_seed": args.first_seed, **figures}, out, indent=1)


if __name__ == "__main__":
    main()
