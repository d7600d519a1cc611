#!/usr/bin/env bash
# Builds ari_social_sim with Debian's catkin into _build/ (devel space: _build/devel).
# Catkin needs Debian's /usr/bin/python3 (it has catkin_pkg); put it first whatever else is on PATH.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH=/usr/bin:$PATH
# catkin snapshots the environment for run_tests at configure time and only puts the devel
# space's Python folder on PYTHONPATH if it already exists; on a fresh clone it does not yet,
# and rostest's Python nodes could not import the generated messages.
mkdir -p _build/devel/lib/python3/dist-packages
# compile_commands.json is what scripts/clang_tidy.sh and scripts/check_warnings.sh read.
cmake -S . -B _build -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCATKIN_ENABLE_TESTING=ON \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -Wno-dev \
  > /tmp/ari_social_sim_configure.log 2>&1 || { cat /tmp/ari_social_sim_configure.log; exit 1; }
cmake --build _build -j"$(nproc)" "$@"
echo "build: done (source _build/devel/setup.bash to use the package)"
