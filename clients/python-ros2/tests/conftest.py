import os
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
CLIENTS = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(CLIENTS, "python", "tests"))   # the deployment harness of the client's tests
sys.path.insert(0, os.path.join(CLIENTS, "python", "src"))
sys.path.insert(0, os.path.join(CLIENTS, "python-ros2", "src"))
sys.path.insert(0, HERE)

# Every DDS participant of these tests (this process and the programs it starts) stays on this machine, in a
# domain of its own: HABLA_TEST_ROS_DOMAIN, else 70.
os.environ["ROS_DOMAIN_ID"] = os.environ.get("HABLA_TEST_ROS_DOMAIN", "70")
os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
os.environ.pop("ROS_LOCALHOST_ONLY", None)
os.environ.pop("ROS_STATIC_PEERS", None)

import rclpy  # noqa: E402

from ros_probe import RosProbe  # noqa: E402


@pytest.fixture(scope="session")
def ros():
    rclpy.init()
    yield
    rclpy.try_shutdown()


@pytest.fixture
def probe(ros):
    p = RosProbe("habla_test_probe")
    yield p
    p.close()
