"""An asyncio client of one HABLA control socket.

    import asyncio, habla.aio
    async def main():
        async with await habla.aio.connect("127.0.0.1", 7002) as s:
            async for sample in s.samples():
                print(sample.value)
        action = await habla.aio.connect("127.0.0.1", 7004)
        await action.write_and_wait("forward")
        await action.close()
    asyncio.run(main())

A reader task takes every line as it comes: samples wait in a queue for samples()/next_sample() (the oldest
dropped beyond `queue_samples`, counted in .dropped_here), answers go to the request that waits for them,
other lines to .events. So writes, requests and reading may run in several tasks at once.
"""

import asyncio
import collections
import os

from .control import EVENTS_KEPT, RECV_BYTES, SAMPLES_HELD, tls_context
from .errors import AuthError, LinkLostError, RefusedError
from .framing import FrameReader, encode
from .hello import Hello, Sample


async def connect(host, port, timeout=5.0, client=None, token=None, tls=None, announce=True,
                  queue_samples=SAMPLES_HELD):
    """Connects, reads the hello (authenticating where required) and starts reading; see habla.connect."""
    try:
        reader, writer = await asyncio.wait_for(asyncio.open_connection(
            host, port, ssl=None if tls is None else tls_context(tls), server_hostname=None if tls is None else host),
            timeout)
    except (OSError, asyncio.TimeoutError) as e:
        raise LinkLostError("cannot connect to %s:%s: %s" % (host, port, e)) from e
    s = AsyncControlSocket(reader, writer, (host, port), queue_samples)
    try:
        await s._handshake(timeout, client or os.environ.get("HABLA_CLIENT"), token or os.environ.get("HABLA_TOKEN"),
                           announce)
    except BaseException:
        await s.close()
        raise
    return s


