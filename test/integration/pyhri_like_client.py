"""An HRI listener that behaves as pyhri 0.4.1 does towards the /humans/... topics, for tests:
our own small module written from pyhri's documented behaviour (/tmp/research/
ros4hri_behaviour.md, A1-A4), not a copy of pyhri. What it keeps of pyhri, on purpose:
- The reference frame is base_link; each object gets it when it is created.
- /humans/{faces,bodies,voices}/tracked, /humans/persons/tracked and /known are diffed into
  objects (default rospy queue, header ignored): a new id makes an object, a missing one closes
  it. A person in both persons lists has two independent Person objects.
- A Person subscribes its face_id / body_id / voice_id and accepts a link ONLY if that id is in
  the listener's tracked set when the message arrives; otherwise the link becomes None and the id
  is NOT kept for later: the link comes back only when the id is sent again. This is what makes
  a person manager that sends links only on change lose them.
- The listener is attached to a Person after its subscribers exist (pyhri sets _hrilistener
  after construction); a link arriving in between is dropped (pyhri raises in the callback).
- transform(): tf lookup <reference frame> -> <prefix><id> at Time(0) with a 0.01 s timeout;
  only LookupException is caught (empty TransformStamped), Connectivity/Extrapolation errors
  reach the caller. A Person's transform() is empty while location_confidence is 0.0, its
  default until a location_confidence message arrives.
Extras for tests (not in pyhri): each object records the monotonic time it was created, the
listener when each id first appeared, and a log of every link message each person id received
(what was received, what was kept, or that it was dropped).
"""
import time

import rospy
import tf2_ros
from geometry_msgs.msg import TransformStamped
from std_msgs.msg import Bool, Float32, String

from ari_social_sim.msg import (EngagementLevel, IdsList, LiveSpeech,
                                NormalizedRegionOfInterest2D, SoftBiometrics)

TF_TIMEOUT = rospy.Duration(0.01)
DROPPED = "DROPPED"


class _Feature:
    """What faces, bodies and voices share: id, tf frame, subscriptions, validity."""
    prefix = ""
    kind = ""

    def __init__(self, feature_id, tf_buffer, reference_frame):
        self.id = feature_id
        self.valid = True
        self.created_at = time.monotonic()
        self._tf = tf_buffer
        self._reference_frame = reference_frame
        self._ns = "/humans/%s/%s/" % (self.kind, feature_id)
        self._subscribers = []

    def _subscribe(self, topic, msg_type, callback):
        self._subscribers.append(rospy.Subscriber(self._ns + topic, msg_type, callback))

    def frame(self):
        return self.prefix + self.id

    def transform(self, from_frame=None):
        try:
            return self._tf.lookup_transform(from_frame or self._reference_frame, self.frame(),
                                             rospy.Time(0), TF_TIMEOUT)
        except tf2_ros.LookupException as e:
            rospy.logwarn("pyhri_like_client: no transform %s -> %s: %s",
                          from_frame or self._reference_frame, self.frame(), e)
            return TransformStamped()

    def close(self):
        self.valid = False
        for subscriber in self._subscribers:
            subscriber.unregister()


class Face(_Feature):
    prefix, kind = "face_", "faces"

    def __init__(self, *args):
        super().__init__(*args)
        self.roi = None
        self.softbiometrics = None
        self._subscribe("roi", NormalizedRegionOfInterest2D, lambda m: setattr(self, "roi", m))
        self._subscribe("softbiometrics", SoftBiometrics,
                        lambda m: setattr(self, "softbiometrics", m))

    def gaze_transform(self, from_frame=None):
        try:
            return self._tf.lookup_transform(from_frame or self._reference_frame,
                                             "gaze_" + self.id, rospy.Time(0), TF_TIMEOUT)
        except tf2_ros.LookupException:
            return TransformStamped()


class Body(_Feature):
    prefix, kind = "body_", "bodies"

    def __init__(self, *args):
        super().__init__(*args)
        self.roi = None
        self._subscribe("roi", NormalizedRegionOfInterest2D, lambda m: setattr(self, "roi", m))


class Voice(_Feature):
    prefix, kind = "voice_", "voices"

    def __init__(self, *args):
        super().__init__(*args)
        self.is_speaking = False
        self.speech = ""
        self.incremental_speech = ""
        self._subscribe("is_speaking", Bool, lambda m: setattr(self, "is_speaking", m.data))
        self._subscribe("speech", LiveSpeech, self._on_speech)

    def _on_speech(self, msg):
        if msg.incremental:
            self.incremental_speech = msg.incremental
        if msg.final:
            self.speech = msg.final


