#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main scenario headless: three people form an
# F-formation in the two-room flat (seed figure 3.5); prints their final positions and distances.
set -euo pipefail
source "$(dirname "$0")/prepare.sh"
exec roslaunch ari_social_sim group_formation.launch "$@"
