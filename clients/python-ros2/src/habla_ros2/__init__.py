"""HABLA in a ROS 2 graph: the daemon's sockets as topics (face), a ROS 2 base as a HABLA body (body), and a
simulated ROS 2 base to try them on (sim-base). See docs/ros2.md."""

__version__ = "1.0.0"