class Person:
    def __init__(self, person_id, tf_buffer, reference_frame, link_log=None):
        self.id = person_id
        self.valid = True
        self.created_at = time.monotonic()
        self._tf = tf_buffer
        self._reference_frame = reference_frame
        self._hrilistener = None  # set by the listener after construction, as in pyhri
        self.face_id = self.body_id = self.voice_id = None
        self.face = self.body = self.voice = None
        self.anonymous = False
        self.alias = None  # stored, never resolved
        self.engagement_status = None  # the level, an int
        self.loc_confidence = 0.0
        # Test aid: (monotonic time, kind, id received, id kept or DROPPED), shared by every
        # Person object the listener makes for this id.
        self.link_log = [] if link_log is None else link_log
        ns = "/humans/persons/%s/" % person_id
        self._subscribers = [
            rospy.Subscriber(ns + "face_id", String, self._on_link, callback_args="face"),
            rospy.Subscriber(ns + "body_id", String, self._on_link, callback_args="body"),
            rospy.Subscriber(ns + "voice_id", String, self._on_link, callback_args="voice"),
            rospy.Subscriber(ns + "anonymous", Bool, lambda m: setattr(self, "anonymous", m.data)),
            rospy.Subscriber(ns + "alias", String, lambda m: setattr(self, "alias", m.data)),
            rospy.Subscriber(ns + "engagement_status", EngagementLevel,
                             lambda m: setattr(self, "engagement_status", m.level)),
            rospy.Subscriber(ns + "location_confidence", Float32,
                             lambda m: setattr(self, "loc_confidence", m.data)),
        ]

    def _on_link(self, msg, kind):
        listener = self._hrilistener
        if listener is None:
            # pyhri: AttributeError inside the callback, the message is lost
            self.link_log.append((time.monotonic(), kind, msg.data, DROPPED))
            return
        tracked = {"face": listener._faces, "body": listener._bodies, "voice": listener._voices}
        feature = tracked[kind].get(msg.data) if msg.data else None
        # Resolved once, now: an id not tracked at this instant is forgotten.
        setattr(self, kind + "_id", msg.data if feature is not None else None)
        setattr(self, kind, feature)
        self.link_log.append((time.monotonic(), kind, msg.data, getattr(self, kind + "_id")))

    def transform(self):
        if self.loc_confidence == 0.0:
            return TransformStamped()
        try:
            return self._tf.lookup_transform(self._reference_frame, "person_" + self.id,
                                             rospy.Time(0), TF_TIMEOUT)
        except tf2_ros.LookupException as e:
            rospy.logwarn("pyhri_like_client: no transform for person %s: %s", self.id, e)
            return TransformStamped()

    def close(self):
        self.valid = False
        for subscriber in self._subscribers:
            subscriber.unregister()


class HRIListener:
    def __init__(self, reference_frame="base_link"):
        self._reference_frame = reference_frame
        self.tf_buffer = tf2_ros.Buffer()
        self.tf_listener = tf2_ros.TransformListener(self.tf_buffer)
        self._faces, self._bodies, self._voices = {}, {}, {}
        self._tracked_persons, self._known_persons = {}, {}
        # Test aids: ("faces", "bodies", "voices", "tracked" or "known", id) -> monotonic time
        # the id first appeared in that list; ("tracked" or "known", person id) -> the link
        # log of all the Person objects made for it.
        self.first_seen = {}
        self.link_logs = {}
        self.list_log = []  # (monotonic time, list, "+" or "-", id)
        self._subscribers = [
            rospy.Subscriber(topic, IdsList, self._update, (objects, factory, which))
            for topic, objects, factory, which in (
                ("/humans/faces/tracked", self._faces, Face, "faces"),
                ("/humans/bodies/tracked", self._bodies, Body, "bodies"),
                ("/humans/voices/tracked", self._voices, Voice, "voices"),
                ("/humans/persons/tracked", self._tracked_persons, Person, "tracked"),
                ("/humans/persons/known", self._known_persons, Person, "known"))]

    def set_reference_frame(self, frame):
        """Applies to objects created from now on only, as in pyhri."""
        self._reference_frame = frame

    def _update(self, msg, args):
        objects, factory, which = args
        ids = set(msg.ids)
        for gone in [i for i in objects if i not in ids]:
            objects.pop(gone).close()
            self.list_log.append((time.monotonic(), which, "-", gone))
        for new in [i for i in msg.ids if i not in objects]:
            self.list_log.append((time.monotonic(), which, "+", new))
            if factory is Person:
                obj = Person(new, self.tf_buffer, self._reference_frame,
                             self.link_logs.setdefault((which, new), []))
                obj._hrilistener = self  # after its subscribers exist, as pyhri does
            else:
                obj = factory(new, self.tf_buffer, self._reference_frame)
            self.first_seen.setdefault((which, new), obj.created_at)
            objects[new] = obj

    # Copies, so that a caller may iterate while the callbacks update the dicts.
    @property
    def faces(self):
        return dict(self._faces)

    @property
    def bodies(self):
        return dict(self._bodies)

    @property
    def voices(self):
        return dict(self._voices)

    @property
    def tracked_persons(self):
        return dict(self._tracked_persons)

    @property
    def known_persons(self):
        return dict(self._known_persons)

    def close(self):
        for subscriber in self._subscribers:
            subscriber.unregister()
        for objects in (self._faces, self._bodies, self._voices, self._tracked_persons,
                        self._known_persons):
            for obj in objects.values():
                obj.close()
            objects.clear()
