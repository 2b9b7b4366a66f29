"""``ArmModel.with_tool_length`` takes a tool length [m] as a model file does: 0 or
0.01 mm..10 m. Was: ``with_tool_length(130)`` (130 mm given as metres) and
``with_tool_length(-0.1)`` gave a model whose every pose was wrong."""

from __future__ import annotations

import math

import numpy as np
import pytest

from armkit import InputError
from armkit.model import load_model

OMX = load_model("openmanipulator_x")


@pytest.mark.parametrize(
    "length, got",
    [
        (130, r"got 130 m \(130000\.0 mm\); is 130 in mm\? give 0\.13"),
        (10.001, r"got 10\.001 m \(10001\.0 mm\); is 10\.001 in mm\? give 0\.010001"),
        (-0.1, r"got -0\.1 m \(-100\.0 mm\)$"),
        (1e-9, r"got 1e-09 m \(0\.0 mm\)$"),
        (math.nan, r"got nan$"),
        (math.inf, r"got inf$"),
        ("0.13", r"got '0\.13'$"),
        (True, r"got True$"),
        (None, r"got None$"),
    ],
)
def test_a_tool_length_that_no_tool_has_is_refused(length: object, got: str) -> None:
    with pytest.raises(InputError, match=r"^tool length must be 0 \(no tool: the flange point\) "
                       r"or 0\.01 mm\.\.10 m, given in metres \(130 mm is 0\.13\), " + got):  # fmt: skip
        OMX.with_tool_length(length)  # type: ignore[arg-type]


@pytest.mark.parametrize("length", [0, 0.0, 0.13, np.float64(0.05), 1, 10.0, 1e-5])
def test_a_plausible_tool_length_is_taken(length: float) -> None:
    m = OMX.with_tool_length(length)
    assert m.tool_length == float(length) and type(m.tool_length) is float
    back = m.with_tool_length(OMX.tool_length)
    assert np.allclose(back.T_flange_tool, OMX.T_flange_tool)
