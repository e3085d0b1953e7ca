"""The client against a real daemon (config/pioneer.json, security on) and the simulated Pioneer."""

import asyncio
import os
import time

import pytest

import habla
import habla.aio
from deployment import HOME, TOKENS


def connect(rig, name, who="tester", **kw):
    tls = rig.certificate if name == "pose" else None
    return habla.connect("127.0.0.1", rig.ports[name], client=who, token=TOKENS[who], tls=tls, timeout=10, **kw)


def test_the_hello_gives_the_shape_and_samples_carry_seq_source_time_and_staleness(rig):
    with connect(rig, "distance_angle") as s:
        assert (s.hello.socket, s.hello.direction, s.hello.client, s.hello.role) == \
            ("distance_angle", "out", "tester", "command")
        assert {"distanceM", "angleRad", "seen"} <= set(s.hello.outputs[0].fields)
        got = [s.next_sample(timeout=10) for _ in range(5)]
    seqs = [g.seq for g in got]
    assert seqs == sorted(seqs) and len(set(seqs)) == 5
    now = time.time()
    assert all(now - 10 < g.t <= now + 1 for g in got), [g.t_us for g in got]
    assert not any(g.stale for g in got)
    assert all(isinstance(g.value["distanceM"], float) for g in got)


def test_an_action_is_answered_ok_and_moves_the_robot_and_a_bad_one_is_refused(rig):
    before = rig.truth.place(5.0, 6.0, 0.0)
    with connect(rig, "action") as action:
        assert action.write_and_wait("forward")["type"] == "ok"
        after = rig.truth.after(1.5)
        with pytest.raises(habla.RefusedError) as caught:
            action.write_and_wait("fly")
        action.write_and_wait("stop")
    assert caught.value.code == "bad_value"
    assert after["robot"]["xM"] - before["robot"]["xM"] > 0.1, (before["robot"], after["robot"])


def test_a_reader_may_not_drive(rig):
    with connect(rig, "action", who="viewer") as action:
        assert action.hello.role == "read"
        with pytest.raises(habla.RefusedError) as caught:
            action.write_and_wait("forward")
    assert caught.value.code == "forbidden"


def test_a_wrong_token_or_none_is_an_auth_error(rig, monkeypatch):
    with pytest.raises(habla.AuthError) as wrong:
        habla.connect("127.0.0.1", rig.ports["reward"], client="tester", token="not-the-token-at-all")
    assert wrong.value.code == "auth_failed"
    monkeypatch.delenv("HABLA_CLIENT", raising=False)
    monkeypatch.delenv("HABLA_TOKEN", raising=False)
    with pytest.raises(habla.AuthError) as none:
        habla.connect("127.0.0.1", rig.ports["reward"])
    assert none.value.code == "auth_required"


def test_a_tls_socket_is_read_with_the_lab_certificate_and_refuses_plain_clients(rig):
    with connect(rig, "pose") as pose:
        sample = pose.next_sample(timeout=10)
        assert {"xM", "yM", "thetaRad"} <= set(sample.value)
    with pytest.raises(habla.RefusedError) as plain:
        habla.connect("127.0.0.1", rig.ports["pose"], client="tester", token=TOKENS["tester"], timeout=10)
    assert plain.value.code == "tls_required"
    with pytest.raises(habla.TlsError):
        habla.connect("127.0.0.1", rig.ports["reward"], client="tester", token=TOKENS["tester"], tls=rig.certificate)


def test_the_asyncio_client_reads_and_acts(rig):
    async def run():
        s = await habla.aio.connect("127.0.0.1", rig.ports["distance_angle"], client="tester", token=TOKENS["tester"])
        a = await habla.aio.connect("127.0.0.1", rig.ports["action"], client="tester", token=TOKENS["tester"])
        try:
            first = await s.next_sample(10)
            second = await s.next_sample(10)
            assert second.seq > first.seq
            assert (await a.write_and_wait("stop"))["type"] == "ok"
            with pytest.raises(habla.RefusedError):
                await a.write_and_wait(42)
        finally:
            await s.close()
            await a.close()
    asyncio.run(run())


def test_the_example_control_program_drives_the_robot_to_the_object(rig, monkeypatch):
    """examples/control-python/approach.py, on the packaged client, against the daemon."""
    import importlib.util
    spec = importlib.util.spec_from_file_location("approach", os.path.join(HOME, "examples", "control-python",
                                                                            "approach.py"))
    approach = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(approach)
    before = rig.truth.place(5.0, 6.0, 0.0)
    monkeypatch.setenv("HABLA_CLIENT", "tester")
    monkeypatch.setenv("HABLA_TOKEN", TOKENS["tester"])
    assert approach.main(["--distance-angle-port", str(rig.ports["distance_angle"]),
                          "--action-port", str(rig.ports["action"]), "--seconds", "40"]) == 0
    after = rig.truth.latest()
    assert after["distanceM"] < 0.6 < before["distanceM"], (before["distanceM"], after["distanceM"])


def test_a_lost_robot_makes_samples_stale_and_a_lost_daemon_is_reconnected(rig):
    """Last: it stops the simulator and restarts the daemon."""
    with connect(rig, "distance_angle") as s:
        s.next_sample(timeout=10)
        rig.stop_simulator()
        deadline = time.monotonic() + 30
        while not s.stale and time.monotonic() < deadline:
            try:
                s.next_sample(timeout=1)
            except TimeoutError:
                pass
        assert s.stale, list(s.events)
    links = []
    r = habla.Reconnecting("127.0.0.1", rig.ports["reward"], backoff=habla.Backoff(0.1, 1.0),
                           on_link=lambda up, why: links.append(up), client="tester", token=TOKENS["tester"])
    try:
        first = r.connect()
        rig.stop_daemon()
        with pytest.raises(habla.LinkLostError):
            first.next_sample(timeout=30)
        r.lost("the daemon stopped")
        rig.start_daemon()
        second = r.connect()
        assert second is not first and r.sessions == 2 and links == [True, False, True]
        assert second.hello.stale   # the keyboard's link is down: the simulator is gone
    finally:
        r.close()
