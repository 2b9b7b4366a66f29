"""Where a view's page is served: the host checked to be an address of this computer
and the port to be free, before any server starts (a server told to bind an address
it cannot would try port after port and never be ready)."""

from __future__ import annotations

import contextlib
import errno
import socket
from dataclasses import dataclass

from .._errors import InputError

TRIES = 100  # ports tried above a busy one that the user did not choose
_HOSTS = "use 127.0.0.1 (this computer only), 0.0.0.0 (every network) or one of its own addresses"


@dataclass(frozen=True)
class Address:
    """A host and a port that could be bound just now.

    Attributes:
        host: as given.  port: the port to serve on (0: any free one).
        note: why the port is not the one asked for ('' if it is).
    """

    host: str
    port: int
    note: str = ""


def serve_address(host: str, port: int, *, exact: bool = True, flag: str = "--port") -> Address:
    """Check that ``host`` is an address of this computer and ``port`` (0: any) is free
    on it. A busy port: InputError if ``exact`` (the user chose it), else the next free
    one above, said in ``note``. InputError (one line, naming ``flag``) for a host that
    is no address here or a port out of 0..65535."""
    if not 0 <= port <= 65535:
        raise InputError(f"{flag} must be 0..65535, got {port}")
    if not host.isprintable() or any(c.isspace() for c in host):
        raise InputError(f"--host {host!r} is no address of this computer; {_HOSTS}")
    infos = _resolve(host, port)
    for candidate in [port] if exact or port == 0 else range(port, min(port + TRIES, 65536)):
        problem = _bind_problem(host, infos, candidate)
        if problem is None:
            note = "" if candidate == port else f"port {port} is busy; serving on {candidate}"
            return Address(host, candidate, note)
        if problem.errno == errno.EADDRNOTAVAIL:
            raise InputError(f"--host {host} is no address of this computer; {_HOSTS}")
        if problem.errno != errno.EADDRINUSE:
            raise InputError(f"cannot serve on {host}, port {candidate}: {problem.strerror}")
    if exact:
        raise InputError(
            f"{flag} {port} is busy on {host or 'every address'} (another program serves "
            f"there); choose another port, or 0 for any free one"
        )
    raise InputError(
        f"ports {port}..{port + TRIES - 1} are all busy on {host}; choose one with {flag} "
        "(0: any free one)"
    )


def _resolve(host: str, port: int) -> list[tuple[int, tuple[object, ...]]]:
    """(family, socket address) of each address ``host`` stands for (InputError: none)."""
    try:
        infos = socket.getaddrinfo(
            host or None, port, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE
        )
    except (socket.gaierror, UnicodeError) as exc:
        reason = getattr(exc, "strerror", None) or str(exc)
        raise InputError(
            f"--host {host} is no address of this computer ({reason}); {_HOSTS}"
        ) from None
    return [(family, sockaddr) for family, _, _, _, sockaddr in infos]


def _bind_problem(
    host: str, infos: list[tuple[int, tuple[object, ...]]], port: int
) -> OSError | None:
    """The error binding every address of ``host`` on ``port`` gives (None: it binds),
    with the options an asyncio server uses (address reuse, IPv6 only on IPv6)."""
    for family, sockaddr in infos:
        with contextlib.closing(socket.socket(family, socket.SOCK_STREAM)) as sock:
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            if family == socket.AF_INET6 and hasattr(socket, "IPV6_V6ONLY"):
                sock.setsockopt(socket.IPPROTO_IPV6, socket.IPV6_V6ONLY, 1)
            try:
                sock.bind((*sockaddr[:1], port, *sockaddr[2:]))
                sock.listen(1)
            except OSError as exc:
                return exc
    return None
