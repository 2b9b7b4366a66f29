"""Fixtures of the drawing tests."""

from __future__ import annotations

import numpy as np
import pytest
from drawing_support import FakeSheet


@pytest.fixture
def tilted_a5() -> FakeSheet:
    """An A5 sheet on a board tilted 30 degrees about the world x axis."""
    t = np.radians(30.0)
    return FakeSheet(
        0.210,
        0.148,
        np.array([0.15, -0.105, 0.02]),
        np.array([0.0, 1.0, 0.0]),
        np.array([-np.cos(t), 0.0, np.sin(t)]),
    )
