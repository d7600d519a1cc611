#!/usr/bin/python3
"""rostest: SIGINT stops world_node within 1 s, whatever it is doing (README, world_node).

world_node is started with subprocess, interrupted as Ctrl-C would, and the time from the signal
to its exit is measured and printed: at a real-time factor of 1e-3 (50 s of wall time per step)
and in the middle of a /sim/step request of the maximum 100000 steps.
"""
import os
import signal
import subprocess
import threading
import time
import unittest

import roslib.packages
import rospy
import rostest
from rosgraph_msgs.msg import Clock

from ari_social_sim.srv import StepSimulation

EXIT_LIMIT_S = 1.0


def start_world_node(name, **params):
    """Starts world_node as `name` with private parameters; returns the process."""
    executable = roslib.packages.find_node("ari_social_sim", "world_node")[0]
    args = [executable, "__name:=" + name] + ["_%s:=%s" % item for item in params.items()]
    return subprocess.Popen(args, stdout=subprocess.DEVNULL)


def seconds_to_exit(process):
    """Sends SIGINT and returns the wall seconds until the process has exited (or 10 s)."""
    sent = time.monotonic()
    process.send_signal(signal.SIGINT)
    try:
        process.wait(timeout=10.0)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()
        return 10.0
    return time.monotonic() - sent


class WorldNodeSigint(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("world_node_sigint")

    def test_slow_real_time_factor(self):
        process = start_world_node("world_node_slow", real_time_factor=0.001)
        try:
            # Services are up once the node runs; its first step comes at once, the next one is
            # 50 s of wall time away.
            rospy.wait_for_service("/sim/step", timeout=30)
            time.sleep(0.5)
            self.assertIsNone(process.poll(), "world_node ended by itself")
            exit_s = seconds_to_exit(process)
        finally:
            if process.poll() is None:
                process.kill()
        print("world_node at real_time_factor 1e-3 exited %.3f s after SIGINT (code %s)"
              % (exit_s, process.returncode))
        self.assertLess(exit_s, EXIT_LIMIT_S)
        self.assertEqual(process.returncode, 0)

    def test_long_step_request(self):
        process = start_world_node("world_node_stepping", start_paused="true")
        try:
            rospy.wait_for_service("/sim/step", timeout=30)
            step = rospy.ServiceProxy("/sim/step", StepSimulation)
            answer = {}

            def call():
                try:
                    answer["response"] = step(steps=100000)
                except (rospy.ServiceException, rospy.ROSException) as e:
                    answer["error"] = str(e)

            caller = threading.Thread(target=call, daemon=True)
            caller.start()
            # Wait until the steps are under way (sim time moving), then interrupt.
            limit = time.monotonic() + 10
            while time.monotonic() < limit:
                clock = rospy.wait_for_message("/clock", Clock, timeout=10).clock.to_sec()
                if clock > 1.0:
                    break
            self.assertTrue(caller.is_alive(), "the 100000 steps finished before the signal")
            exit_s = seconds_to_exit(process)
            caller.join(timeout=5)
        finally:
            if process.poll() is None:
                process.kill()
        print("world_node during /sim/step of 100000 steps exited %.3f s after SIGINT (code %s, "
              "request: %s)" % (exit_s, process.returncode, answer))
        self.assertLess(exit_s, EXIT_LIMIT_S)
        self.assertEqual(process.returncode, 0)


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "world_node_sigint", WorldNodeSigint)
