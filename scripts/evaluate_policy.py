#!/usr/bin/env python3
"""Plays a trained policy file (docs/learning.md, section 10) on seeded episodes of a learning task
and prints its success rate and social metrics. The policy runs through the same C++ code as in
social_mpc_node (learning.load_policy), so this measures what is deployed. Needs no PyTorch.

    scripts/evaluate_policy.py --policy config/policies/join_group.yaml --task join_group \\
        --seeds 100 --first-seed 1000000
    scripts/evaluate_policy.py --policy ... --task scenario:join_group --seeds 100 --first-seed 1
    scripts/evaluate_policy.py --policy config/policies/join_group.yaml --task join_conversation

On join_conversation the policy drives and learning.conversation_rule.PauseSpeaker decides when
ARI speaks (the task's rule baseline); the conversation's figures are printed too.
"""

import argparse
import json
import statistics
import sys

from ari_social_sim import learning
from ari_social_sim.learning.conversation_rule import PauseSpeaker

CONVERSATION_SUMS = ("interruptions", "ari_interruptions", "intrusions", "entries", "answers",
                     "arrived")


def conversation_figures(infos):
    """Per-episode conversation figures of join_conversation's final infos."""
    sums = {key: sum(float(info[key]) for info in infos) for key in CONVERSATION_SUMS}
    addressed = [info["ari_addressed_after_s"] for info in infos
                 if info["ari_addressed_after_s"] >= 0]
    delays = [info["answer_delay_s"] for info in infos if info["answer_delay_s"] >= 0]
    return {
        "arrived": sums["arrived"] / len(infos),
        "interruptions_per_episode": sums["interruptions"] / len(infos),
        "ari_interruptions_per_episode": sums["ari_interruptions"] / len(infos),
        "entries_in_pause_share": (1 - sums["intrusions"] / sums["entries"]
                                   if sums["entries"] else None),
        "joined_share": sum(1 for info in infos if info["entries"] > 0) / len(infos),
        "addressed_share": len(addressed) / len(infos),
        "addressed_after_s_median": statistics.median(addressed) if addressed else None,
        "answer_delay_s_median": statistics.median(delays) if delays else None,
    }


def print_conversation(c):
    def number(value, unit=" s"):
        return "-" if value is None else f"{value:.2f}{unit}"
    pause = c["entries_in_pause_share"]
    print(f"conversation: arrived {100 * c['arrived']:.0f} %, joined (formation) "
          f"{100 * c['joined_share']:.0f} %, interruptions {c['interruptions_per_episode']:.2f} "
          f"per episode (world's count {c['ari_interruptions_per_episode']:.2f}), entries in a "
          f"pause {'-' if pause is None else f'{100 * pause:.0f} %'}"
          f", addressed in {100 * c['addressed_share']:.0f} % after "
          f"{number(c['addressed_after_s_median'])} (median), answered after "
          f"{number(c['answer_delay_s_median'])} (median)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--policy", required=True, help="a policy.yaml")
    parser.add_argument("--task", default="join_group",
                        help="a learning task (join_group, scenario:join_group, ...)")
    parser.add_argument("--seeds", type=int, default=100, help="episodes, one per seed")
    parser.add_argument("--first-seed", type=int, default=1_000_000,
                        help="the first seed (1,000,000 and up are never trained on)")
    parser.add_argument("--json", help="also write the figures to this file")
    parser.add_argument("--no-wait", action="store_true",
                        help="join_conversation: the rule does not stop for a pause to enter")
    parser.add_argument("--always-speak", action="store_true",
                        help="join_conversation: speak at every step instead of the rule's")
    args = parser.parse_args()
    if args.seeds < 1 or args.first_seed < 0:
        parser.error("--seeds: expected an integer >= 1; --first-seed: an integer >= 0")
    try:
        policy = learning.load_policy(args.policy)
        env = learning.make(args.task)
    except ValueError as error:
        sys.exit(f"evaluate_policy: {error}")
    talks = "conversation" in env.observation_layout
    if talks:
        policy = PauseSpeaker(policy, env.observation_layout, wait_for_pause=not args.no_wait)
        policy.always_speak = args.always_speak
    keys = ("success", "collisions", "personal_space_time_s", "ospace_intrusions",
            "path_length_m", "time_s")
    totals = dict.fromkeys(keys, 0.0)
    gcff = []
    finals = []
    for seed in range(args.first_seed, args.first_seed + args.seeds):
        observation, info = env.reset(seed=seed)
        if talks:
            policy.reset()
        terminated = truncated = False
        while not (terminated or truncated):
            observation, _, terminated, truncated, info = env.step(policy.act(observation))
        for key in keys:
            totals[key] += float(info[key])
        if info["gcff_includes_ari"] >= 0:
            gcff.append(info["gcff_includes_ari"])
        finals.append(info)
    figures = {key: value / args.seeds for key, value in totals.items()}
    figures["gcff_includes_ari"] = sum(gcff) / len(gcff) if gcff else None
    print(f"{args.task}, {args.seeds} seeds from {args.first_seed}: success "
          f"{100 * figures['success']:.0f} %, collisions {figures['collisions']:.2f}, "
          f"personal space {figures['personal_space_time_s']:.2f} s, o-space intrusions "
          f"{figures['ospace_intrusions']:.2f}, path {figures['path_length_m']:.2f} m, "
          f"time {figures['time_s']:.2f} s per episode"
          + (f", GCFF counts ARI in the group in {100 * figures['gcff_includes_ari']:.0f} %"
             if gcff else ""))
    if talks:
        figures["conversation"] = conversation_figures(finals)
        print_conversation(figures["conversation"])
    if args.json:
        with open(args.json, "w") as out:
            json.dump({"task": args.task, "policy": args.policy, "seeds": args.seeds,
                       "wait_for_pause": talks and not args.no_wait,
                       "first_seed": args.first_seed, **figures}, out, indent=1)


if __name__ == "__main__":
    main()
