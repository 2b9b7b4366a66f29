"""The arm every CLI command opens: its driver on ``--driver/--port``; a simulated arm
keeps its truth between processes in its state file and is published live while
somebody follows it (``armkit view --follow``)."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ..model import ArmModel


def open_kept(model: ArmModel, args: argparse.Namespace, world: Any = None) -> Any:
    """The driver of ``--driver``/``--port`` for ``model`` (in ``world`` if given); on a
    kept simulated arm a ``LivePublisher`` is attached to its world, so other processes
    can follow it (it writes only while somebody does)."""
    from ..connect import kept_state_file, open_driver, world_of

    driver = open_driver(model, args.driver_name, args.port, world=world, keep=True)
    state = kept_state_file(model, args.port, True) if args.driver_name == "sim" else None
    opened = world_of(driver)
    if state is not None and opened is not None:
        from ..viz.live import publish_live

        for arm in opened.arms():
            publish_live(opened, arm, state)
    return driver
