"""The ROS 2 base set-up for tests, as a user deploys it: the simulated ROS 2 base (habla-ros2 sim-base), the
body (habla-ros2 body) and the daemon with config/ros2-base.json, each a process of its own, on a free block of
loopback ports and in this test run's ROS domain."""

import os
import sys

from deployment import HOME, START_S, Process, Truth, await_port, await_ready, derive_config, exposed, free_offset, \
    habla_command

SRC = os.path.join(HOME, "clients")
PYTHONPATH = os.pathsep.join([os.path.join(SRC, "python", "src"), os.path.join(SRC, "python-ros2", "src")])


def ros2_program(*args):
    return [sys.executable, "-u", "-m", "habla_ros2"] + list(args)


class BaseRig:
    def __init__(self, folder, speed=2.0, tweak=None):
        self.folder, self.speed = folder, speed
        self.offset = free_offset()
        self.config = derive_config(os.path.join(HOME, "config", "ros2-base.json"), self.offset, speed,
                                    os.path.join(folder, "daemon.json"), tweak)
        self.ports = {name: e["port"] for name, e in exposed(self.config).items()}
        self.status_port = 7099 + self.offset
        self.truth_port = 8199 + self.offset
        self.body_port = 8120 + self.offset
        self.sim = self.body = self.daemon = self.truth = None

    def start(self):
        o = self.offset
        env = {"PYTHONPATH": PYTHONPATH}
        self.sim = Process("sim-base", ros2_program(
            "sim-base", "--world", "pioneer-hall", "--speed", "%g" % self.speed, "--teacher", "off",
            "--truth-port", str(self.truth_port), "--mic-port", str(8110 + o), "--keys-port", str(8111 + o)),
            os.path.join(self.folder, "sim-base.log"), env)
        self.body = Process("body", ros2_program("body", "--listen", "127.0.0.1:%d" % self.body_port),
                            os.path.join(self.folder, "body.log"), env)
        self.truth = Truth(self.truth_port)
        self.truth.await_time(0, START_S)
        await_port(self.body_port, START_S, self.body.proc)
        self.daemon = Process("daemon", habla_command() + ["run", self.config, "--time-scale", "%g" % self.speed],
                              os.path.join(self.folder, "daemon.log"))
        await_port(self.ports["distance_angle"], START_S, self.daemon.proc)
        await_ready(self.status_port, START_S)
        return self

    def close(self):
        for p in (self.daemon, self.body, self.sim):
            if p is not None:
                p.stop()
        if self.truth is not None:
            self.truth.close()
