#!/usr/bin/env bash
# Regenerates docs/perception_rviz.png: scenes/perception_demo.yaml with world_node and
# hri_perception_node (default error models), one person talking, shown by two rviz windows side
# by side on a virtual screen: the ground truth (/sim/markers) on the left, what ARI perceives
# (/hri_perception/markers) on the right. Needs a build (scripts/build.sh), xvfb and ImageMagick.
set -euo pipefail
source "$(dirname "$0")/screenshot_env.sh" 11397
work=$(mktemp -d)

roslaunch -p "${port}" ari_social_sim world_perception.launch \
  scene:="${PWD}/scenes/perception_demo.yaml" > "${work}/launch.log" 2>&1 &
launch=$!
trap 'kill ${launch} 2>/dev/null || true; rm -rf "${work}"' EXIT
sleep 8

# Two copies of config/perception.rviz without the displays panel, each with one of the two
# marker displays, seen from the south, placed left and right on a 1920 x 820 screen.
make_view() {  # name, display to keep, x
  python3 - "$2" "$3" > "${work}/$1.rviz" <<'PY'
import sys
import yaml
keep, x = sys.argv[1], int(sys.argv[2])
view = yaml.safe_load(open("config/perception.rviz"))
view["Panels"] = []
for display in view["Visualization Manager"]["Displays"]:
    if display["Class"] == "rviz/MarkerArray":
        display["Enabled"] = display["Name"].startswith(keep)
view["Visualization Manager"]["Views"]["Current"] = {
    "Class": "rviz/Orbit", "Name": "Current View", "Distance": 10.5, "Pitch": 1.15,
    "Yaw": -1.5708, "Focal Point": {"X": 4.9, "Y": 3.9, "Z": 0}, "Target Frame": "map"}
view["Window Geometry"] = {"Width": 960, "Height": 820, "X": x, "Y": 0}
print(yaml.safe_dump(view))
PY
}
make_view truth "Ground truth" 0
make_view perceived "Perceived" 960

xvfb-run -a -s "-screen 0 1920x820x24" bash -c "
  rviz -d ${work}/truth.rviz > /dev/null 2>&1 &
  rviz -d ${work}/perceived.rviz > /dev/null 2>&1 &
  sleep 9
  rosservice call /sim/say '{speaker_id: 20, act: \"INFORM\", content: \"the doctor said we can wait here until they call our names\"}' > /dev/null
  sleep 3
  import -window root ${work}/shot.png
  kill %1 %2"
convert "${work}/shot.png" -gravity NorthWest -font DejaVu-Sans-Bold -pointsize 24 -fill white \
  -undercolor '#000000b0' \
  -annotate +12+10 ' ground truth (/sim/markers) ' \
  -annotate +972+10 ' perceived by ARI (/hri_perception/markers) ' docs/perception_rviz.png
echo "wrote docs/perception_rviz.png"
