"""Shared by the rostests that play a whole scenario with ~start_world false: start the world
once scenario_node listens, then wait for its outcome; the nodes' warnings for a failure's
message."""
import collections
import threading
import time

import rosgraph
import rospy
from rosgraph_msgs.msg import Log
from std_srvs.srv import SetBool


def unpause_when_scenario_node_listens(caller_id, timeout_s=90.0):
    """Waits until scenario_node subscribes to /sim/world_state (so that the script sees every
    state), then unpauses world_node. Returns whether the unpause succeeded."""
    master = rosgraph.Master(caller_id)
    limit = time.monotonic() + timeout_s
    while time.monotonic() < limit:
        _, subscribers, _ = master.getSystemState()
        if "/scenario_node" in dict(subscribers).get("/sim/world_state", []):
            break
        time.sleep(0.05)
    rospy.wait_for_service("/sim/pause", 30.0)
    return rospy.ServiceProxy("/sim/pause", SetBool)(False).success


def wait_until(recorder, condition, timeout_s):
    """Waits until condition() holds, called under recorder.lock."""
    limit = time.monotonic() + timeout_s
    while time.monotonic() < limit:
        with recorder.lock:
            if condition():
                return
        time.sleep(0.1)


def wait_until_finished(recorder, timeout_s):
    """Waits until recorder.status (a ScenarioStatus, under recorder.lock) says finished."""
    wait_until(recorder, lambda: recorder.status is not None and recorder.status.finished,
               timeout_s)


class NodeWarnings:
    """The last warnings and errors the other nodes logged. A scenario's reason says that ARI's
    navigation failed; social_mpc_node's and scenario_node's warnings say why. Read from /rosout,
    where every node publishes its log: rostest starts no rosout node, so /rosout_agg stays
    silent."""

    # rospy's note when a subscriber reaches a topic its publisher has just dropped (a person
    # who left): harmless, and frequent with perception:=detectors.
    IGNORED = "Could not process inbound connection"

    def __init__(self, keep=8):
        self.lock = threading.Lock()
        self.lines = collections.deque(maxlen=keep)
        self.me = rospy.get_name()
        rospy.Subscriber("/rosout", Log, self.on_log, queue_size=100)

    def on_log(self, msg):
        if msg.level >= Log.WARN and msg.name != self.me and not msg.msg.startswith(self.IGNORED):
            with self.lock:
                self.lines.append("%s: %s" % (msg.name, msg.msg))

    def text(self):
        with self.lock:
            return "; ".join(self.lines) if self.lines else "no warnings logged"
