#!/usr/bin/env bash
# Regenerates docs/physics_rviz.png: ari_physics_node alone in the hospital waiting room in mapping
# mode (launch/ari_physics.launch mapping:=true), ARI driven on a loop through the room so the torso
# depth camera fills the OctoMap, then config/physics.rviz on a virtual screen, seen over the whole
# room: the robot model, the occupied voxels, the projected /map, and the head camera and torso
# RGB-D colour images. Needs a build (scripts/build.sh), xvfb and ImageMagick; rviz renders with
# llvmpipe. Takes about a minute.
set -euo pipefail
source "$(dirname "$0")/screenshot_env.sh" 11461
work=$(mktemp -d)

roslaunch -p "${port}" ari_social_sim ari_physics.launch mapping:=true real_time_factor:=0 \
  world:="${PWD}/worlds/hospital_waiting_room.yaml" initial_pose:="[6.5, 1.5, 1.5708]" \
  > "${work}/launch.log" 2>&1 &
launch=$!
trap 'kill ${launch} 2>/dev/null || true; wait ${launch} 2>/dev/null || true; rm -rf "${work}"' EXIT
sleep 8

# Drive a loop through the room by /odom (which starts equal to map): a turn on the spot, then
# past the information stand, along the north chairs, round the west end of the middle chair
# rows and back, so the torso depth camera (0.5-3 m ahead of ARI) maps the furniture on the way.
# Last, face the information stand.
python3 - <<'PY'
import math
import time

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

ROUTE = [(6.5, 3.0), (6.2, 6.8), (3.0, 6.9), (1.9, 5.6), (1.9, 3.0), (5.0, 2.6)]
FINAL_HEADING = 0.9  # rad: the information stand and the chair rows ahead

rospy.init_node("physics_screenshot_driver")
pose = [None]


def on_odom(odom):
    q = odom.pose.pose.orientation
    yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
    pose[0] = (odom.pose.pose.position.x, odom.pose.pose.position.y, yaw)


rospy.Subscriber("/mobile_base_controller/odom", Odometry, on_odom)
cmd = rospy.Publisher("/mobile_base_controller/cmd_vel", Twist, queue_size=1)
deadline = time.time() + 300.0  # wall time: /clock may run slower than real time


def send(linear, angular):
    if time.time() > deadline:
        raise SystemExit("ARI did not finish its route: see the launch log")
    twist = Twist()
    twist.linear.x = linear
    twist.angular.z = angular
    cmd.publish(twist)
    time.sleep(0.05)


def turn_to(heading):
    while True:
        error = math.remainder(heading - pose[0][2], 2 * math.pi)
        if abs(error) < 0.05:
            return
        send(0.0, max(-0.8, min(0.8, 2.0 * error)))


while pose[0] is None:
    time.sleep(0.1)
turned, last = 0.0, pose[0][2]
while turned < 2 * math.pi:  # one turn on the spot
    send(0.0, 0.6)
    turned += math.remainder(pose[0][2] - last, 2 * math.pi)
    last = pose[0][2]
for x, y in ROUTE:
    turn_to(math.atan2(y - pose[0][1], x - pose[0][0]))
    while math.hypot(x - pose[0][0], y - pose[0][1]) > 0.1:
        heading = math.atan2(y - pose[0][1], x - pose[0][0])
        error = math.remainder(heading - pose[0][2], 2 * math.pi)
        send(min(0.5, math.hypot(x - pose[0][0], y - pose[0][1])), 2.0 * error)
turn_to(FINAL_HEADING)
send(0.0, 0.0)
PY

# config/physics.rviz as it is, but seen from the south over the whole room.
python3 - "${work}/view.rviz" <<'PY'
import sys
import yaml

view = yaml.safe_load(open("config/physics.rviz"))
view["Visualization Manager"]["Views"]["Current"] = {
    "Class": "rviz/Orbit", "Name": "Current View", "Distance": 12.5, "Pitch": 0.95,
    "Yaw": -1.5708, "Focal Point": {"X": 5.8, "Y": 5.2, "Z": 0}, "Target Frame": "map"}
yaml.safe_dump(view, open(sys.argv[1], "w"))
PY

xvfb-run -a -s "-screen 0 1280x800x24" bash -c "
  rviz -d ${work}/view.rviz > ${work}/rviz.log 2>&1 &
  sleep 20
  import -window root ${work}/shot.png
  kill %1"
cp "${work}/shot.png" docs/physics_rviz.png
echo "wrote docs/physics_rviz.png"
