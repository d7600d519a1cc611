#!/usr/bin/python3
"""Batch plans of run_episodes, export_dataset, nav_benchmark and dialogue_corpus on a SLURM cluster
(docs/cluster.md).

  slurm_batch.py submit --shards N --out DIR [--partition P] [--time T] [--cpus-per-task C]
                        [--mem M] [--account A] [--overwrite | --resume] -- TOOL ARGS...
  slurm_batch.py status --out DIR

`submit` turns the plan (TOOL with ARGS: run_episodes, export_dataset or nav_benchmark with
--episodes, dialogue_corpus with --dialogues, and what else they take, never --out, --csv or
--shard) into a job array of N shards and a merge job that runs after them (--dependency=afterok). Each task runs its shard in a staging folder of its own
(DIR/slurm/stage/shardK, resumed if a task ran there before) and, once the tool has finished it,
renames the folder into DIR/slurm/done/: DIR never holds a partial file. The merge job moves the
shards' files into DIR and runs TOOL --merge-shards N, which writes exactly what one process
running the plan writes. `submit --resume` submits only the shards not done (and the merge);
`status` reports progress and throughput.
"""
import argparse
import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

class Tool:
    """How a batch tool takes a plan: its count option, where a task and the merge write (DIR's
    own name for a tool that writes one file), whether a rerun task resumes, and the exit codes
    after which its output is complete."""

    def __init__(self, count, out_file=None, resumes=True, complete=(0,), refused=(),
                 out="--out"):
        self.count, self.out_file, self.resumes = count, out_file, resumes
        self.complete, self.refused, self.out = complete, refused, out

    def out_option(self, folder):
        return [self.out, str(folder / self.out_file if self.out_file else folder)]


TOOLS = {
    # run_episodes exits 1 when an episode failed: its output is complete all the same.
    "run_episodes": Tool("--episodes", complete=(0, 1)),
    "export_dataset": Tool("--episodes"),
    # nav_benchmark's shards keep their exact records; the merge writes DIR/nav.csv and the table.
    "nav_benchmark": Tool("--episodes", out_file="nav.csv", out="--csv", refused=("--trace",)),
    # dialogue_corpus writes its file only when complete: a rerun shard starts again.
    "dialogue_corpus": Tool("--dialogues", out_file="corpus.jsonl", resumes=False,
                            refused=("--compare", "--variety", "--report")),
}
# Options the plan may not carry: this script sets them per task.
OWN_OPTIONS = ("--out", "--csv", "--shard", "--resume", "--overwrite", "--merge-shards")
SCRIPT = Path(__file__).resolve()


class PlanError(Exception):
    """Bad input, found before anything is submitted."""


# --- the folder of a plan ------------------------------------------------------------------------

class PlanFolder:
    """Where a plan keeps its state, beside the outputs in DIR."""

    def __init__(self, out):
        self.out = Path(out).resolve()
        self.slurm = self.out / "slurm"
        self.plan_file = self.slurm / "plan.json"
        self.jobs_file = self.slurm / "jobs.json"
        self.logs = self.slurm / "logs"
        self.times = self.slurm / "times"
        self.merged_file = self.slurm / "merged.json"

    def stage(self, shard):
        return self.slurm / "stage" / ("shard%d" % shard)

    def done(self, shard):
        return self.slurm / "done" / ("shard%d" % shard)

    def read_plan(self):
        return json.loads(self.plan_file.read_text())

    def read_jobs(self):
        return json.loads(self.jobs_file.read_text()) if self.jobs_file.exists() else []

    def shards_done(self, plan):
        return [k for k in range(1, plan["shards"] + 1) if self.done(k).is_dir()]


def option_value(args, name):
    """The value of `name` in a tool's arguments (`--episodes 40` or `--episodes=40`)."""
    for i, arg in enumerate(args):
        if arg == name and i + 1 < len(args):
            return args[i + 1]
        if arg.startswith(name + "="):
            return arg.split("=", 1)[1]
    return None


