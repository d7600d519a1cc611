#!/usr/bin/python3
"""Runs a launch file as roslaunch does and exits with a code that tells how it went, which
roslaunch does not (it exits 0 whatever its nodes did). The code comes from the exit codes of the
nodes themselves, which roslaunch's process monitor reports:

  0    the deciding node ended with 0: the scenario succeeded (scenario_node), or the run went to
       its end (world_node of group_formation.launch)
  1    the deciding node ended with 1: the scenario ran and failed (its time limit, no progress);
       the last line names the state and the reason
  2    bad input (a launch argument or file refused, a node refusing its parameters), or a node
       that died: the last line names each node, its exit code and its log files
  130  interrupted (SIGINT, Ctrl-C), 143 (SIGTERM): 128 + the signal, as a shell reports it

The deciding node is scenario_node unless --decider names another. Any other node that dies with
an exit code other than 0 before the deciding node has ended ends the launch at once (exit 2):
a scenario without it cannot succeed, and waiting for scenario_node's server timeout would only
take longer. Nodes' output reaches the terminal as with roslaunch (a node's ROS_FATAL and
ROS_ERROR lines too: they go to standard error even with output="log").

usage: run_launch.py [--decider NODE] PACKAGE FILE.launch [NAME:=VALUE ...]
       run_launch.py [--decider NODE] PATH.launch [NAME:=VALUE ...]
"""
import argparse
import glob
import os
import signal
import sys
import threading
import time

SUCCESS = 0
SCENARIO_FAILED = 1
BAD_INPUT_OR_NODE_DIED = 2
INTERRUPTED = 130  # 128 + SIGINT: what scenario_node returns when stopped

# How long the main thread sleeps between two looks at the launch, as roslaunch's own spin.
POLL_S = 0.1
# How long a finished scenario_node's last /scenario/status may take to arrive after its exit.
STATUS_WAIT_S = 1.0


def node_of(process_name):
    """The node name of a roslaunch process name: `scenario_node-8` -> `scenario_node`."""
    name, _, counter = process_name.rpartition("-")
    return name if name and counter.isdigit() else process_name


class Deaths:
    """The process monitor's ProcessListener: the nodes that ended, in order, with their exit
    codes (None when roslaunch could not tell). Called from the monitor's thread."""

    def __init__(self, decider):
        self.decider = decider
        self.ended = []  # (process name, exit code)
        self._lock = threading.Lock()

    def process_died(self, process_name, exit_code):
        with self._lock:
            self.ended.append((process_name, exit_code))

    def snapshot(self):
        with self._lock:
            return list(self.ended)

    def decider_ended(self):
        return any(node_of(name) == self.decider for name, _ in self.snapshot())

    def launch_should_end(self):
        """Whether the deciding node has ended or another node has died: nothing left to wait for."""
        return self.decider_ended() or any(code != 0 for _, code in self.snapshot())


def describe_death(process_name, exit_code, log_dir):
    """`dialogue_node exited with 2 (log: DIR/dialogue_node-6-stdout.log)`."""
    if exit_code is None:
        how = "ended with an exit code roslaunch could not read"
    elif exit_code < 0:  # Popen's way of saying "killed by this signal"
        how = "was killed by %s" % signal.Signals(-exit_code).name
    else:
        how = "exited with %d" % exit_code
    return "%s %s (log: %s)" % (node_of(process_name), how, log_files(process_name, log_dir))


def log_files(process_name, log_dir):
    """Where roslaunch put the node's output: its files if there are any, else their pattern."""
    pattern = os.path.join(log_dir, process_name + "*.log")
    return ", ".join(sorted(glob.glob(pattern))) or pattern


def verdict(launch, decider, ended, status=None, log_dir=".", stop_signal=0):
    """The exit code and the last line of a launch.

    launch: the launch file's name; decider: the deciding node; ended: (process name, exit code)
    of the nodes that ended, in order; status: the last /scenario/status (its scenario, state,
    finished and reason) or None; stop_signal: the signal that stopped the runner (0: none)."""
    if stop_signal:
        return 128 + stop_signal, "%s interrupted by %s" % (launch,
                                                            signal.Signals(stop_signal).name)
    deaths = []
    decider_end = None
    for name, code in ended:
        if node_of(name) == decider:
            decider_end = (name, code)
            break  # what ended after it, ended because of it
        if code != 0:
            deaths.append(describe_death(name, code, log_dir))
    if deaths:
        return BAD_INPUT_OR_NODE_DIED, "%s: %s" % (launch, "; ".join(deaths))
    if decider_end is None:
        return BAD_INPUT_OR_NODE_DIED, "%s: %s did not end (the launch ended without it)" % (
            launch, decider)
    name, code = decider_end
    said = "%s exited with %s" % (decider, code)
    finished = status is not None and status.finished
    if code == SUCCESS:
        if finished:
            return SUCCESS, "%s succeeded in state %s: %s (%s)" % (
                status.scenario, status.state, status.reason, said)
        return SUCCESS, "%s succeeded (%s)" % (launch, said)
    if code == SCENARIO_FAILED:
        if finished:
            return SCENARIO_FAILED, "%s failed in state %s: %s (%s)" % (
                status.scenario, status.state or "none (the script had not started)",
                status.reason, said)
        return SCENARIO_FAILED, "%s failed (%s; no /scenario/status said why)" % (launch, said)
    if code == INTERRUPTED:
        return INTERRUPTED, "%s interrupted (%s)" % (launch, said)
    # 2 (bad input, a server that never came) or a crash: the node's FATAL line is above.
    return BAD_INPUT_OR_NODE_DIED, "%s: %s" % (launch, describe_death(name, code, log_dir))


