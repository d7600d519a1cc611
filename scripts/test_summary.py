#!/usr/bin/python3
"""Summarises the JUnit XML files catkin's run_tests leaves under a folder.

Prints one line per failed test and one per skipped test with its reason, then
`tests: N passed, N failed, N skipped` (failed counts failures and errors; a skipped test never
counts as passed). Exits 1 if anything failed, no test ran, or a result file is unreadable.

--refuse-data-skips (CI, which has every public data set): a test skipped because a data set is
missing (its reason starts with DATA_SET_SKIP_PREFIX, test/common/data_sets.hpp) counts as failed.
"""
import argparse
import pathlib
import sys
import xml.etree.ElementTree as ElementTree

DATA_SET_SKIP_PREFIX = "data set missing: "


def skip_reason(case: ElementTree.Element) -> str:
    skipped = case.find("skipped")
    return (skipped.get("message") or (skipped.text or "")).strip()


def summarise(folder: str, refuse_data_skips: bool) -> int:
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
                name = f"{path.name}: {case.get('classname')}.{case.get('name')}"
                problems = case.findall("failure") + case.findall("error")
                if problems:
                    failed += 1
                    message = problems[0].get("message") or (problems[0].text or "").strip()
                    print(f"FAILED {name}: {message[:300]}")
                elif case.find("skipped") is not None:
                    reason = skip_reason(case)
                    if refuse_data_skips and reason.startswith(DATA_SET_SKIP_PREFIX):
                        failed += 1
                        print(f"FAILED {name}: skipped where every data set must be present: "
                              f"{reason[:300]}")
                    else:
                        skipped += 1
                        print(f"SKIPPED {name}: {reason[:300]}")
                else:
                    passed += 1
    print(f"{len(files)} result files")
    print(f"tests: {passed} passed, {failed} failed, {skipped} skipped")
    return 0 if failed == 0 and passed > 0 else 1


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", nargs="?", default="_build/test_results")
    parser.add_argument("--refuse-data-skips", action="store_true",
                        help="count a test skipped for a missing data set as failed (CI)")
    options = parser.parse_args()
    return summarise(options.folder, options.refuse_data_skips)


if __name__ == "__main__":
    sys.exit(main())
