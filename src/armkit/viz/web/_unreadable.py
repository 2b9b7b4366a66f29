"""What the view's server says when a client sends what it cannot read.

viser reads every websocket message as msgpack of one of its own kinds; a text
frame, random bytes or a message of no kind it knows end that connection with an
exception, which websockets logs as "connection handler failed" with the whole
traceback, on the terminal of ``armkit view``. The server itself goes on serving
(the page, other clients). ``quiet_unreadable`` turns each such log record into one
line that says so, without the traceback. A connection that is no HTTP request at all
("opening handshake failed", also what a browser's unused preconnection leaves) is
not worth a line: viser drops those records too, but only once it has served one
request, so garbage sent first showed its traceback.
"""

from __future__ import annotations

import logging

LOGGER = "websockets.server"
HANDLER_FAILED = "connection handler failed"
NOISE = ("opening handshake failed", "connection rejected (200 OK)")  # viser's own list


class OneLine(logging.Filter):
    """A failed connection handler as one ``armkit: warning:`` line (no traceback)."""

    def filter(self, record: logging.LogRecord) -> bool:
        if record.getMessage() in NOISE:
            return False
        if record.getMessage() == HANDLER_FAILED and record.exc_info:
            exc = record.exc_info[1]
            why = f"{type(exc).__name__}: {exc}" if str(exc) else type(exc).__name__
            record.msg = (
                "armkit: warning: the view closed a connection that sent what it cannot "
                f"read ({' '.join(why.split())[:120]}); the page serves on"
            )
            record.args, record.exc_info, record.exc_text = (), None, None
            record.levelno, record.levelname = logging.WARNING, "WARNING"
        return True


def quiet_unreadable() -> None:
    """Install ``OneLine`` on websockets' server logger (once per process)."""
    logger = logging.getLogger(LOGGER)
    if not any(isinstance(f, OneLine) for f in logger.filters):
        logger.addFilter(OneLine())
