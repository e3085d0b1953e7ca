"""The face against a real daemon (config/pioneer.json with tokens and a TLS socket) and the simulated
Pioneer, checked by a ROS 2 node written from ROS 2's conventions."""

import json
import math
import os
import sys

import pytest
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from geometry_msgs.msg import PoseStamped, Twist
from std_msgs.msg import Float64, String

import habla
from deployment import TOKENS, PioneerRig, Process
from ros_probe import LATCHED, RELIABLE, SENSOR

SRC = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
PYTHONPATH = os.pathsep.join([os.path.join(SRC, "python", "src"), os.path.join(SRC, "python-ros2", "src")])
NS = "/habla/pioneer_2dx"
WAIT_S = 30


@pytest.fixture(scope="module")
def rig(tmp_path_factory):
    folder = str(tmp_path_factory.mktemp("face"))
    r = PioneerRig(folder)
    face = None
    try:
        r.start_simulator()
        r.start_daemon()
        r.await_ready()
        face = Process("face", [sys.executable, "-u", "-m", "habla_ros2", "face", r.config],
                       os.path.join(folder, "face.log"), env={"PYTHONPATH": PYTHONPATH})
        r.face = face
        yield r
    finally:
        if face is not None:
            face.stop()
        r.close()


def sample_of(rig, name, **kw):
    tls = rig.certificate if name == "pose" else None
    return habla.connect("127.0.0.1", rig.ports[name], client="tester", token=TOKENS["tester"], tls=tls, timeout=10, **kw)


def test_every_socket_is_a_topic_of_the_type_its_shape_gives(rig, probe):
    probe.wait_for_topics({
        NS + "/command": "std_msgs/msg/String", NS + "/command/sample": "std_msgs/msg/String",
        NS + "/action/motion/sample": "std_msgs/msg/String",
        NS + "/distance_angle": "std_msgs/msg/String", NS + "/reward": "std_msgs/msg/Float64",
        NS + "/action": "std_msgs/msg/String", NS + "/action/motion": "geometry_msgs/msg/Twist",
        NS + "/action/set": "std_msgs/msg/String", NS + "/pose": "geometry_msgs/msg/PoseStamped",
        NS + "/link": "std_msgs/msg/String", NS + "/pose/state": "std_msgs/msg/String",
        "/diagnostics": "diagnostic_msgs/msg/DiagnosticArray"}, WAIT_S)
    # a sample's JSON already has its source time: no companion
    assert NS + "/distance_angle/sample" not in probe.topics() and NS + "/pose/sample" not in probe.topics()


def test_stream_topics_carry_the_sockets_samples_with_their_source_time(rig, probe):
    probe.listen(String, NS + "/distance_angle", SENSOR)
    probe.listen(PoseStamped, NS + "/pose", SENSOR)
    # DDS discovery may take longer than the samples below last: read them once the probe hears both topics
    probe.wait_for(lambda: probe.messages(NS + "/distance_angle") and probe.messages(NS + "/pose"), WAIT_S,
                   "the first messages of both topics")
    with sample_of(rig, "distance_angle") as da, sample_of(rig, "pose") as pose:
        seen_da = {s.seq: s for s in (da.next_sample(10) for _ in range(30))}
        seen_pose = {s.t_us: s for s in (pose.next_sample(10) for _ in range(30))}
    json_lines = probe.wait_for(lambda: [json.loads(m.data) for m in probe.messages(NS + "/distance_angle")
                                         if json.loads(m.data)["seq"] in seen_da], WAIT_S, "distance_angle")
    for line in json_lines:
        socket_sample = seen_da[line["seq"]]
        assert (line["t"], line["value"], line["stale"]) == (socket_sample.t_us, socket_sample.value, False)

    def stamp_us(m):
        return m.header.stamp.sec * 1_000_000 + m.header.stamp.nanosec // 1000
    poses = probe.wait_for(lambda: [m for m in probe.messages(NS + "/pose") if stamp_us(m) in seen_pose], WAIT_S, "pose")
    for m in poses:
        v = seen_pose[stamp_us(m)].value
        assert m.header.frame_id == "odom"
        assert (m.pose.position.x, m.pose.position.y) == pytest.approx((v["xM"], v["yM"]), abs=1e-9)
        assert 2 * math.atan2(m.pose.orientation.z, m.pose.orientation.w) == pytest.approx(v["thetaRad"], abs=1e-9)