def check_plan(tool_args, shards):
    """The plan's episodes, after checking the tool, its arguments and the shard count."""
    if not tool_args or tool_args[0] not in TOOLS:
        raise PlanError("expected the tool after --: one of %s, got '%s'" % (
            ", ".join(TOOLS), tool_args[0] if tool_args else ""))
    tool = TOOLS[tool_args[0]]
    for arg in tool_args[1:]:
        name = arg.split("=", 1)[0]
        if name in OWN_OPTIONS:
            raise PlanError("%s: set by slurm_batch.py for each task; leave it out of the plan"
                            % name)
        if name in tool.refused:
            raise PlanError("%s: not for a job array: run it with %s on one process"
                            % (name, tool_args[0]))
    episodes_text = option_value(tool_args[1:], tool.count)
    if episodes_text is None or not episodes_text.isdigit() or int(episodes_text) < 1:
        raise PlanError("%s: expected the plan's count (a positive integer) among the tool's "
                        "arguments, got '%s'" % (tool.count, episodes_text or ""))
    episodes = int(episodes_text)
    if shards < 1 or episodes % shards != 0:
        divisors = [d for d in range(1, min(episodes, 64) + 1) if episodes % d == 0]
        raise PlanError("--shards %d: expected a count that divides %s %d, so that every "
                        "task runs as many (e.g. %s)" % (
                            shards, tool.count, episodes, ", ".join(map(str, divisors[:8]))))
    return episodes


def tool_binary(tool):
    """The tool's executable, found as rosrun finds it (the package's setup.bash sourced)."""
    try:
        found = subprocess.run(["catkin_find", "--first-only", "--without-underlays", "--libexec",
                                "ari_social_sim", tool], capture_output=True, text=True)
        path = found.stdout.strip()
    except FileNotFoundError:
        path = ""
    if not path or not os.access(path, os.X_OK):
        raise PlanError("%s: not found: source the package's setup.bash (devel/setup.bash) first"
                        % tool)
    return path


# --- SLURM ---------------------------------------------------------------------------------------

def slurm(command, what):
    """Runs a SLURM command; its standard output, or PlanError with SLURM's own words."""
    try:
        result = subprocess.run(command, capture_output=True, text=True)
    except FileNotFoundError:
        raise PlanError("%s: %s not found: install slurm-client (scripts/install_deps.sh)"
                        % (what, command[0]))
    if result.returncode != 0:
        raise PlanError("%s: %s" % (what, (result.stderr or result.stdout).strip()))
    return result.stdout


def check_partition(partition):
    """The partition to use: the one given, checked to exist, or the cluster's default."""
    names = [p.strip() for p in slurm(["sinfo", "-h", "-o", "%P"], "sinfo").split()]
    default = next((n[:-1] for n in names if n.endswith("*")), None)
    known = [n.rstrip("*") for n in names]
    if partition is None:
        if default is None:
            raise PlanError("--partition: the cluster has no default partition: expected one of "
                            "%s" % ", ".join(known))
        return default
    if partition not in known:
        raise PlanError("--partition: expected one of the cluster's partitions (%s), got '%s'"
                        % (", ".join(known), partition))
    return partition


def resource_options(args, partition):
    options = ["--partition", partition, "--time", args.time,
               "--cpus-per-task", str(args.cpus_per_task), "--mem", args.mem]
    if args.account:
        options += ["--account", args.account]
    return options


