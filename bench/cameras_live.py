#!/usr/bin/env python3
"""Rate of ARI's cameras in the live 3D suite (world_node + ari_physics_node): launches
world_3d.launch with a scene at a real-time factor, subscribes to the head camera and the torso
RGB-D camera (colour and aligned depth) and prints the simulated time's rate and each topic's
frames per wall second and per simulated second. Frames per simulated second below the cameras'
rates (10 and 15 Hz by default) mean the suite could not keep that real-time factor.

    bench/cameras_live.py [--scene FILE] [--rtf 1 2 3] [--seconds 30]

Needs the workspace sourced (roslaunch, rospy) and no other roscore running.
"""
import argparse
import os
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TOPICS = ("/head_front_camera/color/image_raw", "/torso_front_camera/color/image_raw",
          "/torso_front_camera/aligned_depth_to_color/image_raw")


def measure(seconds):
    import rospy
    from rosgraph_msgs.msg import Clock
    from sensor_msgs.msg import Image

    counts = {topic: 0 for topic in TOPICS}
    clock = [None]

    def counter(topic):
        def on_image(_):
            counts[topic] += 1
        return on_image

    def on_clock(message):
        clock[0] = message.clock.to_sec()

    rospy.init_node("cameras_live", anonymous=True, disable_signals=True)
    for topic in TOPICS:
        rospy.Subscriber(topic, Image, counter(topic), queue_size=5)
    rospy.Subscriber("/clock", Clock, on_clock)
    time.sleep(8.0)  # the cameras start rendering once subscribed
    for topic in TOPICS:
        counts[topic] = 0
    wall_start, sim_start = time.time(), clock[0]
    time.sleep(seconds)
    wall, sim = time.time() - wall_start, clock[0] - sim_start
    rates = {topic: (counts[topic] / wall, counts[topic] / sim) for topic in TOPICS}
    rospy.signal_shutdown("measured")
    return wall, sim, rates


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=os.path.join(HERE, "scenes", "waiting_room_10.yaml"))
    parser.add_argument("--rtf", type=float, nargs="+", default=[1.0, 2.0, 3.0])
    parser.add_argument("--seconds", type=float, default=30.0)
    args = parser.parse_args()
    for rtf in args.rtf:
        if not rtf > 0.0:
            sys.exit(f"--rtf: expected real-time factors > 0, got {rtf}")
        launch = subprocess.Popen(
            ["roslaunch", "ari_social_sim", "world_3d.launch", f"scene:={args.scene}",
             f"real_time_factor:={rtf}"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            start_new_session=True)
        try:
            time.sleep(6.0)
            child = subprocess.run(
                [sys.executable, __file__, "--measure", str(args.seconds)], capture_output=True,
                text=True, timeout=args.seconds + 60.0)
            print(f"real_time_factor {rtf:g}:")
            print(child.stdout.rstrip() or child.stderr.rstrip())
        finally:
            os.killpg(launch.pid, signal.SIGINT)
            launch.wait(timeout=30)
            time.sleep(3.0)


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--measure":
        wall, sim, rates = measure(float(sys.argv[2]))
        print(f"  wall {wall:.1f} s, sim {sim:.1f} s: {sim / wall:.2f}x")
        for topic, (per_wall, per_sim) in rates.items():
            print(f"  {topic}: {per_wall:.1f} Hz of wall time, {per_sim:.2f} per sim second")
    else:
        main()
