"""Helpers of the browser tests: Chromium or a reason why not, projection, colours."""

from __future__ import annotations

import colorsys
import io
import os
from typing import Any

import numpy as np
import pytest

from armkit.viz.web import find_chromium

PANEL = 360  # [px] the control panel floats over the right edge of the page


def chromium_or_skip() -> str:
    """The Chromium to use; in CI a missing browser is a failure, elsewhere a skip."""
    path = find_chromium()
    if path is not None:
        return path
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail(
            "Chromium is missing in CI: .ci/run installs Debian's chromium before the tests"
        )
    pytest.skip("no Chromium here (apt-get install chromium); CI runs these tests")


def project(camera: Any, point: Any) -> tuple[int, int]:
    """Pixel (column, row) of the world ``point`` [m] in the page's camera (viser
    reports it in OpenCV convention: x right, y down, z forward; vertical fov)."""
    import viser.transforms as vtf

    R = vtf.SO3(np.asarray(camera.wxyz)).as_matrix()
    p = R.T @ (np.asarray(point, dtype=np.float64) - np.asarray(camera.position))
    assert p[2] > 0, "the point is behind the camera"
    f = (camera.image_height / 2) / np.tan(camera.fov / 2)
    u = camera.image_width / 2 + f * float(p[0]) / float(p[2])
    v = camera.image_height / 2 + f * float(p[1]) / float(p[2])
    return round(u), round(v)


def decode(png: bytes) -> np.ndarray:
    """PNG bytes -> (H, W, 3) uint8."""
    import imageio.v3 as iio

    return np.asarray(iio.imread(io.BytesIO(png)))[..., :3]


def hue_matches(pixel: Any, colour: tuple[int, int, int], tolerance: float = 14.0) -> bool:
    """True when ``pixel`` has the hue of ``colour`` (within ``tolerance`` degrees)
    and is clearly coloured (saturation >= 0.55): shading changes the brightness only."""
    h1, s1, v1 = colorsys.rgb_to_hsv(*(np.asarray(pixel[:3], dtype=float) / 255.0))
    h2, _, _ = colorsys.rgb_to_hsv(*(np.asarray(colour, dtype=float) / 255.0))
    dh = abs(h1 - h2) * 360.0
    return min(dh, 360.0 - dh) <= tolerance and s1 >= 0.55 and v1 >= 0.15


def colour_near(
    image: np.ndarray, pixel: tuple[int, int], colour: tuple[int, int, int], radius: int = 3
) -> bool:
    """True when a pixel within ``radius`` of (column, row) has ``colour``'s hue."""
    u, v = pixel
    patch = image[max(0, v - radius) : v + radius + 1, max(0, u - radius) : u + radius + 1]
    return any(hue_matches(p, colour) for p in patch.reshape(-1, 3))


def visible_area(image: np.ndarray, pixel: tuple[int, int]) -> bool:
    """True when the pixel is on the page and not under the control panel or the notice."""
    u, v = pixel
    h, w = image.shape[:2]
    return 0 <= v < h and 0 <= u < w - PANEL and not (u < 330 and v < 170)
