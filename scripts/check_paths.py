#!/usr/bin/python3
"""Fails when a tracked source, CMake, launch, config, test or script file names a path outside
the repository: a relative path that climbs above the repository's root, a build variable or
package path followed by `/..`, the folder CI keeps beside the clone, or an absolute path into a
home or build folder (/home/..., /root/..., /work/..., .../_build/...). A user has a clone and nothing beside
it: the build once baked in folders beside the checkout that only CI had, and nothing noticed.

Each problem is printed as `FILE:LINE: <what>`; exit 1 if there is any, 0 otherwise.
Exempt: this script and scripts/check_docs.py (they spell the patterns out) and .ci/run, CI's own
set-up, which points
ARI_DATA_DIR at the copies of the public data sets that CI keeps beside the clone.

usage: /usr/bin/python3 scripts/check_paths.py [--repo DIR] [--self-test]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

THIS_SCRIPT = "scripts/check_paths.py"
# check_docs.py spells out the same mentions as patterns and in its self-test.
EXEMPT = {THIS_SCRIPT, "scripts/check_docs.py", ".ci/run"}
SUFFIXES = (".cpp", ".hpp", ".h", ".py", ".yaml", ".launch", ".test", ".cmake", ".sh", ".xml",
            ".urdf", ".rviz", ".msg", ".srv", ".action", ".cfg", ".txt")
NAMES = ("CMakeLists.txt",)
NOT_TRACKED = {".git", "_build", "build", "devel"}

# A build-tree or package root variable followed by `/..`: always above the root (the project's
# CMake files are all included from the root, so their CMAKE_CURRENT_SOURCE_DIR is the root).
ROOT_THEN_UP = re.compile(
    r"(?:\$\{(?:CMAKE_CURRENT_SOURCE_DIR|CMAKE_SOURCE_DIR|PROJECT_SOURCE_DIR|"
    r"ari_social_sim_SOURCE_DIR)\}|\$\(find ari_social_sim\)|ARI_SOURCE_DIR\s*\"?)\s*\"?/\.\.")
# Any number of `../` in a row, and the folder CI keeps beside the clone.
UP_RUN = re.compile(r"(?<![\w.])((?:\.\./)+|(?:\.\.\\/)+)")
# Spelled in pieces, so that this file does not itself name the folder it looks for.
BESIDE_FOLDER = "../" + "shared"
BESIDE = re.compile(re.escape(BESIDE_FOLDER) + r"\b")
ABSOLUTE_PRIVATE = re.compile(r"(?<![\w.$}~-])/(?:home|root|Users|work)/[\w.-]+|"
                              r"(?<![\w.$}~-])/[\w./-]*/_build\b")


def tracked_files(repo):
    try:
        listed = subprocess.run(["git", "-C", repo, "ls-files", "-z"], check=True,
                                capture_output=True).stdout.decode("utf-8")
        names = [n for n in listed.split("\0") if n]
    except (OSError, subprocess.CalledProcessError):
        names = []
        for root, folders, files in os.walk(repo):
            folders[:] = sorted(f for f in folders if f not in NOT_TRACKED)
            names += [os.path.relpath(os.path.join(root, f), repo) for f in files]
    return sorted(n for n in names if n not in EXEMPT and
                  (n.endswith(SUFFIXES) or os.path.basename(n) in NAMES))


def problems_in_line(name, line):
    depth = name.count("/")  # folders between the file and the root
    if ROOT_THEN_UP.search(line):
        yield "climbs above the repository from its root"
    if BESIDE.search(line):
        yield "names '%s', a folder outside the repository" % BESIDE_FOLDER
    for match in UP_RUN.finditer(line):
        if match.group(1).count("..") > depth:
            yield "'%s' climbs above the repository from %s" % (match.group(1), name)
    for match in ABSOLUTE_PRIVATE.finditer(line):
        yield "absolute path '%s' into a home or build folder" % match.group(0)


def check(repo):
    problems = []
    for name in tracked_files(repo):
        try:
            with open(os.path.join(repo, name), encoding="utf-8") as f:
                lines = f.read().split("\n")
        except (OSError, UnicodeDecodeError):
            continue  # deleted but still listed, or not text
        for number, line in enumerate(lines, 1):
            for what in problems_in_line(name, line):
                problems.append("%s:%d: %s" % (name, number, what))
    return problems


def self_test():
    """Planted problems of each kind beside lines that are fine; exactly the planted ones must be
    reported."""
    files = {
        "cmake/data.cmake": ('set(DIR "${CMAKE_CURRENT_SOURCE_DIR}/%s/mpgt")\n' % BESIDE_FOLDER +
                             "include(${CMAKE_CURRENT_LIST_DIR}/../CMakeLists.txt)\n"),
        "src/core/data.cpp": 'const char* kDir = "../../../corpus";\n'
                             '#include "../core/rng.hpp"\n',
        "launch/a.launch": '<param name="data" value="/home/alice/data"/>\n'
                           '<arg name="bag" default="$(env HOME)/run.bag"/>\n'
                           '<include file="$(find ari_social_sim)/../other/x.launch"/>\n',
        "scripts/run.sh": 'cd "$(dirname "$0")/.."\nls /work/main/_build/devel /tmp/ci/_build/x\n',
        "test/perception/test_x.cpp": '#include "../common/data_sets.hpp"\n',
        ".ci/run": 'export ARI_DATA_DIR="$(cd .. && pwd)/data"\n',
    }
    expected = [
        "cmake/data.cmake:1: climbs above the repository from its root",
        "cmake/data.cmake:1: names '%s', a folder outside the repository" % BESIDE_FOLDER,
        "src/core/data.cpp:1: '../../../' climbs above the repository from src/core/data.cpp",
        "launch/a.launch:1: absolute path '/home/alice' into a home or build folder",
        "launch/a.launch:3: climbs above the repository from its root",
        "scripts/run.sh:2: absolute path '/work/main' into a home or build folder",
        "scripts/run.sh:2: absolute path '/tmp/ci/_build' into a home or build folder",
    ]
    with tempfile.TemporaryDirectory() as repo:
        for name, text in files.items():
            os.makedirs(os.path.dirname(os.path.join(repo, name)), exist_ok=True)
            with open(os.path.join(repo, name), "w") as f:
                f.write(text)
        found = check(repo)
    for line in found:
        print("check_paths self-test: reported: " + line)
    if sorted(found) != sorted(expected):
        print("check_paths self-test: FAILED; expected exactly:\n  " + "\n  ".join(expected))
        return False
    print("check_paths self-test: the %d planted paths outside the repository were reported, "
          "nothing else" % len(expected))
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repo", default=os.path.join(os.path.dirname(__file__), ".."))
    parser.add_argument("--self-test", action="store_true")
    options = parser.parse_args()
    if options.self_test and not self_test():
        return 1
    problems = check(os.path.abspath(options.repo))
    for problem in problems:
        print(problem)
    print("check_paths: %d tracked files name a path outside the repository" % len(
        {p.split(":")[0] for p in problems}) if problems else
          "check_paths: no tracked file names a path outside the repository")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
