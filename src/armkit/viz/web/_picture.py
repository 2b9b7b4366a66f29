"""A picture of a view: the page opened in headless Chromium, rendered by its own client.

The page's client renders the 3D canvas on request (viser's ``get_render``),
so the picture is exactly what a person sees, without the control panel.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from ..._errors import ArmkitError
from ..._files import check_output_path
from ._chromium import Chromium, wait_until
from ._view import View

READY = "document.querySelector('canvas') !== null"
SETTLE = 0.5  # [s] for the page to receive and draw the scene before the picture
RENDER_STEPS = ("starting the browser", "opening the page", "waiting for the scene", "rendering")


def connected_client(view: View, count: int = 1, timeout: float = 20.0) -> Any:
    """The ``count``-th client connected to ``view`` (waits up to ``timeout`` [s])."""
    wait_until(lambda: len(view.server.get_clients()) >= count, timeout, "the page to connect")
    clients = view.server.get_clients()
    return clients[sorted(clients)[count - 1]]


def wait_for_camera(view: View, client: Any, timeout: float = 20.0) -> None:
    """Wait until the page's camera is where the view put it (the page is set up)."""
    want = np.asarray(view.server.initial_camera.position)
    wait_until(
        lambda: bool(np.allclose(client.camera.position, want, atol=1e-3)),
        timeout,
        "the page to place its camera",
    )


def render_png(
    view: View,
    path: Path,
    width: int = 1024,
    height: int = 768,
    progress: Callable[[int, str], None] | None = None,
) -> Path:
    """Open ``view`` in headless Chromium of ``width`` x ``height`` [px] and write its
    3D canvas to the PNG file ``path`` (on white). Returns the path. ``progress(k, step)``
    is told as each of the ``RENDER_STEPS`` starts (k = 0, 1, ...) and when all are done
    (k = len(RENDER_STEPS), step "done")."""
    import imageio.v3 as iio

    path = check_output_path(path, suffixes=(".png",))

    def step(k: int) -> None:
        if progress is not None:
            progress(k, RENDER_STEPS[k] if k < len(RENDER_STEPS) else "done")

    step(0)
    with Chromium(width, height) as browser:
        step(1)
        browser.open(view.url, READY)
        step(2)
        client = connected_client(view)
        wait_for_camera(view, client)
        client.flush()
        time.sleep(SETTLE)
        step(3)
        try:
            rgba = client.get_render(height, width, transport_format="png", timeout=30.0)
        except TimeoutError:
            raise ArmkitError("the page did not render a picture within 30 s") from None
    alpha = rgba[..., 3:4].astype(np.float64) / 255.0
    rgb = rgba[..., :3].astype(np.float64) * alpha + 255.0 * (1.0 - alpha)
    iio.imwrite(path, np.round(rgb).astype(np.uint8))
    step(len(RENDER_STEPS))
    return path
