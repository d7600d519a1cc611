# Sourced by the screenshot scripts, which start their own ROS master: goes to the repository's
# root, puts Debian's python first, sources the devel space and points ROS_MASTER_URI at the port
# given (ARI_SCREENSHOT_ROS_PORT overrides it), which must be free.
# usage: source scripts/screenshot_env.sh DEFAULT_PORT
cd "$(dirname "${BASH_SOURCE[0]}")/.."
export PATH=/usr/bin:$PATH
set +u  # catkin's setup scripts read unset variables
source _build/devel/setup.bash
set -u
port=${ARI_SCREENSHOT_ROS_PORT:-$1}
export ROS_MASTER_URI=http://localhost:${port}
if timeout 5 rostopic list > /dev/null 2>&1; then
  echo "a ROS master already runs on port ${port}: set ARI_SCREENSHOT_ROS_PORT to a free one" >&2
  exit 1
fi