class LastStatus:
    """The last /scenario/status a scenario_node published (latched, so a late subscriber gets
    it too), if any: the state and the reason of the end. Only words for the last line; the exit
    code never depends on it."""

    def __init__(self):
        # Imported now, before the launch starts: they take seconds on a busy machine, and a
        # short scenario would be over before the subscriber is.
        import rospy
        from ari_social_sim.msg import ScenarioStatus
        self._rospy = rospy
        self._message_type = ScenarioStatus
        self.message = None

    def start(self):
        """Subscribes, unless the launch has ended already (a node that refused its input at
        once takes the master down with it): then there is no status to hear."""
        rospy = self._rospy
        try:
            rospy.init_node("run_launch", anonymous=True, disable_signals=True,
                            disable_rosout=True)
        except rospy.ROSException:
            return
        rospy.Subscriber("/scenario/status", self._message_type, self._on_status)

    def wait_for_end(self, timeout_s):
        """Gives the final status, sent just before its node exited, time to arrive."""
        deadline = time.monotonic() + timeout_s
        while not (self.message and self.message.finished) and time.monotonic() < deadline:
            time.sleep(0.05)

    def _on_status(self, message):
        self.message = message


def listening_parent(run_id, launch_files, listener):
    """A ROSLaunchParent whose process monitor reports every node's end to `listener`.

    ROSLaunchParent adds its process_listeners only once every node has started, so a node that
    dies sooner (one refusing its parameters) would go unreported; this one adds the listener as
    soon as the process monitor exists, before any node starts."""
    import roslaunch.parent

    class ListeningParent(roslaunch.parent.ROSLaunchParent):
        def _start_pm(self):
            super()._start_pm()
            self.pm.add_process_listener(listener)

    return ListeningParent(run_id, launch_files)


def record_stop_signals():
    """Makes SIGINT and SIGTERM record their number in the list returned before roslaunch's own
    handler (installed once the launch has started) shuts the launch down. The nodes roslaunch
    then kills go unreported, so only this tells an interrupted run. roslaunch's process monitor
    puts its handler back first, calling this one from it."""
    stop_signal = [0]
    for number in (signal.SIGINT, signal.SIGTERM):
        roslaunch_handler = signal.getsignal(number)

        def on_stop(received, frame, roslaunch_handler=roslaunch_handler):
            stop_signal[0] = received
            if callable(roslaunch_handler):
                roslaunch_handler(received, frame)

        signal.signal(number, on_stop)
    return stop_signal


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description="Runs a launch file and exits 0 (success), 1 (the scenario failed), 2 (bad "
                    "input or a node died) or 130 (interrupted).")
    parser.add_argument("--decider", default="scenario_node",
                        help="the node whose exit code is the launch's (default: scenario_node)")
    parser.add_argument("launch", nargs="+",
                        help="PACKAGE FILE.launch or PATH.launch, then NAME:=VALUE arguments")
    options = parser.parse_args(argv)
    files = [word for word in options.launch if ":=" not in word]
    options.launch_args = [word for word in options.launch if ":=" in word]
    return options, files


def run(options, files):
    """Runs the launch to its end; returns (exit code, last line)."""
    import roslaunch
    import roslaunch.rlutil
    import rospkg

    try:
        path = roslaunch.rlutil.resolve_launch_arguments(files)[0]
    except (roslaunch.RLException, IndexError) as error:
        return BAD_INPUT_OR_NODE_DIED, "expected PACKAGE FILE.launch or PATH.launch, got %s " \
            "(%s)" % (" ".join(files), error)
    launch = os.path.basename(path)
    run_id = roslaunch.rlutil.get_or_generate_uuid(None, False)
    roslaunch.configure_logging(run_id)
    deaths = Deaths(options.decider)
    parent = listening_parent(run_id, [(path, options.launch_args)], deaths)
    status = LastStatus()
    try:
        parent.start()
        stop_signal = record_stop_signals()
        if options.decider not in [node.name for node in parent.config.nodes]:
            return BAD_INPUT_OR_NODE_DIED, "%s has no node %s: name the node whose exit code " \
                "decides with --decider" % (launch, options.decider)
        status.start()
        while parent.runner.spin_once() and not deaths.launch_should_end() \
                and not stop_signal[0]:
            time.sleep(POLL_S)
        if deaths.decider_ended():
            status.wait_for_end(STATUS_WAIT_S)
    except (roslaunch.RLException, ValueError, rospkg.ResourceNotFound) as error:
        # An argument or a file the launch refuses (a seed that is no integer, a missing file):
        # nothing ran.
        print(error, file=sys.stderr)
        return BAD_INPUT_OR_NODE_DIED, "roslaunch refused %s (above); no node ran" % launch
    finally:
        parent.shutdown()
    log_dir = os.path.join(rospkg.get_log_dir(), run_id)
    return verdict(launch, options.decider, deaths.snapshot(), status.message, log_dir,
                   stop_signal[0])


def main(argv):
    options, files = parse_arguments(argv)
    code, line = run(options, files)
    print("run_launch: %s: exit code %d" % (line, code), file=sys.stderr, flush=True)
    return code


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
