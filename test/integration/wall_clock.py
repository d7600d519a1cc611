"""Waits on the wall clock, for tests of a node that owns sim time: a test that waited on sim time
would hang with the node it tests."""
import time


def wait_wall(predicate, timeout_s, poll_s=0.002):
    """True as soon as predicate() is, else predicate()'s value after timeout_s of wall time."""
    limit = time.monotonic() + timeout_s
    while time.monotonic() < limit:
        if predicate():
            return True
        time.sleep(poll_s)
    return predicate()
