#!/usr/bin/python3
"""A small stand-in for ROS4HRI's hri_person_manager 1.1.0 (ROS 1), written from its documented
behaviour (README, doc/ALGORITHM.md; our notes in /tmp/research/ros4hri_behaviour.md, section B),
not from its code: the project may not contain third-party code. It lets the tests run
hri_perception_node in `~mode detectors` (faces, bodies, voices and candidate matches only) and
still get persons, the way ARI's real stack would make them.

What it does, and where it is simpler than the real node:
- Feature nodes (face/body/voice) exist while their id is in /humans/<kind>/tracked; an id that
  leaves its list takes its edges with it. Person nodes are made by a PERSON match naming a
  feature that exists, and stay forever (named persons are never forgotten).
- /humans/candidate_matches: confidence <= 0 removes the edge, else sets it. A match naming a
  feature that is not (yet) tracked is ignored (the real node's features_from_matches = false).
  Edges below /humans/match_threshold are dropped for good, as the real node prunes them.
- Every 100 ms (sim time), queued events are applied in arrival order, then the associations are
  computed. SIMPLIFICATION: the real node searches each connected component for the partition
  into the fewest sub-graphs with at most one node of each type and the highest likelihood; here
  a greedy union-find takes the edges from the most to the least confident and refuses any union
  that would put two nodes of one type (two faces, two persons, ...) together. On the small
  graphs perception makes (one face-body-voice chain per human) both give the same answer.
- An association without a person gets `anonymous_person_<5 letters a-j>`, derived from a hash
  of its alphabetically first feature id, and keeps that id while any of its features stays in
  it. It is dropped (topics shut down, out of /known) when its association goes.
- Per person: face_id / body_id / voice_id latched and re-sent EVERY cycle ("" when none), as
  the real node does (pyhri needs it); anonymous latched once.
- DEVIATION location_confidence: the real node publishes it unlatched and only when it changes,
  so a late subscriber never sees it (and pyhri then refuses Person.transform()). Here it is
  published every cycle: 1.0 while tracked, still 1.0 for 10 s after the person's last feature
  went (what the real node's integer arithmetic gives), then 0.0.
- tf person_<id> in /humans/reference_frame (default map), copied from face_<face_id>, else
  head_<body_id>, else voice_<voice_id>, looked up at Time(0) and re-stamped now; the last one is
  re-broadcast while location_confidence > 0. DEVIATIONS: when a frame is missing the next best
  is used (and body_<body_id> after head_<body_id>, for a perception without head frames), where
  the real node publishes nothing new; and the real node names an anonymous person's frame by its
  bare id while pyhri/libhri look up person_<id>, so every person's frame here is person_<id>.
- /humans/persons/tracked and /known: latched, stamped now, sent when they change (and once at
  start, so a latched subscriber always finds a list).
Not done: aliases (PERSON-PERSON matches), proxemics, /humans/graph, the reset service.
"""
import hashlib
import threading

import rospy
import tf2_ros
from std_msgs.msg import Bool, Float32, Header, String

from ari_social_sim.msg import IdsList, IdsMatch

PERSON, FACE, BODY, VOICE = IdsMatch.PERSON, IdsMatch.FACE, IdsMatch.BODY, IdsMatch.VOICE
FEATURE_KINDS = {FACE: "faces", BODY: "bodies", VOICE: "voices"}
# Where a person is, best first: its face, its body's head (as the real node; body_ when a
# perception publishes no head_ frames), its voice.
SOURCE_FRAMES = ((FACE, "face_"), (BODY, "head_"), (BODY, "body_"), (VOICE, "voice_"))
LINK_TOPIC = {FACE: "face_id", BODY: "body_id", VOICE: "voice_id"}
LIFETIME_UNTRACKED_S = 10.0
ANONYMOUS_PREFIX = "anonymous_person_"
MATCH = "match"  # the event kind of a candidate match (rospy ignores callback_args=None)


def hash_letters(text):
    """Five letters a-j from a stable hash of `text` (the decimal digits of its SHA-1), so that
    the same first feature always gives the same anonymous person."""
    digits = str(int(hashlib.sha1(text.encode()).hexdigest(), 16))
    return "".join(chr(ord("a") + int(d)) for d in digits[:5])


