"""What the face needs from a daemon's config: its system name, the sockets it exposes, and how to reach them
(address, TLS, the credentials of a client with the right role)."""

import collections
import json
import os

Endpoint = collections.namedtuple("Endpoint", "name host port tls client token")
Endpoint.__doc__ = """One exposed socket: where to connect, the certificate to trust (None: plain TCP) and the
credentials to authenticate with (None where the config has none)."""

LOOPBACK = "127.0.0.1"
WILDCARDS = ("0.0.0.0", "::", "")


class DaemonConfig:
    """A daemon's config file, read for its exposed sockets."""

    def __init__(self, path, host=None, credentials=None, tls_trust=None):
        self.path = os.path.abspath(path)
        with open(self.path) as f:
            self.root = json.load(f)
        self.folder = os.path.dirname(self.path)
        self.system = self.root.get("system") or os.path.splitext(os.path.basename(path))[0]
        security = self.root.get("security") or {}
        self._host = host
        self._clients = self._read_clients(credentials or security.get("credentials"))
        cert = tls_trust or (security.get("tls") or {}).get("certificate")
        self._trust = os.path.join(self.folder, cert) if cert else None

    def _read_clients(self, credentials):
        if not credentials:
            return []
        with open(os.path.join(self.folder, credentials)) as f:
            return json.load(f).get("clients", [])

    def endpoints(self, only=None):
        """Every exposed socket (or those named in only), in config order."""
        out = []
        for m in self.root.get("methods", []):
            expose = m.get("expose")
            if not isinstance(expose, dict) or "port" not in expose:
                continue
            name = expose.get("name", m["id"])
            if only and name not in only:
                continue
            bind = expose.get("bind", LOOPBACK)
            host = self._host or (LOOPBACK if bind in WILDCARDS else bind)
            client, token = self.credentials_for(name, actuating=_takes_control(m))
            out.append(Endpoint(name, host, int(expose["port"]), self._trust if expose.get("tls") else None,
                                client, token))
        return out

    def credentials_for(self, socket, actuating):
        """The client to connect as: one with the command role on the socket where the socket takes values,
        else one that may read it; (None, None) where the config has no credentials."""
        def role(c):
            roles = c.get("roles") or {}
            return roles.get(socket, roles.get("*"))
        wanted = ("command",) if actuating else ("read", "command")
        for want in wanted + (("read",) if actuating else ()):
            for c in self._clients:
                if role(c) == want:
                    return c["name"], c["token"]
        return None, None


def _takes_control(method):
    inputs = method.get("inputs") or {}
    return any(v == "control" for v in inputs.values())
