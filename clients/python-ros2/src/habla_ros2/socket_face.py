"""One HABLA socket on ROS 2: a thread that reads it (connecting again with back-off when the link is lost)
and publishes each sample on the output's topic, the socket's state, and the actions its /set topics bring."""

import json
import threading
import time

from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

import habla

from . import mapping, names

READ_WAIT_S = 1.0        # a quiet socket's read wakes this often to keep the connection alive
STREAM_DEPTH = 10        # samples a best-effort stream keeps for a slow subscriber
EVENT_DEPTH = 100        # words, rewards and actions a reliable topic keeps

SENSOR_QOS = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=STREAM_DEPTH, reliability=ReliabilityPolicy.BEST_EFFORT,
                        durability=DurabilityPolicy.VOLATILE)
EVENT_QOS = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=EVENT_DEPTH, reliability=ReliabilityPolicy.RELIABLE,
                       durability=DurabilityPolicy.VOLATILE)
STATE_QOS = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=1, reliability=ReliabilityPolicy.RELIABLE,
                       durability=DurabilityPolicy.TRANSIENT_LOCAL)


def qos_for(output, hello, override=None):
    """Sensor streams (vectors, records, images, audio of a socket that only streams) are best effort; words,
    numbers, and everything of a socket that takes actions are reliable."""
    if override is not None:
        return SENSOR_QOS if override == "best_effort" else EVENT_QOS
    stream = output.kind in ("vector", "record", "image", "audio") and hello.direction == "out"
    return SENSOR_QOS if stream else EVENT_QOS