class PersonManagerStandin:
    def __init__(self):
        self.threshold = rospy.get_param("/humans/match_threshold", 0.5)
        self.reference_frame = rospy.get_param("/humans/reference_frame", "map")
        # Graph: nodes are (type, id) so that a face and a body may share an id string.
        self.features = set()         # tracked (type, id)
        self.person_nodes = set()     # (PERSON, id) made by matches; never removed
        self.edges = {}               # frozenset({node, node}) -> confidence
        self.anonymous_of = {}        # feature node -> anonymous person id it belongs to
        self.persons = {}             # person id -> ManagedPerson (what we publish)
        self.sent_tracked = self.sent_known = None
        # Callbacks only queue events; the loop applies them in arrival order, as the real node.
        self.events = []
        self.lock = threading.Lock()
        self.tf_buffer = tf2_ros.Buffer()
        self.tf_listener = tf2_ros.TransformListener(self.tf_buffer)
        self.tf_broadcaster = tf2_ros.TransformBroadcaster()
        self.tracked_pub = rospy.Publisher("/humans/persons/tracked", IdsList, queue_size=1,
                                           latch=True)
        self.known_pub = rospy.Publisher("/humans/persons/known", IdsList, queue_size=1,
                                         latch=True)
        for kind_type, kind in FEATURE_KINDS.items():
            rospy.Subscriber("/humans/%s/tracked" % kind, IdsList, self.queue_event,
                             callback_args=kind_type, queue_size=10)
        # Larger than the real node's 10: perception sends several matches per frame and a
        # rospy callback must not drop any of them.
        rospy.Subscriber("/humans/candidate_matches", IdsMatch, self.queue_event,
                         callback_args=MATCH, queue_size=200)

    def queue_event(self, msg, kind_type):
        with self.lock:
            self.events.append((kind_type, msg))

    # --- graph updates -------------------------------------------------------------------
    def apply_tracked(self, kind_type, ids):
        current = {node for node in self.features if node[0] == kind_type}
        now = {(kind_type, i) for i in ids}
        self.features |= now
        for gone in current - now:
            self.features.discard(gone)
            self.anonymous_of.pop(gone, None)
            self.edges = {e: c for e, c in self.edges.items() if gone not in e}

    def apply_match(self, m):
        a, b = (m.id1_type, m.id1), (m.id2_type, m.id2)
        valid_types = (PERSON, FACE, BODY, VOICE)
        if not m.id1 or not m.id2 or m.id1 == m.id2 or m.id1_type not in valid_types \
                or m.id2_type not in valid_types:
            rospy.logerr("person_manager_standin: invalid match %s/%d - %s/%d",
                         m.id1, m.id1_type, m.id2, m.id2_type)
            return
        if a[0] == PERSON and b[0] == PERSON:
            rospy.logwarn_once("person_manager_standin: person-person matches (aliases) ignored")
            return
        # Features come from the tracked lists only (features_from_matches = false).
        if any(n[0] != PERSON and n not in self.features for n in (a, b)):
            return
        edge = frozenset((a, b))
        if m.confidence <= 0.0:
            self.edges.pop(edge, None)
            return
        for node in (a, b):
            if node[0] == PERSON:
                self.person_nodes.add(node)
        if m.confidence < self.threshold:
            self.edges.pop(edge, None)  # pruned for good, even if it was confident before
        else:
            self.edges[edge] = m.confidence

    # --- associations --------------------------------------------------------------------
    def associations(self):
        """Lists of nodes, at most one of each type, joined by their most confident edges."""
        nodes = sorted(self.features | self.person_nodes)
        root = {n: n for n in nodes}
        types = {n: {n[0]} for n in nodes}

        def find(n):
            while root[n] != n:
                root[n] = root[root[n]]
                n = root[n]
            return n

        for edge, _ in sorted(self.edges.items(), key=lambda ec: (-ec[1], sorted(ec[0]))):
            ra, rb = (find(n) for n in sorted(edge))
            if ra != rb and not types[ra] & types[rb]:
                root[rb] = ra
                types[ra] |= types.pop(rb)
        groups = {}
        for n in nodes:
            groups.setdefault(find(n), []).append(n)
        return list(groups.values())

    def name_anonymous(self, features, taken):
        """Reuses the anonymous id of any of `features`, else derives one from the first id."""
        by_id = sorted(features, key=lambda n: (n[1], n[0]))
        for n in by_id:
            previous = self.anonymous_of.get(n)
            if previous and previous not in taken:
                return previous
        salt = ""
        while True:  # a hash collision between two associations: derive another one
            candidate = ANONYMOUS_PREFIX + hash_letters(by_id[0][1] + salt)
            if candidate not in taken:
                return candidate
            salt += "+"

    # --- the 10 Hz cycle -----------------------------------------------------------------
    def cycle(self, now, dt):
        with self.lock:
            events, self.events = self.events, []
        for kind_type, msg in events:
            if kind_type == MATCH:
                self.apply_match(msg)
            else:
                self.apply_tracked(kind_type, msg.ids)

        links = {}  # person id -> ({type: feature id}, anonymous)
        taken = {n[1] for n in self.person_nodes}
        anonymous_of = {}
        for group in self.associations():
            person = next((n[1] for n in group if n[0] == PERSON), None)
            features = [n for n in group if n[0] != PERSON]
            anonymous = person is None
            if anonymous:
                person = self.name_anonymous(features, taken)
                anonymous_of.update((n, person) for n in features)
            taken.add(person)
            links[person] = ({n[0]: n[1] for n in features}, anonymous)
        self.anonymous_of = anonymous_of

        for person_id in [p for p in self.persons if p not in links]:
            self.persons.pop(person_id).shutdown()  # an anonymous person whose features went
        for person_id, (features, anonymous) in sorted(links.items()):
            managed = self.persons.get(person_id)
            if managed is None:
                managed = self.persons[person_id] = ManagedPerson(person_id, anonymous)
            managed.update(features, now, dt, self)

        tracked = sorted(p for p, m in self.persons.items() if m.tracked)
        known = sorted(self.persons)
        if tracked != self.sent_tracked:
            self.tracked_pub.publish(IdsList(ids=tracked, header=Header(stamp=now)))
            self.sent_tracked = tracked
        if known != self.sent_known:
            self.known_pub.publish(IdsList(ids=known, header=Header(stamp=now)))
            self.sent_known = known

    def spin(self):
        rate = rospy.Rate(10)
        last = rospy.Time.now()
        while not rospy.is_shutdown():
            try:
                rate.sleep()
            except rospy.ROSTimeMovedBackwardsException:
                last = rospy.Time.now()  # the world was reset: start counting again
                continue
            except rospy.ROSInterruptException:
                break
            now = rospy.Time.now()
            self.cycle(now, max(0.0, (now - last).to_sec()))
            last = now


