# Sourced by main.sh and test.sh: installs what is missing, builds, and sets up the environment
# (Debian's python3 first, the package's devel space sourced).
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
export PATH=/usr/bin:$PATH
set +u  # catkin's setup scripts read unset variables
source _build/devel/setup.bash
set -u
