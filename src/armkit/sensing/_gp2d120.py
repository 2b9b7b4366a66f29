"""The Sharp GP2D120 infrared distance sensor: output voltage against distance.

Its datasheet ("Analog output voltage vs. distance to reflective object", white
paper, Vcc = 5 V) gives a curve, not a formula: it rises to about 3 V at 3 cm,
then falls as 1/distance to about 0.4 V at 30 cm. The measuring range is 4..30 cm;
nearer than 3 cm the same voltage comes back (the sensor cannot tell), farther than
30 cm the curve flattens into the noise. ``CURVE`` is that figure read at its grid
points; between them armkit interpolates linearly in 1/distance.
"""

from __future__ import annotations

import numpy as np

# (distance [m], output [V]) read from the datasheet's figure
CURVE = (
    (0.000, 0.90),
    (0.010, 1.60),
    (0.020, 2.60),
    (0.030, 3.05),
    (0.040, 2.75),
    (0.050, 2.30),
    (0.060, 1.98),
    (0.080, 1.55),
    (0.100, 1.27),
    (0.120, 1.07),
    (0.140, 0.93),
    (0.160, 0.82),
    (0.180, 0.74),
    (0.200, 0.67),
    (0.250, 0.53),
    (0.300, 0.43),
    (0.350, 0.36),
    (0.400, 0.31),
    (0.500, 0.26),
    (0.800, 0.20),
)
RANGE = (0.04, 0.30)  # [m] the datasheet's measuring range
PEAK = 3  # index of the curve's maximum (3 cm)
NOISE_V = 0.010  # [V] standard deviation of the output noise (armkit's choice)

_D = np.array([d for d, _ in CURVE])
_V = np.array([v for _, v in CURVE])


def volts(distance: float) -> float:
    """The output [V] for a reflector at ``distance`` [m] (beyond 0.8 m: the 0.8 m value)."""
    d = min(max(distance, 0.0), float(_D[-1]))
    if d <= _D[PEAK]:
        return float(np.interp(d, _D[: PEAK + 1], _V[: PEAK + 1]))
    inv = 1.0 / _D[PEAK:]
    return float(np.interp(1.0 / d, inv[::-1], _V[PEAK:][::-1]))


def distance(output: float) -> float | None:
    """The distance [m] an output ``output`` [V] means, on the falling part of the
    curve; None outside the measuring range (4..30 cm)."""
    lo, hi = volts(RANGE[1]), volts(RANGE[0])
    if not lo <= output <= hi:
        return None
    inv = 1.0 / _D[PEAK:]
    return float(1.0 / np.interp(output, _V[PEAK:][::-1], inv[::-1]))