class ManagedPerson:
    """The topics and tf frame of one person, as the real node's ManagedPerson keeps them."""

    def __init__(self, person_id, anonymous):
        ns = "/humans/persons/%s/" % person_id
        self.id = person_id
        self.frame = "person_" + person_id
        self.links = {t: rospy.Publisher(ns + topic, String, queue_size=1, latch=True)
                      for t, topic in LINK_TOPIC.items()}
        self.anonymous = rospy.Publisher(ns + "anonymous", Bool, queue_size=1, latch=True)
        self.anonymous.publish(Bool(data=anonymous))
        self.confidence_pub = rospy.Publisher(ns + "location_confidence", Float32, queue_size=1)
        self.tracked = False
        self.unseen_s = 0.0
        self.confidence = 0.0
        self.last_transform = None
        self.last_stamp = None

    def update(self, features, now, dt, manager):
        for kind_type, publisher in self.links.items():
            publisher.publish(String(data=features.get(kind_type, "")))
        self.tracked = bool(features)
        if self.tracked:
            self.unseen_s = 0.0
            self.confidence = 1.0
            # The best located feature: a face, else a body, else a voice.
            for kind_type, prefix in SOURCE_FRAMES:
                if kind_type not in features:
                    continue
                try:
                    self.last_transform = manager.tf_buffer.lookup_transform(
                        manager.reference_frame, prefix + features[kind_type], rospy.Time(0))
                    break
                except (tf2_ros.LookupException, tf2_ros.ConnectivityException,
                        tf2_ros.ExtrapolationException):
                    pass  # not there (yet): the next best, else keep the last one, if any
        else:
            self.unseen_s += dt
            self.confidence = 1.0 if self.unseen_s < LIFETIME_UNTRACKED_S else 0.0
        self.confidence_pub.publish(Float32(data=self.confidence))
        # Re-stamped now, once per stamp (a paused clock would repeat it and tf2 complains).
        if self.confidence > 0.0 and self.last_transform is not None and now != self.last_stamp:
            t = self.last_transform
            t.header.stamp = now
            t.header.frame_id = manager.reference_frame
            t.child_frame_id = self.frame
            manager.tf_broadcaster.sendTransform(t)
            self.last_stamp = now

    def shutdown(self):
        for publisher in list(self.links.values()) + [self.anonymous, self.confidence_pub]:
            publisher.unregister()


if __name__ == "__main__":
    rospy.init_node("hri_person_manager")
    PersonManagerStandin().spin()
