#!/usr/bin/env bash
# Installs what is missing, builds, and plays the main scenario, group_discussion (seed section
# 3.7), with the whole suite: ARI joins Paul and Irene, answers Irene's question and goes back.
# Prints the transcript and the outcome; with a display (DISPLAY set) rviz shows the run.
# Extra arguments go to roslaunch (e.g. seed:=3 real_time_factor:=2 record:=true).
set -euo pipefail
source "$(dirname "$0")/prepare.sh"
gui=false
if [[ -n "${DISPLAY:-}" ]]; then
  gui=true
fi
exec roslaunch ari_social_sim group_discussion.launch gui:="$gui" "$@"
