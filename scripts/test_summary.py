#!/usr/bin/python3
"""Summarises the JUnit XML files catkin's run_tests leaves under a folder.

Prints one line per suite with failures, then `tests: N passed, N failed` (failed counts failures
and errors). Exits 1 if anything failed, no test ran, or a suite produced no result file.
"""
import pathlib
import sys
import xml.etree.ElementTree as ElementTree


def main(folder: str) -> int:
    passed = failed = skipped = 0
    files = sorted(pathlib.Path(folder).rglob("*.xml"))
    for path in files:
        try:
            root = ElementTree.parse(path).getroot()
        except ElementTree.ParseError as error:
            print(f"{path}: unreadable result file ({error})")
            failed += 1
            continue
        suites = [root] if root.tag == "testsuite" else root.iter("testsuite")
        for suite in suites:
            for case in suite.iter("testcase"):
                problems = case.findall("failure") + case.findall("error")
                if problems:
                    failed += 1
                    message = problems[0].get("message") or (problems[0].text or "").strip()
                    print(f"FAILED {path.name}: {case.get('classname')}.{case.get('name')}: "
                          f"{message[:300]}")
                elif case.find("skipped") is not None:
                    skipped += 1
                else:
                    passed += 1
    print(f"{len(files)} result files")
    print(f"tests: {passed} passed, {failed} failed, {skipped} skipped")
    return 0 if failed == 0 and passed > 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "_build/test_results"))
