"""The client against a scripted daemon: framing, bad lines, refusals, reconnection, asyncio."""

import asyncio
import json
import socket

import pytest

import habla
import habla.aio
from scripted import HELLO, ScriptedDaemon, line, sample


@pytest.fixture
def daemon_with():
    made = []

    def make(*chunks, answer=None):
        d = ScriptedDaemon(*chunks, answer=answer)
        made.append(d)
        return d
    yield make
    for d in made:
        d.close()


def connect(d, **kw):
    return habla.connect("127.0.0.1", d.port, timeout=5, **kw)


def test_the_hello_is_read_on_connect_and_describes_the_socket(daemon_with):
    with connect(daemon_with(line(HELLO))) as s:
        assert s.hello.socket == "ranges"
        assert s.hello.direction == "both"
        assert s.hello.outputs[0].name == "out" and s.hello.outputs[0].kind == "vector"
        assert s.hello.inputs == [habla.Input("in", "vector")]


def test_the_client_announces_itself_with_one_ping(daemon_with):
    d = daemon_with(line(HELLO))
    with connect(d):
        assert d.wait_for(lambda: d.pings == 1)


def test_lines_that_are_not_objects_are_reported_and_reading_goes_on(daemon_with):
    d = daemon_with(line(HELLO), b"[1, 2]\n", b"{not json\n", b"\xff\xfe\n", b"\n", sample(1, [0.5]))
    with connect(d) as s:
        got = s.next_sample(timeout=5)
        assert got.value == [0.5] and got.seq == 1
        assert [e["code"] for e in s.events] == ["not_object", "bad_json", "bad_utf8"]


def test_a_binary_block_is_read_after_its_line_even_when_it_holds_newlines(daemon_with):
    pcm = bytes(range(10)) + b"\n\n{"
    header = line({"type": "sample", "output": "audio", "seq": 1, "t": 5, "stale": False, "kind": "audio",
                   "rateHz": 16000, "channels": 1, "bits": 16, "bytes": len(pcm)})
    with connect(daemon_with(line(HELLO), header + pcm, sample(2, [3.0]))) as s:
        assert s.next_sample(timeout=5).data == pcm
        assert s.next_sample(timeout=5).value == [3.0]


@pytest.mark.parametrize("first, wanted", [
    (b'["hello"]\n', habla.BadHelloError),
    (line({"type": "hello", "protocol": "habla-control/2", "socket": "x"}), habla.BadHelloError),
    (line({"type": "sample", "seq": 1}), habla.BadHelloError),
    (line({"type": "error", "code": "too_many_clients", "message": "full"}), habla.RefusedError),
])
def test_a_bad_hello_is_a_typed_error_not_a_crash(daemon_with, first, wanted):
    with pytest.raises(wanted):
        connect(daemon_with(first))


def test_nobody_listening_is_a_lost_link():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    with pytest.raises(habla.LinkLostError):
        habla.connect("127.0.0.1", port, timeout=5)


def test_a_refused_write_raises_with_the_daemons_code_and_samples_meanwhile_are_kept(daemon_with):
    def answer(req):
        if req["value"] == "fly":
            return sample(7, [1.0]) + line({"type": "error", "code": "bad_value", "message": "no", "id": req["id"]})
        return line({"type": "ok", "id": req["id"]})
    with connect(daemon_with(line(HELLO), answer=answer)) as s:
        assert s.write_and_wait("forward")["type"] == "ok"
        with pytest.raises(habla.RefusedError) as caught:
            s.write_and_wait("fly")
        assert caught.value.code == "bad_value"
        assert s.next_sample(timeout=1).seq == 7


def test_a_token_is_sent_first_and_the_full_hello_kept(daemon_with):
    full = dict(HELLO, auth="ok", client="mdb", role="command")
    d = daemon_with(line({"type": "hello", "protocol": "habla-control/1", "socket": "ranges", "auth": "required"}),
                    answer=lambda req: line(full) if req.get("op") == "auth" else None)
    with connect(d, client="mdb", token="t" * 20) as s:
        assert (s.hello.client, s.hello.role) == ("mdb", "command")
        assert d.received[0] == {"op": "auth", "client": "mdb", "token": "t" * 20}


def test_missing_or_refused_credentials_raise_auth_error(daemon_with, monkeypatch):
    monkeypatch.delenv("HABLA_CLIENT", raising=False)
    monkeypatch.delenv("HABLA_TOKEN", raising=False)
    required = line({"type": "hello", "protocol": "habla-control/1", "socket": "ranges", "auth": "required"})
    with pytest.raises(habla.AuthError) as none_given:
        connect(daemon_with(required))
    assert none_given.value.code == "auth_required"
    d = daemon_with(required, answer=lambda req: line({"type": "error", "code": "auth_failed", "message": "no"}))
    with pytest.raises(habla.AuthError) as refused:
        connect(d, client="mdb", token="wrong-token-wrong")
    assert refused.value.code == "auth_failed"


