#!/usr/bin/env bash
# Runs one rostest N times and counts the passes, printing each run's "[ measured ]" lines (a
# rostest keeps its test's stdout in the result XML only). For tests whose outcome depends on
# timing, e.g. test/integration/pyhri_client.test:
#   bash scripts/repeat_rostest.sh 10 pyhri_client.test
# With "all" for the test, each run is the whole rostest suite as scripts/test.sh runs it (catkin's
# run_tests_ari_social_sim_rostest target: every test/integration/*.test, with their arguments),
# and a run passes when every test case in it passed:
#   bash scripts/repeat_rostest.sh 10 all
# Exits non-zero unless every run passed. Needs a build (scripts/build.sh).
set -uo pipefail
cd "$(dirname "$0")/.."
if (($# < 2)) || ! [[ $1 =~ ^[1-9][0-9]{0,3}$ ]]; then
  echo "usage: bash scripts/repeat_rostest.sh RUNS(1-9999) TEST_FILE-or-all [rostest args...]" >&2
  exit 2
fi
runs=$1
test_file=$2
shift 2
export PATH=/usr/bin:$PATH
set +u; source _build/devel/setup.bash; set -u
results=$(mktemp -d /tmp/repeat_rostest.XXXXXX)
passed=0
if [ "$test_file" = all ]; then
  for i in $(seq "$runs"); do
    rm -rf _build/test_results
    cmake --build _build --target run_tests_ari_social_sim_rostest -j1 > "$results/run$i.log" 2>&1
    cp -r _build/test_results "$results/run$i"
    if summary=$(/usr/bin/python3 scripts/test_summary.py "$results/run$i"); then
      passed=$((passed + 1)); verdict=PASS
    else
      verdict=FAIL
    fi
    echo "run $i: $verdict, $(echo "$summary" | tail -1) (log $results/run$i.log)"
    echo "$summary" | grep '^FAILED' | sed 's/^/  /' || true
  done
  echo "rostest suite: $passed of $runs runs passed"
  [ "$passed" -eq "$runs" ]
  exit
fi
for i in $(seq "$runs"); do
  export ROS_TEST_RESULTS_DIR=$results/run$i
  if rostest ari_social_sim "$test_file" "$@" > "$results/run$i.log" 2>&1; then
    passed=$((passed + 1)); verdict=PASS
  else
    verdict=FAIL
  fi
  echo "run $i: $verdict (log $results/run$i.log)"
  /usr/bin/python3 - "$ROS_TEST_RESULTS_DIR" <<'PY'
import pathlib, sys, xml.etree.ElementTree as ET
for xml in sorted(pathlib.Path(sys.argv[1]).rglob("rosunit-*.xml")):
    root = ET.parse(xml).getroot()
    for out in root.iter("system-out"):
        for line in (out.text or "").splitlines():
            if "[ measured ]" in line:
                print("  " + line.strip())
    for failure in root.iter("failure"):
        text = (failure.text or failure.get("message") or "").split("\n")[0]
        print("  FAILED: " + text[:400] + (" ..." if len(text) > 400 else ""))
PY
done
echo "$test_file: $passed of $runs runs passed"
[ "$passed" -eq "$runs" ]