def submit_jobs(folder, plan, shards, resources):
    """The job array of `shards` (none: only the merge) and the merge after it; their ids."""
    folder.logs.mkdir(parents=True, exist_ok=True)
    name = "ari_%s" % plan["tool"]
    python = sys.executable or "/usr/bin/python3"
    array_id = None
    if shards:
        array_id = slurm(["sbatch", "--parsable", "--array", ",".join(map(str, shards)),
                          "--job-name", name, "--requeue",
                          "--output", str(folder.logs / "shard_%A_%a.out")] + resources +
                         ["--wrap", "exec %s %s _task --out %s" % (python, SCRIPT, folder.out)],
                         "sbatch").strip().split(";")[0]
    merge = ["sbatch", "--parsable", "--job-name", name + "_merge",
             "--output", str(folder.logs / "merge_%j.out")] + resources
    if array_id:
        merge += ["--dependency", "afterok:%s" % array_id, "--kill-on-invalid-dep=yes"]
    merge_id = slurm(merge + ["--wrap", "exec %s %s _merge --out %s" % (
        python, SCRIPT, folder.out)], "sbatch").strip().split(";")[0]
    return array_id, merge_id


# --- submit --------------------------------------------------------------------------------------

def prepare_folder(folder, plan, overwrite, resume):
    """Deals with what DIR holds: a new plan, the same plan resumed, or one replaced."""
    if folder.plan_file.exists():
        if overwrite:
            cancel_earlier_jobs(folder)
            shutil.rmtree(folder.out)
        elif not resume:
            raise PlanError("--out: %s holds a plan already: pass --resume to run what is "
                            "missing or --overwrite to start again" % folder.out)
        else:
            there = folder.read_plan()
            if there != plan:
                differences = ["%s: %s there, %s now" % (key, json.dumps(there.get(key)),
                                                         json.dumps(plan[key]))
                               for key in plan if there.get(key) != plan[key]]
                raise PlanError("--resume: %s was planned otherwise (%s); pass the same plan or "
                                "--overwrite" % (folder.out, "; ".join(differences)))
            cancel_earlier_jobs(folder)
            return
    elif folder.out.exists() and any(folder.out.iterdir()):
        raise PlanError("--out: %s is not empty and holds no plan of slurm_batch.py: expected a "
                        "new or empty folder" % folder.out)
    folder.slurm.mkdir(parents=True, exist_ok=True)
    folder.plan_file.write_text(json.dumps(plan, indent=1) + "\n")


def cancel_earlier_jobs(folder):
    """Cancels what an earlier submission left queued: a merge that would run twice."""
    ids = [job[key] for job in folder.read_jobs() for key in ("array", "merge") if job.get(key)]
    if ids:
        subprocess.run(["scancel"] + ids, capture_output=True)


def submit(args):
    folder = PlanFolder(args.out)
    episodes = check_plan(args.tool_args, args.shards)
    tool_binary(args.tool_args[0])
    partition = check_partition(args.partition)
    resources = resource_options(args, partition)
    # SLURM checks the resources (time, memory, CPUs against the partition) without queueing.
    slurm(["sbatch", "--test-only", "--array", "1-%d" % args.shards] + resources +
          ["--wrap", "true"], "--partition/--time/--cpus-per-task/--mem")
    plan = {"tool": args.tool_args[0], "args": args.tool_args[1:], "shards": args.shards,
            "episodes": episodes}
    prepare_folder(folder, plan, args.overwrite, args.resume)
    if folder.merged_file.exists():
        print("slurm_batch: %s is merged already: nothing to do" % folder.out)
        return 0
    done = folder.shards_done(plan)
    missing = [k for k in range(1, args.shards + 1) if k not in done]
    array_id, merge_id = submit_jobs(folder, plan, missing, resources)
    jobs = folder.read_jobs() + [{"array": array_id, "merge": merge_id, "shards": missing,
                                  "submitted": time.time()}]
    folder.jobs_file.write_text(json.dumps(jobs, indent=1) + "\n")
    print("slurm_batch: %s: %d of %d shards to run%s, merge job %s after them" % (
        folder.out, len(missing), args.shards,
        " (job array %s: %s)" % (array_id, ",".join(map(str, missing))) if missing else "",
        merge_id))
    return 0


# --- a task of the array -------------------------------------------------------------------------

