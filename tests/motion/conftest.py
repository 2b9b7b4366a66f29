"""Shared fixtures: the simulator's state file goes to a temporary directory."""

from __future__ import annotations

import pytest

from armkit.model import ArmModel, load_model


@pytest.fixture(scope="session")
def omx() -> ArmModel:
    return load_model("openmanipulator_x")


@pytest.fixture(scope="session")
def lynx6() -> ArmModel:
    return load_model("lynx6")
