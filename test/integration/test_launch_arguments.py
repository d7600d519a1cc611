#!/usr/bin/python3
"""rostest, must-show 5 of issue 12 (launch_arguments.test): every launch that starts perception
refuses a `perception:=` value other than sim, detectors and none before starting anything, with
a message listing the three, and accepts the three."""
import subprocess
import unittest

import rostest

LAUNCHES = ["perception.launch", "world_perception.launch", "navigation.launch",
            "dialogue_world.launch", "group_discussion.launch", "join_group.launch",
            "corridor.launch", "waiting_room.launch"]


def nodes_of(launch, perception):
    """roslaunch's exit code, output and the node list it would start (nothing is started)."""
    run = subprocess.run(["roslaunch", "--nodes", "ari_social_sim", launch,
                          "perception:=" + perception], capture_output=True, text=True,
                         timeout=60)
    return run.returncode, run.stdout + run.stderr


class LaunchArguments(unittest.TestCase):
    def test_unknown_perception_mode_is_refused_naming_the_three(self):
        for launch in LAUNCHES:
            code, output = nodes_of(launch, "real")
            self.assertNotEqual(code, 0, launch)
            self.assertIn("perception:=real: expected one of sim, detectors, none", output, launch)

    def test_each_mode_starts_its_parts(self):
        expected = {"sim": {"/hri_perception", "/group_detection"},
                    "detectors": {"/hri_perception", "/group_detection"}, "none": set()}
        for mode, perception_nodes in expected.items():
            code, output = nodes_of("navigation.launch", mode)
            self.assertEqual(code, 0, output)
            nodes = set(output.split())
            self.assertEqual(nodes & {"/hri_perception", "/group_detection"}, perception_nodes,
                             mode)
            # ARI's tf tree from its URDF in every mode (base_link for ROS4HRI clients).
            self.assertIn("/robot_state_publisher", nodes, mode)


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "launch_arguments", LaunchArguments)
