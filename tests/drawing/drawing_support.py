"""Test helpers for the drawing tests: a tiny stand-in for the scene's Sheet."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "drawings"


@dataclass(frozen=True)
class FakeSheet:
    """A sheet on a plane: corner ``origin`` (3,), unit vectors ``u``, ``v`` (3,) [m]."""

    width: float
    height: float
    origin: NDArray[np.float64]
    u: NDArray[np.float64]
    v: NDArray[np.float64]

    def to_world(self, uv: NDArray[np.float64]) -> NDArray[np.float64]:
        uv = np.asarray(uv, dtype=np.float64)
        return self.origin + uv[:, :1] * self.u + uv[:, 1:2] * self.v


def write(tmp_path: Path, name: str, text: str) -> Path:
    p = tmp_path / name
    p.write_text(text)
    return p