class AsyncControlSocket:
    """One connection to one method's control socket, for asyncio."""

    def __init__(self, reader, writer, address, queue_samples):
        self.address = address
        self.hello = None
        self.stale = False
        self.dropped = 0          # samples the daemon dropped for this client
        self.dropped_here = 0     # samples this client's own queue dropped
        self.commander = None
        self.events = collections.deque(maxlen=EVENTS_KEPT)
        self._reader, self._writer = reader, writer
        self._frames = FrameReader()
        self._samples = collections.deque()
        self._early = collections.deque()
        self._queue_samples = queue_samples
        self._arrived = asyncio.Event()
        self._answers = {}
        self._next_id = 0
        self._lost = None
        self._task = None

    async def _handshake(self, timeout, client, token, announce):
        first = await asyncio.wait_for(self._read_frame(), timeout)
        if first.get("type") == "error":
            raise RefusedError(first)
        self.hello = Hello(first)
        if self.hello.auth_required:
            if not client or not token:
                raise AuthError({"code": "auth_required", "message": "socket %r requires authentication: give "
                                 "client= and token= (or HABLA_CLIENT and HABLA_TOKEN)" % self.hello.socket})
            await self.send({"op": "auth", "client": client, "token": token})
            answer = await asyncio.wait_for(self._read_frame(), timeout)
            while answer.get("type") not in ("hello", "error"):   # a sample or notice overtook the hello: keep it
                if answer.get("type") == "sample":
                    self._samples.append(Sample(answer))
                else:
                    self._take(answer)
                answer = await asyncio.wait_for(self._read_frame(), timeout)
            if answer.get("type") == "error":
                raise AuthError(answer)
            self.hello = Hello(answer)
        elif announce:
            await self.send({"op": "ping"})
        self.stale = self.hello.stale
        self._task = asyncio.get_running_loop().create_task(self._read_all())

    async def _read_frame(self):
        """One frame during the handshake; frames that came with it wait in _early for the reader task."""
        while not self._early:
            chunk = await self._reader.read(RECV_BYTES)
            if not chunk:
                raise LinkLostError("the daemon closed the connection to %s:%s" % self.address)
            self._early.extend(self._frames.feed(chunk))
        return self._early.popleft()

    async def _read_all(self):
        try:
            while self._early:
                self._take(self._early.popleft())
            while True:
                chunk = await self._reader.read(RECV_BYTES)
                if not chunk:
                    raise LinkLostError("the daemon closed the connection to %s:%s" % self.address)
                for frame in self._frames.feed(chunk):
                    self._take(frame)
        except (OSError, LinkLostError) as e:
            self._lost = e if isinstance(e, LinkLostError) else LinkLostError("the connection broke: %s" % e)
        except asyncio.CancelledError:
            self._lost = LinkLostError("the connection was closed")
        except Exception as e:  # a frame over the limits: the stream cannot go on
            self._lost = LinkLostError("the stream from %s:%s cannot be read: %s" % (self.address + (e,)))
        for future in self._answers.values():
            if not future.done():
                future.set_exception(self._lost)
        self._answers.clear()
        self._arrived.set()

    def _take(self, frame):
        kind = frame.get("type")
        if kind == "sample":
            if len(self._samples) >= self._queue_samples:
                self._samples.popleft()
                self.dropped_here += 1
            self._samples.append(Sample(frame))
            self._arrived.set()
            return
        future = self._answers.pop(frame.get("id"), None) if kind in ("ok", "error", "pong") else None
        if future is not None and not future.done():
            if kind == "error":
                future.set_exception(RefusedError(frame))
            else:
                future.set_result(frame)
            return
        if kind == "stale":
            self.stale = bool(frame.get("stale"))
        elif kind == "dropped" and isinstance(frame.get("count"), int):
            self.dropped += frame["count"]
        elif kind == "control":
            self.commander = frame.get("holder")
        self.events.append(frame)

    async def next_sample(self, timeout=None):
        """The next sample; TimeoutError after timeout seconds, LinkLostError once the connection is gone."""
        async def wait():
            while not self._samples:
                if self._lost is not None:
                    raise self._lost
                self._arrived.clear()
                await self._arrived.wait()
            return self._samples.popleft()
        return await asyncio.wait_for(wait(), timeout)

    async def samples(self, timeout=None):
        """Every sample as it comes, until the connection ends."""
        while True:
            yield await self.next_sample(timeout)

    def __aiter__(self):
        return self.samples()

    async def send(self, obj):
        if self._lost is not None:
            raise self._lost
        try:
            self._writer.write(encode(obj))
            await self._writer.drain()
        except OSError as e:
            raise LinkLostError("the connection to %s:%s broke: %s" % (self.address + (e,))) from e

    async def write(self, value, input=None):
        """Writes a value without waiting for an answer."""
        req = {"op": "write", "value": value}
        if input is not None:
            req["input"] = input
        await self.send(req)

    async def request(self, obj, timeout=5.0):
        """Sends a request with an id; its ok (or pong) line, or RefusedError for an error answer."""
        self._next_id += 1
        req = dict(obj, id=obj.get("id", self._next_id))
        future = asyncio.get_running_loop().create_future()
        self._answers[req["id"]] = future
        try:
            await self.send(req)
            return await asyncio.wait_for(future, timeout)
        finally:
            self._answers.pop(req["id"], None)

    async def write_and_wait(self, value, input=None, timeout=5.0):
        """Writes a value and returns the daemon's ok, or raises RefusedError with its code."""
        req = {"op": "write", "value": value}
        if input is not None:
            req["input"] = input
        return await self.request(req, timeout)

    async def close(self):
        if self._task is not None:
            self._task.cancel()
            try:
                await self._task
            except asyncio.CancelledError:
                pass
        self._writer.close()
        try:
            await self._writer.wait_closed()
        except (OSError, asyncio.CancelledError):
            pass

    async def __aenter__(self):
        return self

    async def __aexit__(self, *exc):
        await self.close()
