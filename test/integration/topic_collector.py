"""Shared by the perception rostests: every message of a topic, kept for later checks."""
import threading
import time

import rospy


class Collector:
    """Subscribes to `topic` and keeps every message that arrives, under a lock."""

    def __init__(self, topic, msg_type, queue_size=100):
        self.messages = []
        self._lock = threading.Lock()
        rospy.Subscriber(topic, msg_type, self._on_msg, queue_size=queue_size)

    def _on_msg(self, msg):
        with self._lock:
            self.messages.append(msg)

    def all(self):
        with self._lock:
            return list(self.messages)

    def last(self):
        with self._lock:
            return self.messages[-1] if self.messages else None

    def wait(self, predicate, timeout=30.0, what="a message"):
        """The newest message satisfying `predicate`, waiting up to `timeout` s of wall time."""
        limit = time.monotonic() + timeout
        while time.monotonic() < limit:
            for msg in reversed(self.all()):
                if predicate(msg):
                    return msg
            time.sleep(0.05)
        raise AssertionError("timed out waiting for " + what)
