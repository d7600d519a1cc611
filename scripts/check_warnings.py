#!/usr/bin/python3
"""Fails unless the build treats compiler warnings as errors in the project's own code: every
compile command of a source under src/, test/ or bench/ in the build's compile_commands.json
carries -Werror (CMakeLists.txt's ARI_WARNINGS_AS_ERRORS, on by default). The build itself then
stops at the first warning; this check shows that the build scripts/test.sh just ran had it on.

--self-test first compiles a file with an unused variable using the flags of one of the project's
own sources and shows the compiler refuses it, and that a clean file compiles.

usage: /usr/bin/python3 scripts/check_warnings.py [--build DIR] [--self-test]
"""
import argparse
import json
import os
import shlex
import subprocess
import sys
import tempfile

OWN_FOLDERS = ("src", "test", "bench")


def own_commands(repo, build):
    """(source path relative to the repository, argument list) of each of the project's sources."""
    database = os.path.join(build, "compile_commands.json")
    if not os.path.exists(database):
        sys.exit(f"check_warnings: {database} not found: run scripts/build.sh first")
    with open(database) as stream:
        entries = json.load(stream)
    for entry in entries:
        path = os.path.relpath(entry["file"], repo)
        if path.split(os.sep)[0] in OWN_FOLDERS:
            arguments = entry.get("arguments") or shlex.split(entry["command"])
            yield path, arguments, entry["directory"]


def syntax_check_command(arguments, source):
    """The compile command with `source` in place of its file and no output written."""
    command = []
    skip = False
    for argument in arguments:
        if skip:
            skip = False
        elif argument == "-o":
            skip = True
        elif argument == "-c" or argument.endswith((".cpp", ".cc")):
            continue
        else:
            command.append(argument)
    return command + ["-fsyntax-only", source]


def self_test(arguments, directory):
    with tempfile.TemporaryDirectory() as folder:
        bad = os.path.join(folder, "bad.cpp")
        good = os.path.join(folder, "good.cpp")
        with open(bad, "w") as stream:
            stream.write("int f() {\n  int unused = 0;\n  return 1;\n}\n")
        with open(good, "w") as stream:
            stream.write("int f() {\n  return 1;\n}\n")
        result = subprocess.run(syntax_check_command(arguments, bad), cwd=directory,
                                capture_output=True, text=True)
        errors = [line for line in result.stderr.splitlines() if "error:" in line]
        if result.returncode == 0 or not errors:
            sys.exit("check_warnings self-test: FAILED, a file with a warning compiled")
        result = subprocess.run(syntax_check_command(arguments, good), cwd=directory,
                                capture_output=True, text=True)
        if result.returncode != 0:
            sys.exit("check_warnings self-test: FAILED, a clean file did not compile:\n" +
                     result.stderr)
        print("check_warnings self-test: a file with a warning fails to compile ("
              + errors[0].split("error: ", 1)[1] + "), a clean one compiles")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repo", default=os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))))
    parser.add_argument("--build", default=None, help="the build folder (default REPO/_build)")
    parser.add_argument("--self-test", action="store_true")
    args = parser.parse_args()
    build = os.path.abspath(args.build or os.path.join(args.repo, "_build"))
    commands = list(own_commands(args.repo, build))
    if not commands:
        sys.exit(f"check_warnings: no compile command of the project's sources in {build}")
    if args.self_test:
        source, arguments, directory = commands[0]
        self_test(arguments, directory)
    lenient = [source for source, arguments, _ in commands if "-Werror" not in arguments]
    for source in lenient:
        print(f"{source}: compiled without -Werror")
    if lenient:
        sys.exit(f"check_warnings: {len(lenient)} of {len(commands)} sources are compiled without "
                 "-Werror: configure with -DARI_WARNINGS_AS_ERRORS=ON")
    print(f"check_warnings: all {len(commands)} of the project's sources compile with -Werror")


if __name__ == "__main__":
    main()
