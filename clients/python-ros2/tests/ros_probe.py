"""A ROS 2 node for tests, written the way a ROS 2 user would: subscriptions with the QoS of the data,
publishers, and the graph; spun in a thread of its own. Every wait is bounded and waits for a state."""

import threading
import time

from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy, qos_profile_sensor_data

RELIABLE = QoSProfile(depth=100, reliability=ReliabilityPolicy.RELIABLE)
LATCHED = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
SENSOR = qos_profile_sensor_data


class RosProbe:
    def __init__(self, name):
        self.node = Node(name)
        self._cv = threading.Condition()
        self.got = {}
        self._executor = SingleThreadedExecutor()
        self._executor.add_node(self.node)
        self._spinning = True
        self._thread = threading.Thread(target=self._spin, daemon=True)
        self._thread.start()

    def _spin(self):
        while self._spinning:
            self._executor.spin_once(timeout_sec=0.05)

    def listen(self, msg_type, topic, qos):
        """Keeps every message of the topic in self.got[topic], with the time it arrived."""
        def take(msg):
            with self._cv:
                self.got.setdefault(topic, []).append((time.time(), msg))
                self._cv.notify_all()
        with self._cv:
            self.got.setdefault(topic, [])
        return self.node.create_subscription(msg_type, topic, take, qos)

    def messages(self, topic):
        with self._cv:
            return [m for _, m in self.got.get(topic, [])]

    def wait_for(self, predicate, timeout_s, what):
        deadline = time.monotonic() + timeout_s
        with self._cv:
            while True:
                value = predicate()
                if value:
                    return value
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    raise AssertionError("waited %.0f s for %s" % (timeout_s, what))
                self._cv.wait(min(remaining, 0.2))

    def topics(self):
        return dict(self.node.get_topic_names_and_types())

    def wait_for_topics(self, wanted, timeout_s):
        """Waits until the graph shows every topic of wanted (name -> type) with that type."""
        deadline = time.monotonic() + timeout_s
        while True:
            have = self.topics()
            missing = {t: ty for t, ty in wanted.items() if ty not in have.get(t, [])}
            if not missing:
                return have
            if time.monotonic() > deadline:
                raise AssertionError("topics missing after %.0f s: %s; the graph has %s" % (timeout_s, missing, have))
            time.sleep(0.1)

    def close(self):
        self._spinning = False
        self._thread.join(5)
        self._executor.shutdown()
        self.node.destroy_node()
