#!/usr/bin/python3
"""rostest: a client that behaves as pyhri 0.4.1 (pyhri_like_client.py) against
world_perception.launch on scenes/perception_demo.yaml, started once perception has run for a
few seconds, as a user's node would be:
  - every tracked body, face and person (location_confidence > 0) has a transform to base_link;
  - every tracked person whose body is tracked is linked to that body within 1 s of the client
    starting, of both appearing in the client's lists (they flicker with the error models on),
    or of the link topic's first message reaching the client, whichever is last; and still
    linked, to the live Body object, at the end.
pyhri resolves a person's body_id only when the message arrives, and only if the body is then in
its tracked set: a person manager that sends links only on change loses some of them.
Repeat it with scripts/repeat_rostest.sh 10 pyhri_client.test."""
import time
import unittest

import rospy
import rostest
import tf2_ros
from std_msgs.msg import String

from ari_social_sim.msg import IdsList
from pyhri_like_client import DROPPED, HRIListener

WARM_UP_S = 4.0      # wall time perception runs before the client starts
OBSERVE_S = 3.0      # wall time the client runs before the checks
LINK_DEADLINE_S = 1.0
EMPTY_LIST_WAIT_S = 2.0  # wall time to look again while a tracked list is empty


def resolved(transform):
    return bool(transform.child_frame_id)


