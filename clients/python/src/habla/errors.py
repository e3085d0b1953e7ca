"""The errors a HABLA client raises, one type per way a conversation with the daemon can fail."""


class HablaError(Exception):
    """Anything that went wrong talking to a HABLA socket."""


class BadHelloError(HablaError, ConnectionError):
    """The peer's first line is not a habla-control/1 hello: not HABLA, another protocol version, or garbage."""


class LinkLostError(HablaError, ConnectionError):
    """The connection ended or broke: the daemon stopped, restarted, closed this client, or the network failed.
    A client that wants to go on connects again (see habla.Reconnecting)."""


class RefusedError(HablaError):
    """The daemon answered a request with an error line: a refused write (busy, bad_value, forbidden,
    read_only, queue_full, ...), a bad rate, an unknown op. `code` is the daemon's code, `line` the whole line."""

    def __init__(self, line):
        super().__init__("%s: %s" % (line.get("code"), line.get("message")))
        self.code = line.get("code")
        self.message = line.get("message")
        self.line = line


class AuthError(RefusedError):
    """The socket requires authentication and it failed: no credentials given (auth_required), an unknown
    client or a wrong token (auth_failed), or a client with no role on this socket (forbidden)."""


class TlsError(HablaError, ConnectionError):
    """The TLS handshake failed: the socket does not speak TLS, or its certificate is not the trusted one or does
    not name the address connected to."""


class FrameError(HablaError):
    """A frame that cannot be resynchronised: a line or a binary block over the client's limit."""
