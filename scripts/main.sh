#!/usr/bin/env bash
# Installs what is missing, builds, and runs the two main scenarios headless:
# 1. D6.4's figure 3.5 (world only): three people walk from the middle of the left room of the
#    two-room flat to a group centre and form an F-formation; prints their final positions,
#    headings and mutual distances;
# 2. group_discussion (D6.4 §3.7) with the whole suite: ARI joins Paul and Irene, answers
#    Irene's question and goes back; prints the transcript and the outcome.
# With a display (DISPLAY set) rviz shows the second. Extra arguments go to its launch
# (e.g. seed:=3 real_time_factor:=2 record:=true time_limit:=3).
# Both run through scripts/run_launch.py, whose exit code tells how they went (roslaunch's does
# not): 0 success, 1 the scenario failed, 2 bad input or a node died, 130 interrupted (README,
# "Exit codes"). The first run that does not succeed ends the script with its code.
set -euo pipefail
source "$(dirname "$0")/prepare.sh"
/usr/bin/python3 scripts/run_launch.py --decider world_node ari_social_sim group_formation.launch
gui=false
if [[ -n "${DISPLAY:-}" ]]; then
  gui=true
fi
exec /usr/bin/python3 scripts/run_launch.py ari_social_sim group_discussion.launch gui:="$gui" "$@"
