#!/usr/bin/python3
"""rostest: scenario_node ends a run whose world is gone within its world_timeout, and prints its
report when interrupted, on test/integration/scenario_humans.yaml (Ana walks, state walk)."""
import os
import signal
import subprocess
import tempfile
import threading
import time
import unittest

import roslib.packages
import rospy
import rostest

from ari_social_sim.msg import ScenarioStatus

PACKAGE = "ari_social_sim"
SCENARIO = os.path.join(roslib.packages.get_pkg_dir(PACKAGE), "test", "integration",
                        "scenario_humans.yaml")
WORLD_TIMEOUT_S = 3.0


def node_path(name):
    return roslib.packages.find_node(PACKAGE, name)[0]


class StatusWatch:
    """The last /scenario/status received."""

    def __init__(self):
        self.lock = threading.Lock()
        self.status = None
        self.sub = rospy.Subscriber("/scenario/status", ScenarioStatus, self.on_status,
                                    queue_size=10)

    def on_status(self, msg):
        with self.lock:
            self.status = msg

    def wait_for_state(self, state, timeout_s):
        limit = time.monotonic() + timeout_s
        while time.monotonic() < limit:
            with self.lock:
                if self.status is not None and self.status.state == state:
                    return True
            time.sleep(0.01)
        return False


class ScenarioNodeRobustness(unittest.TestCase):
    def start(self, run):
        """world_node paused at half real time (Ana's walk takes ~6 s of wall time), and
        scenario_node, which starts it; scenario_node's output goes to a file."""
        self.watch = StatusWatch()
        self.world = subprocess.Popen(
            [node_path("world_node"), "__name:=world_node", "_scene:=" + SCENARIO,
             "_real_time_factor:=0.5", "_start_paused:=true"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        self.output = tempfile.TemporaryFile(mode="w+")
        self.scenario = subprocess.Popen(
            [node_path("scenario_node"), "__name:=scenario_node_" + run, "_scenario:=" + SCENARIO,
             "_world_timeout:=%g" % WORLD_TIMEOUT_S],
            stdout=self.output, stderr=subprocess.STDOUT)
        self.assertTrue(self.watch.wait_for_state("walk", 60.0), "the run never entered walk")

    def report(self):
        self.output.seek(0)
        return self.output.read()

    def tearDown(self):
        for process in (self.scenario, self.world):
            if process.poll() is None:
                process.kill()
                process.wait()
        self.watch.sub.unregister()

    def test_a_world_gone_ends_the_run_naming_the_wait(self):
        self.start("gone")
        self.world.kill()  # SIGKILL: world_node stays registered with the master, silent
        killed = time.monotonic()
        code = self.scenario.wait(timeout=WORLD_TIMEOUT_S + 10.0)
        elapsed = time.monotonic() - killed
        report = self.report()
        self.assertLessEqual(elapsed, WORLD_TIMEOUT_S + 2.0, report)
        self.assertEqual(code, 1, report)
        self.assertIn("outcome: failure after", report)
        self.assertIn("in state walk: no /sim/world_state for 3 s (world_node gone?) while in "
                      "state walk", report)
        print("scenario_node exited %.2f s after world_node was killed (world_timeout %g s)"
              % (elapsed, WORLD_TIMEOUT_S))

    def test_sigint_prints_the_report_and_exits_within_a_second(self):
        self.start("sigint")
        self.scenario.send_signal(signal.SIGINT)
        sent = time.monotonic()
        code = self.scenario.wait(timeout=10.0)
        elapsed = time.monotonic() - sent
        report = self.report()
        self.assertLessEqual(elapsed, 1.0, report)
        self.assertEqual(code, 130, report)
        self.assertIn("scenario scenario_humans (times from the script's start)\ntranscript:\n",
                      report)
        self.assertIn("states: walk 0.00 s\n", report)
        self.assertIn("outcome: interrupted in state walk after", report)
        self.assertIn("(SIGINT)\n", report)
        print("scenario_node exited %.3f s after SIGINT" % elapsed)


if __name__ == "__main__":
    rospy.init_node("test_scenario_node_robustness")
    rostest.rosrun(PACKAGE, "scenario_node_robustness", ScenarioNodeRobustness)
