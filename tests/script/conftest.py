"""Fixtures for the script tests: a private config directory and a counting arm."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from script_arms import CountingDriver, counting_arm

from armkit import Arm


@pytest.fixture
def arm() -> Iterator[tuple[Arm, CountingDriver]]:
    a, d = counting_arm()
    yield a, d
    a.close()
