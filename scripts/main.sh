#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main scenario headless: three people form an
# F-formation in the two-room flat (seed figure 3.5); prints their final positions and distances.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
export PATH=/usr/bin:$PATH
set +u  # catkin's setup scripts read unset variables
source _build/devel/setup.bash
set -u
exec roslaunch ari_social_sim group_formation.launch "$@"