class SocketFace:
    """The topics of one socket. start() begins reading; close() ends it."""

    def __init__(self, node, system, endpoint, frame_prefix="", qos_override=None, backoff=None):
        self.node, self.system, self.endpoint = node, system, endpoint
        self.topic = names.socket_topic(system, endpoint.name)
        self._frame_prefix = frame_prefix
        self._qos_override = qos_override
        self._log = node.get_logger()
        self._link = habla.Reconnecting(endpoint.host, endpoint.port, backoff=backoff or habla.Backoff(0.2, 5.0),
                                        on_link=self._on_link, client=endpoint.client, token=endpoint.token,
                                        tls=endpoint.tls, timeout=5.0)
        self._lock = threading.Lock()
        self._pubs = {}           # output name -> (carrier, publisher, companion publisher or None)
        self._subs = []
        self._pending = {}        # request id -> value written, until the daemon answers
        self.hello = None
        self.state = {"socket": endpoint.name, "topic": self.topic, "connected": False, "stale": None, "why": "",
                      "samples": 0, "dropped": 0, "actions": 0, "refused": 0, "lastRefusal": None, "commander": None}
        self._state_pub = node.create_publisher(String, self.topic + "/state", STATE_QOS)
        self._thread = threading.Thread(target=self._run, name="face-" + endpoint.name, daemon=True)
        self._closed = False

    def start(self):
        self._publish_state()
        self._thread.start()
        return self

    def close(self):
        self._closed = True
        self._link.close()
        self._thread.join(5.0)

    # -- reading ------------------------------------------------------------------------------------------
    def _run(self):
        while not self._closed:
            try:
                sock = self._link.connect()
            except habla.HablaError as e:   # a bad hello or refused credentials: trying again will not help
                self._log.error("socket %s (%s:%d): %s; not retried" % (self.endpoint.name, self.endpoint.host,
                                                                        self.endpoint.port, e))
                self._update(why=str(e))
                return
            if sock is None:
                return
            self._attach(sock)
            try:
                while True:
                    try:
                        frame = sock.read_frame(READ_WAIT_S)
                    except TimeoutError:
                        sock.keep_alive()
                        continue
                    self._take(frame)
            except (habla.LinkLostError, habla.FrameError) as e:
                self._link.lost(str(e))

    def _attach(self, sock):
        """A new connection: the first one makes the publishers and /set subscriptions from its hello."""
        hello = sock.hello
        with self._lock:
            first = self.hello is None
            self.hello = hello
        if first:
            main = names.main_output(hello.socket, [o.name for o in hello.outputs])
            for output in hello.outputs:
                carrier = mapping.carrier_of(output)
                topic = names.output_topic(self.system, self.endpoint.name, output.name, output.name == main)
                pub = self.node.create_publisher(carrier.msg_type, topic, qos_for(output, hello, self._qos_override))
                companion = None if carrier.stamped else self.node.create_publisher(String, topic + "/sample",
                                                                                   EVENT_QOS)
                self._pubs[output.name] = (carrier, pub, companion)
                self._log.info("%s -> %s [%s]" % (self.endpoint.name, topic, carrier.name))
            for i, inp in enumerate(hello.inputs):
                type_name, msg_type, value_of = mapping.setter_of(inp.kind)
                topic = names.set_topic(self.system, self.endpoint.name, inp.name, i == 0)
                self._subs.append(self.node.create_subscription(
                    msg_type, topic, lambda m, n=inp.name, f=value_of: self._on_set(n, f, m), EVENT_QOS))
                self._log.info("%s <- %s [%s]" % (self.endpoint.name, topic, type_name))
        self._update(connected=True, stale=hello.stale, why="")

    def _take(self, frame):
        kind = frame.get("type")
        if kind == "sample":
            self._publish(habla.Sample(frame))
        elif kind == "stale":
            self._update(stale=bool(frame.get("stale")), why=frame.get("why", ""))
        elif kind == "dropped":
            self._update(dropped=self.state["dropped"] + int(frame.get("count") or 0))
        elif kind == "control":
            self._update(commander=frame.get("holder"))
        elif kind in ("ok", "error") and "id" in frame:
            self._answered(frame)

    def _publish(self, sample):
        entry = self._pubs.get(sample.output)
        if entry is None:
            return
        carrier, pub, companion = entry
        msg = carrier.message(sample, self._frame(carrier))
        if msg is not None:
            pub.publish(msg)
        if companion is not None:
            companion.publish(String(data=mapping.sample_json(sample)))
        with self._lock:
            self.state["samples"] += 1
            stale_changed = sample.stale != self.state["stale"]
        if stale_changed:
            self._update(stale=sample.stale)

    def _frame(self, carrier):
        base = {"nav_msgs/Odometry": "odom", "geometry_msgs/PoseStamped": "odom",
                "sensor_msgs/CompressedImage": "camera"}.get(carrier.name, "base_link")
        return self._frame_prefix + base

    # -- actions ------------------------------------------------------------------------------------------
    def _on_set(self, input_name, value_of, msg):
        try:
            value = value_of(msg)
        except ValueError as e:
            self._refused({"code": "bad_value", "message": "the message is not a value: %s" % e}, None)
            return
        sock = self._link.socket
        if sock is None:
            self._refused({"code": "not_connected", "message": "the socket is not connected"}, value)
            return
        rid = sock.new_id()
        with self._lock:
            self._pending[rid] = value
        try:
            sock.write(value, input=input_name if len(self.hello.inputs) > 1 else None, id=rid)
        except habla.LinkLostError as e:
            with self._lock:
                self._pending.pop(rid, None)
            self._refused({"code": "not_connected", "message": str(e)}, value)

    def _answered(self, frame):
        with self._lock:
            value = self._pending.pop(frame["id"], None)
        if frame["type"] == "ok":
            self._update(actions=self.state["actions"] + 1)
        else:
            self._refused(frame, value)

    def _refused(self, error, value):
        self._log.warn("%s refused %s: %s: %s" % (self.endpoint.name, json.dumps(value), error.get("code"),
                                                 error.get("message")))
        self._update(refused=self.state["refused"] + 1,
                     lastRefusal={"code": error.get("code"), "message": error.get("message"), "value": value,
                                  "at": time.time()})

    # -- state --------------------------------------------------------------------------------------------
    def _on_link(self, up, why):
        if not up:
            self._log.warn("%s: link lost: %s" % (self.endpoint.name, why))
            with self._lock:
                self._pending.clear()
            self._update(connected=False, why=why)

    def _update(self, **changes):
        with self._lock:
            self.state.update(changes)
        self._publish_state()

    def _publish_state(self):
        with self._lock:
            text = json.dumps(self.state, separators=(",", ":"))
        self._state_pub.publish(String(data=text))

    def snapshot(self):
        with self._lock:
            return dict(self.state)