def run_forwarding_signals(command):
    """Runs `command`, passing SIGTERM, SIGINT and SIGUSR1 on (SLURM's cancel and time limit):
    the tools stop between two steps and keep what they finished. Its exit status."""
    child = subprocess.Popen(command)

    def forward(signum, _frame):
        child.send_signal(signum)

    for signum in (signal.SIGTERM, signal.SIGINT, signal.SIGUSR1):
        signal.signal(signum, forward)
    return child.wait()


def task(args):
    """One shard: the tool in the shard's staging folder, then the folder renamed into done/."""
    folder = PlanFolder(args.out)
    plan = folder.read_plan()
    shard = int(os.environ["SLURM_ARRAY_TASK_ID"])
    stage = folder.stage(shard)
    stage.mkdir(parents=True, exist_ok=True)
    started = time.time()
    tool = TOOLS[plan["tool"]]
    command = ([tool_binary(plan["tool"])] + plan["args"] +
               ["--shard", "%d/%d" % (shard, plan["shards"])] + tool.out_option(stage) +
               (["--resume"] if tool.resumes else ["--overwrite"]))
    status = run_forwarding_signals(command)
    if status not in tool.complete:
        return status  # stopped or failed: the stage is resumed by the next attempt
    folder.done(shard).parent.mkdir(parents=True, exist_ok=True)
    os.rename(stage, folder.done(shard))
    folder.times.mkdir(parents=True, exist_ok=True)
    (folder.times / ("shard%d.json" % shard)).write_text(json.dumps(
        {"start": started, "end": time.time(), "episodes": plan["episodes"] // plan["shards"]}))
    return 0


# --- the merge -----------------------------------------------------------------------------------

def move_into(source, target):
    """Moves every file under `source` to the same place under `target` (renames: same disk)."""
    for path in sorted(source.rglob("*")):
        if path.is_file():
            destination = target / path.relative_to(source)
            destination.parent.mkdir(parents=True, exist_ok=True)
            os.replace(path, destination)


def throughput(folder):
    """(episodes, wall seconds from the first task's start to the last one's end)."""
    records = [json.loads(p.read_text()) for p in folder.times.glob("shard*.json")]
    if not records:
        return 0, 0.0
    return (sum(r["episodes"] for r in records),
            max(r["end"] for r in records) - min(r["start"] for r in records))


def merge(args):
    folder = PlanFolder(args.out)
    plan = folder.read_plan()
    missing = [k for k in range(1, plan["shards"] + 1) if not folder.done(k).is_dir()]
    if missing:
        print("slurm_batch: shards %s have not finished; resubmit with --resume"
              % ",".join(map(str, missing)), file=sys.stderr)
        return 2
    started = time.time()
    for k in range(1, plan["shards"] + 1):
        move_into(folder.done(k), folder.out)
    tool = TOOLS[plan["tool"]]
    command = ([tool_binary(plan["tool"])] + plan["args"] +
               ["--merge-shards", str(plan["shards"])] + tool.out_option(folder.out))
    status = subprocess.run(command).returncode
    if status not in tool.complete:
        return status
    shutil.rmtree(folder.slurm / "done", ignore_errors=True)
    shutil.rmtree(folder.slurm / "stage", ignore_errors=True)
    episodes, wall_s = throughput(folder)
    report = {"episodes": episodes, "array_wall_s": wall_s, "merge_wall_s": time.time() - started,
              "episodes_per_minute": 60.0 * episodes / wall_s if wall_s > 0 else None}
    folder.merged_file.write_text(json.dumps(report, indent=1) + "\n")
    print("slurm_batch: merged %d shards into %s: %d episodes in %.1f s over the array "
          "(%.1f episodes per minute), merge %.1f s" % (
              plan["shards"], folder.out, episodes, wall_s,
              report["episodes_per_minute"] or 0.0, report["merge_wall_s"]))
    return 0


# --- status --------------------------------------------------------------------------------------

def rows_in_stage(stage):
    """Units a running task has finished: its CSV's rows (run_episodes), or the records in its
    progress file (nav_benchmark: one per episode, type and controller)."""
    rows = 0
    for csv in stage.glob("*.csv"):
        rows += max(0, csv.read_text(errors="replace").count("\n") - 1)
    for progress in stage.glob("*.records.active"):
        rows += progress.read_text(errors="replace").count("\ndone ")
    return rows


def records_per_episode(plan):
    """nav_benchmark runs each episode of every type with every controller: 8 x 2 by default."""
    if plan["tool"] != "nav_benchmark":
        return 1
    types = option_value(plan["args"], "--types")
    controllers = option_value(plan["args"], "--controllers")
    return ((len(types.split(",")) if types else 8) *
            (len(controllers.split(",")) if controllers else 2))


def status(args):
    folder = PlanFolder(args.out)
    if not folder.plan_file.exists():
        raise PlanError("--out: %s holds no plan of slurm_batch.py" % folder.out)
    plan = folder.read_plan()
    per_shard = plan["episodes"] // plan["shards"]
    done = folder.shards_done(plan)
    merged = folder.merged_file.exists()
    running = 0
    if not merged:
        running = sum(rows_in_stage(folder.stage(k)) for k in range(1, plan["shards"] + 1)
                      if k not in done) // records_per_episode(plan)
    episodes = plan["episodes"] if merged else len(done) * per_shard + running
    queued = slurm(["squeue", "-h", "-o", "%i %T", "-n", "ari_%s,ari_%s_merge" % (
        plan["tool"], plan["tool"])], "squeue").split("\n")
    finished, wall_s = throughput(folder)
    print("%s: %s; %d of %d shards done, %d of %d episodes; %d job(s) queued or running" % (
        folder.out, "merged" if merged else "not merged", plan["shards"] if merged else len(done),
        plan["shards"], episodes, plan["episodes"], len([q for q in queued if q.strip()])))
    if wall_s > 0:
        print("throughput: %.1f episodes per minute over the array (%d episodes of finished "
              "shards in %.1f s)" % (60.0 * finished / wall_s, finished, wall_s))
    return 0


# --- command line --------------------------------------------------------------------------------

def parse(argv):
    parser = argparse.ArgumentParser(
        prog="slurm_batch.py", description="Batch plans on a SLURM cluster (docs/cluster.md).")
    commands = parser.add_subparsers(dest="command", required=True)
    sub = commands.add_parser("submit", help="submit a plan as a job array and a merge job")
    sub.add_argument("--shards", type=int, required=True, help="tasks of the array")
    sub.add_argument("--out", required=True, help="the plan's output folder")
    sub.add_argument("--partition", help="default: the cluster's default partition")
    sub.add_argument("--time", default="01:00:00", help="time limit per task (SLURM's format)")
    sub.add_argument("--cpus-per-task", type=int, default=1)
    sub.add_argument("--mem", default="2G", help="memory per task (SLURM's format)")
    sub.add_argument("--account", help="the account to charge, if the cluster wants one")
    mode = sub.add_mutually_exclusive_group()
    mode.add_argument("--overwrite", action="store_true", help="replace an earlier plan's folder")
    mode.add_argument("--resume", action="store_true", help="run what an earlier submission "
                      "did not finish")
    sub.add_argument("tool_args", nargs=argparse.REMAINDER,
                     help="-- then the tool and its arguments")
    stat = commands.add_parser("status", help="progress and throughput of a plan")
    stat.add_argument("--out", required=True)
    for internal in ("_task", "_merge"):  # what the jobs run
        hidden = commands.add_parser(internal)
        hidden.add_argument("--out", required=True)
    args = parser.parse_args(argv)
    if args.command == "submit" and args.tool_args[:1] == ["--"]:
        args.tool_args = args.tool_args[1:]
    return args


def main(argv):
    args = parse(argv)
    handlers = {"submit": submit, "status": status, "_task": task, "_merge": merge}
    try:
        return handlers[args.command](args)
    except PlanError as error:
        print("slurm_batch: %s" % error, file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
