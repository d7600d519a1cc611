#!/usr/bin/python3
"""The repository alone: runs the README's main job (scripts/main.sh) as a user with a bare clone
would, through scripts/run_alone.sh (no folder beside the repository in sight, an empty
ARI_DATA_DIR and HOME), and requires it to succeed. First a self-test shows that the guard bites:
a program given a path beside the repository (`<repo>/../<folder>/...`, as a build that baked in
a folder beside the checkout would) reads it outside the guard and fails inside it.

Writes a JUnit file (counted by scripts/test_summary.py) and prints what it saw.
usage: /usr/bin/python3 scripts/check_alone.py --build DIR --junit FILE
"""
import argparse
import os
import pathlib
import shutil
import subprocess
import tempfile
import time
import xml.etree.ElementTree as ElementTree

REPO = pathlib.Path(__file__).resolve().parent.parent
RUN_ALONE = str(REPO / "scripts" / "run_alone.sh")
CANNOT_ISOLATE = 3  # run_alone.sh: no mount namespace (not root)
FEATURES = "frame,person_id,x,y,theta\n1,a,0,0,0\n1,b,1.2,0,3.141593\n"


class Case:
    def __init__(self, name):
        self.name, self.failure, self.skipped, self.seconds = name, None, None, 0.0


def run(command, log=None):
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if log:
        pathlib.Path(log).write_text(result.stdout)
    return result.returncode, result.stdout


def self_test(build):
    """detect_groups reads a table in a folder beside the repository: 0 outside, 2 inside."""
    case = Case("guard_hides_folders_beside_the_repository")
    detect_groups = os.path.join(build, "devel", "lib", "ari_social_sim", "detect_groups")
    beside = pathlib.Path(tempfile.mkdtemp(prefix=".ari_alone_probe_", dir=REPO.parent))
    try:
        (beside / "features.csv").write_text(FEATURES)
        # The path as a baked-in default beside the checkout would spell it.
        path = "%s/../%s/features.csv" % (REPO, beside.name)
        command = [detect_groups, "--features", path, "--stride", "0.6", "--mdl", "0.8"]
        outside, _ = run(command)
        inside, said = run([RUN_ALONE] + command)
    finally:
        shutil.rmtree(beside)
    print("check_alone self-test: %s outside the guard: exit %d; inside: exit %d (%s)"
          % (path, outside, inside, said.strip().splitlines()[-1] if said.strip() else ""))
    if inside == CANNOT_ISOLATE:
        case.skipped = "no private mount namespace here (run as root): " + said.strip()
    elif outside != 0 or inside != 2 or "cannot open" not in said:
        case.failure = ("a path beside the repository was not hidden: exit %d outside, %d inside: "
                        "%s" % (outside, inside, said[-500:]))
    return case


def main_job(log):
    case = Case("main_job_runs_on_the_repository_alone")
    started = time.monotonic()
    status, said = run([RUN_ALONE, "bash", "scripts/main.sh"], log)
    case.seconds = time.monotonic() - started
    tail = "\n".join(said.strip().splitlines()[-12:])
    print("check_alone: scripts/main.sh on the repository alone: exit %d after %.0f s (log: %s)\n%s"
          % (status, case.seconds, log, tail))
    if status == CANNOT_ISOLATE:
        case.skipped = "no private mount namespace here (run as root)"
    elif status != 0:
        case.failure = "scripts/main.sh exited %d on the repository alone: %s" % (status, tail)
    return case


def write_junit(cases, path):
    suite = ElementTree.Element("testsuite", name="repository_alone", tests=str(len(cases)))
    for case in cases:
        element = ElementTree.SubElement(suite, "testcase", classname="repository_alone",
                                         name=case.name, time="%.1f" % case.seconds)
        if case.failure:
            ElementTree.SubElement(element, "failure", message=case.failure)
        elif case.skipped:
            ElementTree.SubElement(element, "skipped", message=case.skipped)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    ElementTree.ElementTree(suite).write(path, encoding="utf-8", xml_declaration=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(REPO / "_build"))
    parser.add_argument("--junit", required=True)
    options = parser.parse_args()
    guard = self_test(os.path.abspath(options.build))
    cases = [guard]
    if guard.failure is None and guard.skipped is None:
        cases.append(main_job(os.path.join(os.path.abspath(options.build), "main_alone.log")))
    write_junit(cases, options.junit)
    return 1 if any(c.failure for c in cases) else 0


if __name__ == "__main__":
    raise SystemExit(main())
