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
    navigation failed; scenario_node's and social_mpc_node's warnings say why, so theirs come
    first (CI shows only the start of a failure's message). Read from /rosout, where every node
    publishes its log: rostest starts no rosout node, so /rosout_agg stays silent."""

    # The ROS transport's notes when a connection drops as its other end goes (a person who left,
    # a tool that asked once): harmless, frequent with perception:=detectors, and long enough to
    # push the cause out of CI's view. rospy's, then roscpp's.
    IGNORED = ("Could not process inbound connection", "Inbound TCP/IP connection failed")
    # The nodes that say why ARI did not get where it was going.
    FIRST = ("/scenario_node", "/social_mpc_node")

    def __init__(self, keep=8):
        self.lock = threading.Lock()
        self.lines = collections.deque(maxlen=keep)
        self.first_lines = collections.deque(maxlen=keep)
        self.me = rospy.get_name()
        rospy.Subscriber("/rosout", Log, self.on_log, queue_size=100)

    def on_log(self, msg):
        if msg.level < Log.WARN or msg.name == self.me or msg.msg.startswith(self.IGNORED):
            return
        with self.lock:
            lines = self.first_lines if msg.name in self.FIRST else self.lines
            lines.append("%s: %s" % (msg.name, msg.msg))

    def text(self):
        with self.lock:
            lines = list(self.first_lines) + list(self.lines)
        return "; ".join(lines) if lines else "no warnings logged"
