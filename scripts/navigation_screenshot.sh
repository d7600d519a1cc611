#!/usr/bin/env bash
# Regenerates docs/navigation_rviz.png: scenes/social_navigation_demo.yaml with world_node,
# hri_perception_node and social_mpc_node (launch/navigation.launch); ARI is asked to join the
# group Paul (human20) is in and is shown in config/navigation.rviz twice: on its way past the
# couple and the waiting patient (plan, predicted footprints, personal spaces, o-spaces, social
# cost), and once it has joined. Needs a build (scripts/build.sh), xvfb and ImageMagick.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH=/usr/bin:$PATH
set +u
source _build/devel/setup.bash
set -u
port=${ARI_SCREENSHOT_ROS_PORT:-11398}
export ROS_MASTER_URI=http://localhost:${port}
work=$(mktemp -d)

roslaunch -p "${port}" ari_social_sim navigation.launch \
  scene:="${PWD}/scenes/social_navigation_demo.yaml" > "${work}/launch.log" 2>&1 &
launch=$!
trap 'kill ${launch} 2>/dev/null || true; rm -rf "${work}"' EXIT
sleep 10

# config/navigation.rviz without the displays panel, framed on the scene.
python3 - > "${work}/view.rviz" <<'PY'
import yaml
view = yaml.safe_load(open("config/navigation.rviz"))
view["Panels"] = []
view["Visualization Manager"]["Views"]["Current"].update({"Scale": 118, "X": 6.9, "Y": 3.4})
view["Window Geometry"] = {"Width": 1280, "Height": 800, "X": 0, "Y": 0}
print(yaml.safe_dump(view))
PY

# Waits until /social_mpc/status says less than $1 m to go (or, with "succeeded", the end).
cat > "${work}/wait.py" <<'PY'
import re, sys, time
import rospy
from std_msgs.msg import String
rospy.init_node("navigation_screenshot_wait", anonymous=True)
deadline = time.time() + 90
while time.time() < deadline:
    status = rospy.wait_for_message("/social_mpc/status", String, timeout=90).data
    if sys.argv[1] == "succeeded":
        if status.startswith("succeeded"):
            sys.exit(0)
    else:
        match = re.search(r"([0-9.]+) m to go", status)
        if match and float(match.group(1)) < float(sys.argv[1]):
            sys.exit(0)
    if status.startswith("aborted"):
        sys.exit("ARI " + status)
sys.exit("ARI did not get there in 90 s")
PY

xvfb-run -a -s "-screen 0 1280x800x24" bash -c "
  rviz -d ${work}/view.rviz > /dev/null 2>&1 &
  sleep 8
  rostopic pub -1 /social_mpc/approach/goal ari_social_sim/ApproachActionGoal \
    '{goal: {target_type: 2, target_id: human20}}' > /dev/null
  python3 ${work}/wait.py ${ARI_SCREENSHOT_ON_THE_WAY:-3.2}
  import -window root ${work}/on_the_way.png
  python3 ${work}/wait.py succeeded
  sleep 2
  import -window root ${work}/joined.png
  kill %1"
label() {  # image, caption
  convert "$1" -gravity NorthWest -font DejaVu-Sans-Bold -pointsize 16 -fill white \
    -undercolor '#000000b0' -annotate +10+10 "$2" "$1"
}
label "${work}/on_the_way.png" ' on the way: plan and footprints (blue), personal spaces (orange; green: members to join), o-space (red), social cost (yellow-red) '
label "${work}/joined.png" ' joined: ARI in the gap of the group it was sent to, facing its centre (cyan: the group perception reports) '
convert "${work}/on_the_way.png" "${work}/joined.png" -append -resize 75% docs/navigation_rviz.png
echo "wrote docs/navigation_rviz.png"