def test_the_end_of_the_stream_is_a_lost_link(daemon_with):
    d = daemon_with(line(HELLO), sample(1, [1.0]))
    with connect(d) as s:
        assert s.next_sample(timeout=5).seq == 1
        d.wait_for(lambda: d.pings == 1)
        d.drop_connections()
        with pytest.raises(habla.LinkLostError):
            s.next_sample(timeout=5)


def test_backoff_grows_to_its_ceiling_and_starts_again_after_a_session():
    b = habla.Backoff(initial_s=0.1, max_s=0.5, factor=2, jitter=0)
    assert [b.next() for _ in range(5)] == [0.1, 0.2, 0.4, 0.5, 0.5]
    b.reset()
    assert b.next() == 0.1


def test_a_reconnecting_socket_comes_back_after_the_daemon_drops_it(daemon_with):
    d = daemon_with(line(HELLO), sample(1, [1.0]))
    links = []
    r = habla.Reconnecting("127.0.0.1", d.port, backoff=habla.Backoff(0.05, 0.2),
                           on_link=lambda up, why: links.append(up), timeout=5)
    try:
        samples = r.samples(timeout=5)
        assert next(samples).seq == 1
        d.wait_for(lambda: d.pings == 1)
        d.drop_connections()
        assert next(samples).seq == 1      # the same script again, on a new connection
        assert links == [True, False, True] and r.sessions == 2 and d.connections == 2
    finally:
        r.close()


def test_a_reconnecting_socket_does_not_retry_a_refused_token(daemon_with):
    d = daemon_with(line({"type": "hello", "protocol": "habla-control/1", "socket": "x", "auth": "required"}),
                    answer=lambda req: line({"type": "error", "code": "auth_failed", "message": "no"}))
    r = habla.Reconnecting("127.0.0.1", d.port, client="a", token="b" * 16)
    with pytest.raises(habla.AuthError):
        r.connect()
    assert d.connections == 1


def test_the_asyncio_client_reads_samples_and_matches_answers_by_id(daemon_with):
    def answer(req):
        if req.get("value") == "fly":
            return line({"type": "error", "code": "bad_value", "message": "no", "id": req["id"]})
        return sample(9, [2.0]) + line({"type": "ok", "id": req["id"]})
    d = daemon_with(line(HELLO), sample(1, [1.0]), answer=answer)

    async def run():
        async with await habla.aio.connect("127.0.0.1", d.port) as s:
            assert (await s.next_sample(5)).seq == 1
            assert (await s.write_and_wait("forward"))["type"] == "ok"
            with pytest.raises(habla.RefusedError):
                await s.write_and_wait("fly")
            assert (await s.next_sample(5)).seq == 9
            d.drop_connections()
            with pytest.raises(habla.LinkLostError):
                await s.next_sample(5)
    asyncio.run(run())


def test_non_finite_numbers_are_written_as_null(daemon_with):
    d = daemon_with(line(HELLO))
    with connect(d) as s:
        s.write([float("nan"), 1.0])
        assert d.wait_for(lambda: d.received)
    assert d.received[0] == {"op": "write", "value": [None, 1.0]}
    assert json.dumps(d.received[0])


def test_lines_that_overtake_the_hello_after_authenticating_are_kept_not_taken_for_the_hello(daemon_with):
    full = dict(HELLO, auth="ok", client="mdb", role="command")
    required = line({"type": "hello", "protocol": "habla-control/1", "socket": "ranges", "auth": "required"})
    control = line({"type": "control", "holder": None, "why": "x disconnected"})

    def answer(req):
        return control + sample(5, [1.0]) + line(full) if req.get("op") == "auth" else None
    with connect(daemon_with(required, answer=answer), client="mdb", token="t" * 20) as s:
        assert s.hello.client == "mdb" and s.next_sample(timeout=5).seq == 5
        assert [e["type"] for e in s.events] == ["control"]

    async def run():
        async with await habla.aio.connect("127.0.0.1", daemon_with(required, answer=answer).port, client="mdb",
                                           token="t" * 20) as a:
            assert a.hello.client == "mdb" and (await a.next_sample(5)).seq == 5
            assert [e["type"] for e in a.events] == ["control"]
    asyncio.run(run())