def test_words_and_rewards_arrive_reliably_with_their_samples(rig, probe):
    subs = [probe.listen(String, NS + "/command", RELIABLE), probe.listen(String, NS + "/command/sample", RELIABLE),
            probe.listen(Float64, NS + "/reward", RELIABLE), probe.listen(String, NS + "/reward/sample", RELIABLE)]
    # A word and a reward are published once: wait until the face's publisher of every topic is matched with this
    # node's subscription (DDS discovery), not only seen in the graph, or on a busy machine they are gone unheard.
    probe.wait_for(lambda: rig.face.alive() and all(s.get_publisher_count() > 0 for s in subs), WAIT_S, "the face")
    rig.truth.send({"op": "note", "label": "left"})      # the teacher plays E5 on the microphone
    rig.truth.send({"op": "reward", "value": -1})        # and types -1 on the keyboard
    probe.wait_for(lambda: probe.messages(NS + "/command") and probe.messages(NS + "/reward"), WAIT_S, "word and reward")
    assert probe.messages(NS + "/command")[-1].data == "left"
    assert probe.messages(NS + "/reward")[-1].data == -1.0
    stamped = probe.wait_for(lambda: probe.messages(NS + "/reward/sample"), WAIT_S, "the reward's sample")
    line = json.loads(stamped[-1].data)
    assert line["value"] == -1.0 and line["t"] > 0 and line["output"] == "reward"


def test_a_ros_publisher_drives_the_robot_and_a_refused_action_is_counted(rig, probe):
    probe.listen(String, NS + "/action/state", LATCHED)
    probe.listen(Twist, NS + "/action/motion", RELIABLE)
    set_pub = probe.node.create_publisher(String, NS + "/action/set", RELIABLE)
    probe.wait_for(lambda: set_pub.get_subscription_count() > 0, WAIT_S, "the face's /set subscription")
    before = rig.truth.place(5.0, 6.0, 0.0)
    for _ in range(4):
        set_pub.publish(String(data="forward"))
        rig.truth.after(0.5)
    after = rig.truth.after(0.5)
    assert after["robot"]["xM"] - before["robot"]["xM"] > 0.2, (before["robot"], after["robot"])
    assert any(m.linear.x > 0 for m in probe.messages(NS + "/action/motion"))
    set_pub.publish(String(data="fly"))

    def refused():
        states = [json.loads(m.data) for m in probe.messages(NS + "/action/state")]
        return states and states[-1]["refused"] >= 1 and states[-1]
    state = probe.wait_for(refused, WAIT_S, "the refusal on the state topic")
    assert state["lastRefusal"]["code"] == "bad_value" and state["lastRefusal"]["value"] == "fly"
    assert state["actions"] >= 4 and state["commander"]["client"] == "tester"
    assert "refused \"fly\": bad_value" in rig.face.log()


def test_staleness_and_the_lost_link_show_on_ros_2(rig, probe):
    """Last: it stops the simulator."""
    probe.listen(String, NS + "/distance_angle/state", LATCHED)
    probe.listen(DiagnosticArray, "/diagnostics", RELIABLE)
    probe.listen(String, NS + "/link", SENSOR)
    probe.wait_for(lambda: probe.messages(NS + "/link"), WAIT_S, "the link topic")
    rig.stop_simulator()

    def stale():
        states = [json.loads(m.data) for m in probe.messages(NS + "/distance_angle/state")]
        return states and states[-1]["stale"] and states[-1]
    assert stale is not None and probe.wait_for(stale, WAIT_S, "distance_angle turning stale")["connected"]

    def warned():
        for arr in probe.messages("/diagnostics"):
            for st in arr.status:
                if st.name == "habla/pioneer-2dx/distance_angle" and st.level == DiagnosticStatus.WARN:
                    return st
    assert probe.wait_for(warned, WAIT_S, "a WARN diagnostic").message.startswith("stale")

    def link_down():
        lines = [json.loads(m.data) for m in probe.messages(NS + "/link")]
        return any(not line["value"]["connected"] for line in lines)
    probe.wait_for(link_down, WAIT_S, "the link topic saying the robot's link is down")
