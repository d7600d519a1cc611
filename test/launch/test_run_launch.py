"""scripts/run_launch.py (README, "Exit codes"): the mapping from the nodes' exit codes to the
launch's, then real launches of group_discussion through it: a forced time limit gives 1 with the
state and the reason, a node refusing its parameter gives 2 naming it, a bad launch argument 2.
Each real run has its own master port and log folder, so that it shares nothing with a roscore
the machine may be running."""
import importlib.util
import os
import socket
import subprocess
import sys
import tempfile
from types import SimpleNamespace

import pytest

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "run_launch.py")
spec = importlib.util.spec_from_file_location("run_launch", SCRIPT)
run_launch = importlib.util.module_from_spec(spec)
spec.loader.exec_module(run_launch)

LAUNCH = "group_discussion.launch"


def status(state, reason, finished=True):
    return SimpleNamespace(scenario="group_discussion", state=state, finished=finished,
                           reason=reason)


def verdict(ended, **kwargs):
    return run_launch.verdict(LAUNCH, "scenario_node", ended, log_dir="/logs", **kwargs)


class TestMapping:
    def test_the_deciding_nodes_zero_one_and_130_are_the_launchs(self):
        code, line = verdict([("scenario_node-8", 0)], status=status("leave", "ARI left"))
        assert code == 0
        assert line == ("group_discussion succeeded in state leave: ARI left (scenario_node "
                        "exited with 0)")
        code, line = verdict([("scenario_node-8", 1)],
                             status=status("ask_help", "time limit of 3 s reached"))
        assert code == 1
        assert line == ("group_discussion failed in state ask_help: time limit of 3 s reached "
                        "(scenario_node exited with 1)")
        assert verdict([("scenario_node-8", 130)])[0] == 130

    def test_a_failure_without_a_status_still_says_so(self):
        code, line = verdict([("scenario_node-8", 1)])
        assert code == 1
        assert "failed (scenario_node exited with 1; no /scenario/status said why)" in line

    def test_the_deciding_node_refusing_its_input_or_crashing_gives_two(self):
        code, line = verdict([("scenario_node-8", 2)])
        assert code == 2
        assert line == ("group_discussion.launch: scenario_node exited with 2 "
                        "(log: /logs/scenario_node-8*.log)")
        code, line = verdict([("scenario_node-8", -11)])
        assert code == 2
        assert "scenario_node was killed by SIGSEGV" in line
        assert verdict([("scenario_node-8", None)])[0] == 2

    def test_another_node_dying_first_gives_two_naming_every_one(self):
        ended = [("dialogue_node-6", 2), ("rviz-9", -6), ("scenario_node-8", 2)]
        code, line = verdict(ended)
        assert code == 2
        assert line == ("group_discussion.launch: dialogue_node exited with 2 (log: "
                        "/logs/dialogue_node-6*.log); rviz was killed by SIGABRT (log: "
                        "/logs/rviz-9*.log)")
        # Even when the scenario then ran to a success or a failure of its own.
        assert verdict([("dialogue_node-6", 1), ("scenario_node-8", 0)])[0] == 2

    def test_what_ends_cleanly_or_after_the_deciding_node_does_not_count(self):
        assert verdict([("helper-3", 0), ("scenario_node-8", 0)])[0] == 0
        assert verdict([("scenario_node-8", 0), ("dialogue_node-6", 1)])[0] == 0

    def test_a_launch_that_ends_without_the_deciding_node_gives_two(self):
        code, line = verdict([])
        assert code == 2
        assert "scenario_node did not end" in line

    def test_a_stop_signal_gives_128_plus_its_number(self):
        assert verdict([("scenario_node-8", 0)], stop_signal=2) == (
            130, "group_discussion.launch interrupted by SIGINT")
        assert verdict([], stop_signal=15)[0] == 143

    def test_process_names_lose_roslaunchs_counter_only(self):
        assert run_launch.node_of("scenario_node-8") == "scenario_node"
        assert run_launch.node_of("ns/my-node-12") == "ns/my-node"
        assert run_launch.node_of("my-node") == "my-node"

    def test_the_listener_says_when_the_launch_has_nothing_left_to_wait_for(self):
        deaths = run_launch.Deaths("scenario_node")
        deaths.process_died("helper-2", 0)
        assert not deaths.launch_should_end()
        deaths.process_died("dialogue_node-6", 2)
        assert deaths.launch_should_end()
        deaths = run_launch.Deaths("world_node")
        deaths.process_died("world_node-1", 0)
        assert deaths.launch_should_end()


def free_port():
    with socket.socket() as probe:
        probe.bind(("localhost", 0))
        return probe.getsockname()[1]


def run_group_discussion(*launch_args):
    """(exit code, standard output and error) of group_discussion through the runner."""
    with tempfile.TemporaryDirectory(prefix="run_launch_test.") as logs:
        env = dict(os.environ, ROS_MASTER_URI="http://localhost:%d" % free_port(),
                   ROS_LOG_DIR=logs)
        run = subprocess.run([sys.executable, SCRIPT, "ari_social_sim", LAUNCH] +
                             list(launch_args), env=env, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True, timeout=120)
    return run.returncode, run.stdout


@pytest.mark.skipif("ROS_PACKAGE_PATH" not in os.environ, reason="needs the devel space")
class TestRealLaunches:
    def test_a_time_limit_too_short_fails_with_one_naming_the_state_and_the_reason(self):
        code, output = run_group_discussion("time_limit:=2")
        last = output.rstrip().splitlines()[-1]
        assert code == 1, output
        assert last.startswith("run_launch: group_discussion failed in state "), output
        assert "time limit of 2.000000 s reached" in last
        assert last.endswith("(scenario_node exited with 1): exit code 1")
        assert "outcome: failure" in output  # scenario_node's own report reached the terminal

    def test_a_node_refusing_its_parameter_gives_two_naming_it(self):
        code, output = run_group_discussion("navigation_policy:=/nonexistent/policy.yaml")
        last = output.rstrip().splitlines()[-1]
        assert code == 2, output
        assert "social_mpc_node exited with 2 (log: " in last, output
        assert "/nonexistent/policy.yaml" in output  # the node's FATAL line reached the terminal

    def test_a_bad_launch_argument_gives_two(self):
        code, output = run_group_discussion("seed:=abc")
        assert code == 2, output
        assert "seed:=abc: expected an integer, -1 for the scenario file seed" in output
        assert output.rstrip().splitlines()[-1] == (
            "run_launch: roslaunch refused group_discussion.launch (above); no node ran: exit "
            "code 2")
