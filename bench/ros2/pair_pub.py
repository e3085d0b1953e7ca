"""The bench's plain ROS 2 pair, publisher side: std_msgs/String messages carrying the time they were made, on
N topics at a fixed rate, with the QoS the face gives a sensor stream.
    python pair_pub.py TOPICS HZ SECONDS"""

import json
import sys
import time

import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

QOS = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=10, reliability=ReliabilityPolicy.BEST_EFFORT,
                 durability=DurabilityPolicy.VOLATILE)


def main(topics, hz, seconds):
    rclpy.init()
    node = Node("bench_pair_pub")
    pubs = [node.create_publisher(String, "/bench/pair/c%d" % i, QOS) for i in range(topics)]
    deadline = time.monotonic() + 30
    while any(p.get_subscription_count() == 0 for p in pubs) and time.monotonic() < deadline:
        time.sleep(0.05)
    print("matched", flush=True)
    time.sleep(0.5)
    period, start, n = 1.0 / hz, time.monotonic(), 0
    sent = [0] * topics
    while time.monotonic() - start < seconds:
        delay = start + n * period - time.monotonic()
        if delay > 0:
            time.sleep(delay)
        for i, p in enumerate(pubs):
            sent[i] += 1
            p.publish(String(data=json.dumps({"t": time.time_ns() // 1000, "value": {"n": sent[i]}})))
        n += 1
    time.sleep(2.0)
    print(json.dumps({"sent": sent}), flush=True)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main(int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]))