class PyhriClient(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("pyhri_client_test")
        rospy.wait_for_message("/humans/bodies/tracked", IdsList, timeout=60)
        time.sleep(WARM_UP_S)
        cls.start = time.monotonic()
        cls.hri = HRIListener()  # reference frame base_link, as pyhri's default
        time.sleep(OBSERVE_S)

    def test_bodies_faces_and_persons_resolve_to_base_link(self):
        # A tracked list is empty in a frame its detector missed, as hri_face_detect's is (one
        # missed frame drops a face): Marie's face, 1.3 m away, is missed in about 8 % of frames.
        # Look again, as a client would, until every kind lists something or EMPTY_LIST_WAIT_S.
        limit = time.monotonic() + EMPTY_LIST_WAIT_S
        while True:
            counts, failures = self.resolve_to_base_link()
            if all(total for _, total in counts.values()) or time.monotonic() > limit:
                break
            time.sleep(0.05)
        print("[ measured ] transforms to base_link: " + ", ".join(
            "%s %d/%d" % (kind, ok, total) for kind, (ok, total) in counts.items()))
        for kind, (ok, total) in counts.items():
            self.assertGreater(total, 0, "no tracked %s with a location" % kind)
        if failures:
            self.fail("unresolved: " + "; ".join(failures))

    def resolve_to_base_link(self):
        """(counts, failures): per kind, how many tracked objects resolve to base_link of how
        many, and each that does not, with why."""
        counts = {}
        failures = []

        def check(kind, objects, wanted=lambda obj: True):
            ok = total = 0
            for obj in objects.values():
                if not wanted(obj):
                    continue
                total += 1
                try:
                    good = resolved(obj.transform())
                    reason = "LookupException"
                except (tf2_ros.ConnectivityException, tf2_ros.ExtrapolationException) as e:
                    good, reason = False, type(e).__name__ + ": " + str(e)
                ok += good
                if not good:
                    failures.append("%s %s: %s" % (kind, obj.id, reason))
            counts[kind] = (ok, total)

        check("body", self.hri.bodies)
        check("face", self.hri.faces)
        check("person", self.hri.tracked_persons, lambda p: p.loc_confidence > 0.0)
        return counts, failures

    def test_tracked_persons_are_linked_to_their_tracked_body_within_1s(self):
        end = time.monotonic()
        persons = sorted(self.hri.tracked_persons)
        self.assertTrue(persons, "no tracked persons")
        checked, failures, all_delays, from_start = 0, [], [], []
        for person_id in persons:
            # What perception says the body is: the latched link, read independently.
            body_id = rospy.wait_for_message("/humans/persons/%s/body_id" % person_id, String,
                                             timeout=5).data
            if not body_id or body_id not in self.hri.bodies:
                print("[ measured ] %s: body '%s' not tracked, not checked" % (person_id, body_id))
                continue
            checked += 1
            log = [e for e in self.hri.link_logs.get(("tracked", person_id), []) if e[1] == "body"]
            refused = sum(1 for _, _, got, kept in log if got == body_id and kept is None)
            dropped = sum(1 for _, _, got, kept in log if got == body_id and kept == DROPPED)
            why = "%d body_id messages, %d '%s' refused (body not in the client's list yet), " \
                  "%d dropped (Person not attached to the listener yet)" % (
                      len(log), refused, body_id, dropped)
            # Tracked lists flicker (error models on): the person and its body are both in the
            # client's lists over several intervals, each starting with a fresh Person or Body
            # object. In each, the link must be made within the deadline of the link data
            # reaching the client: of the interval's start, or of the first body_id message if
            # later. (A client making ~90 subscriptions at once may wait 1 s for some of them to
            # connect: roscpp's XML-RPC server listens with a backlog of 5 and a dropped SYN is
            # re-sent after 1 s, or 3 s. That is ROS 1's, not the perception's; it is printed
            # apart, and an interval in which no body_id message arrived is not judged.)
            delays, missed, short, silent, first = [], [], 0, 0, None
            for begin, finish in self.together(person_id, body_id, end):
                arrivals = [t for t, _, _, _ in log if begin <= t < finish]
                if not arrivals:
                    silent += 1  # its subscription not connected yet
                    continue
                origin = max(begin, arrivals[0])
                links = [t for t, _, _, kept in log if kept == body_id and begin <= t < finish]
                if links:
                    delays.append(links[0] - origin)
                    if first is None:
                        first = (links[0] - max(begin, self.start), origin - begin)
                elif finish - origin >= LINK_DEADLINE_S:
                    missed.append("%+.2f..%+.2f s" % (begin - self.start, finish - self.start))
                else:
                    short += 1
            all_delays += delays
            if first:
                from_start.append(first[0])
            print("[ measured ] %s -> body %s: linked in %d of %d intervals in both lists, "
                  "%s s after the link data arrived (%d too short to tell, %d without link data "
                  "yet, %d never linked); first link %s; %s"
                  % (person_id, body_id, len(delays), len(delays) + len(missed) + short + silent,
                     "/".join("%.3f" % d for d in delays) or "-", short, silent, len(missed),
                     "%.3f s after the client started (link topic silent for its first %.3f s)"
                     % first if first else "never", why))
            late = [round(d, 3) for d in delays if d > LINK_DEADLINE_S]
            if missed or late or not delays:
                failures.append("%s -> %s: %s%s%s (%s)" % (
                    person_id, body_id, "never linked while both tracked %s " % missed
                    if missed else "", "linked %s s after the data arrived " % late
                    if late else "", "never linked" if not delays and not missed else "", why))
            # And linked at the end, to the live Body object (pyhri keeps a closed one, or None,
            # until body_id is sent again).
            limit = time.monotonic() + LINK_DEADLINE_S
            while not self.linked_now(person_id, body_id) and time.monotonic() < limit:
                time.sleep(0.01)
            if not self.linked_now(person_id, body_id):
                failures.append("%s -> %s: not linked to the live body at the end (%s)"
                                % (person_id, body_id, why))
        if all_delays:
            print("[ measured ] %d persons checked; link delays after the data arrived: median "
                  "%.3f s, max %.3f s over %d intervals; first links %.3f-%.3f s after the "
                  "client started (%d of %d within %.0f s)"
                  % (checked, sorted(all_delays)[len(all_delays) // 2], max(all_delays),
                     len(all_delays), min(from_start), max(from_start),
                     sum(d <= LINK_DEADLINE_S for d in from_start), len(from_start),
                     LINK_DEADLINE_S))
        self.assertGreater(checked, 0, "no tracked person has a tracked body")
        if failures:
            self.fail("links missing, late or stale: " + "; ".join(failures))

    def together(self, person_id, body_id, end):
        """The (begin, end) monotonic intervals in which the client had both the tracked person
        and the body in its lists."""
        present = {"tracked": False, "bodies": False}
        intervals, begin = [], None
        for t, which, op, item in list(self.hri.list_log):
            if t > end or (which, item) not in (("tracked", person_id), ("bodies", body_id)):
                continue
            was_together = all(present.values())
            present[which] = op == "+"
            if all(present.values()) and not was_together:
                begin = t
            elif was_together and not all(present.values()):
                intervals.append((begin, t))
        if all(present.values()):
            intervals.append((begin, end))
        return intervals

    def linked_now(self, person_id, body_id):
        person = self.hri.tracked_persons.get(person_id)
        body = self.hri.bodies.get(body_id)
        return person is not None and body is not None and person.body is body


if __name__ == "__main__":
    rostest.rosrun("ari_social_sim", "pyhri_client", PyhriClient)
