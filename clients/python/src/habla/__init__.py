"""A client for HABLA's control sockets (the habla-control/1 protocol of docs/protocol.md).

    import habla
    with habla.connect("127.0.0.1", 7002) as s:      # the hello is read on connect: s.hello
        for sample in s.samples():                     # habla.Sample: value, seq, t_us, stale
            print(sample.value)

habla.Reconnecting keeps a socket connected across losses of the link; habla.aio is the asyncio client.
"""

from .control import ControlSocket, connect
from .errors import AuthError, BadHelloError, FrameError, HablaError, LinkLostError, RefusedError, TlsError
from .hello import PROTOCOL, Hello, Input, Output, Sample
from .reconnect import Backoff, Reconnecting

__all__ = ["AuthError", "Backoff", "BadHelloError", "ControlSocket", "FrameError", "HablaError", "Hello", "Input",
           "LinkLostError", "Output", "PROTOCOL", "Reconnecting", "RefusedError", "Sample", "TlsError", "connect"]
__version__ = "1.0.0"
