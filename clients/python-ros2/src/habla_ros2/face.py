"""habla-ros2 face CONFIG: every socket a daemon exposes, as ROS 2 topics under /habla/<system>/<socket>.

Per socket: its outputs' topics (types and QoS in mapping.py and socket_face.py), <socket>/state (a JSON
String, latched: connected, stale, counts, the last refusal), and <socket>/set for its control inputs.
/diagnostics carries one status per socket (OK, WARN while stale, ERROR while not connected) once a second.
"""

import rclpy
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus, KeyValue
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node

from . import names
from .daemon_config import DaemonConfig
from .socket_face import EVENT_QOS, SocketFace

DIAGNOSTICS_PERIOD_S = 1.0


class Face(Node):
    """The face of one daemon: a SocketFace per exposed socket and the diagnostics."""

    def __init__(self, config, only=None, frame_prefix="", qos=None):
        super().__init__("habla_face_" + names.token(config.system))
        self.config = config
        self.faces = [SocketFace(self, config.system, e, frame_prefix, (qos or {}).get(e.name))
                      for e in config.endpoints(only)]
        self._diag = self.create_publisher(DiagnosticArray, "/diagnostics", EVENT_QOS)
        self.create_timer(DIAGNOSTICS_PERIOD_S, self._diagnose)
        for f in self.faces:
            f.start()

    def _diagnose(self):
        msg = DiagnosticArray()
        msg.header.stamp = self.get_clock().now().to_msg()
        for f in self.faces:
            s = f.snapshot()
            st = DiagnosticStatus(name="habla/%s/%s" % (self.config.system, s["socket"]), hardware_id=self.config.system)
            if not s["connected"]:
                st.level, st.message = DiagnosticStatus.ERROR, "not connected: " + (s["why"] or "connecting")
            elif s["stale"]:
                st.level, st.message = DiagnosticStatus.WARN, "stale: " + (s["why"] or "a link it depends on is down")
            else:
                st.level, st.message = DiagnosticStatus.OK, "ok"
            st.values = [KeyValue(key=k, value=str(s[k])) for k in ("topic", "samples", "dropped", "actions", "refused")]
            msg.status.append(st)
        self._diag.publish(msg)

    def close(self):
        for f in self.faces:
            f.close()


def run(args):
    config = DaemonConfig(args.config, host=args.host, credentials=args.credentials, tls_trust=args.tls_trust)
    qos = dict(item.split("=", 1) for item in args.qos or [])
    for name, value in qos.items():
        if value not in ("reliable", "best_effort"):
            raise SystemExit("habla-ros2 face: --qos %s=%s: the QoS is reliable or best_effort" % (name, value))
    rclpy.init()
    face = Face(config, only=set(args.sockets.split(",")) if args.sockets else None, frame_prefix=args.frame_prefix,
                qos=qos)
    face.get_logger().info("the face of %s: %d sockets under %s/%s" % (
        config.path, len(face.faces), names.ROOT, names.token(config.system)))
    try:
        rclpy.spin(face)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        face.close()
        face.destroy_node()
        rclpy.try_shutdown()
    return 0


def add_arguments(p):
    p.add_argument("config", help="the daemon's config file (its exposed sockets, system name and security)")
    p.add_argument("--host", help="the daemon's address (default: each socket's bind address, 127.0.0.1 for a wildcard)")
    p.add_argument("--sockets", help="only these sockets, comma-separated (default: every exposed socket)")
    p.add_argument("--credentials", help="a credentials file instead of the config's security.credentials")
    p.add_argument("--tls-trust", help="the certificate to trust for TLS sockets (default: the config's certificate)")
    p.add_argument("--frame-prefix", default="", help="put before the frame ids odom, base_link, camera")
    p.add_argument("--qos", action="append", metavar="SOCKET=reliable|best_effort",
                   help="the QoS of a socket's topics instead of the one its shape gives")
