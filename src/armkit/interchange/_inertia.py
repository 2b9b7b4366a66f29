"""Mass, centre of mass and inertia of a link made of capsules of uniform density.

A capsule (a cylinder of length L with a half sphere of the same radius r on each
end) of density rho [kg/m^3] has the textbook moments about its centre: along
its axis ``mc r^2 / 2 + ms 2 r^2 / 5``, across it ``mc (L^2 / 12 + r^2 / 4) +
ms (2 r^2 / 5 + L^2 / 4 + 3 L r / 8)``, where mc is the cylinder's mass and ms
the two half spheres'. A link's capsules add by the parallel axis theorem.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]

DENSITY = 1200.0  # [kg/m^3]: ABS/PLA plastic and servos, the cheap arms' stuff


@dataclass(frozen=True, eq=False)
class Inertial:
    """A rigid body's mass properties in some frame.

    Attributes:
        mass: [kg].  com: centre of mass [m], shape (3,).
        inertia: about the centre of mass, axes of the frame [kg m^2], shape (3, 3).
    """

    mass: float
    com: F64
    inertia: F64

    def about(self, point: F64) -> F64:
        """The inertia tensor about ``point`` [m] (parallel axis theorem), shape (3, 3)."""
        d = self.com - point
        shifted: F64 = self.inertia + self.mass * (float(d @ d) * np.eye(3) - np.outer(d, d))
        return shifted


def capsule_inertial(a: F64, b: F64, radius: float, density: float = DENSITY) -> Inertial:
    """The capsule from ``a`` to ``b`` [m] of ``radius`` [m] and ``density`` [kg/m^3]."""
    axis = b - a
    length = float(np.linalg.norm(axis))
    u = axis / length if length > 1e-12 else np.array([0.0, 0.0, 1.0])
    r2 = radius * radius
    mc = density * math.pi * r2 * length
    ms = density * 4.0 / 3.0 * math.pi * r2 * radius
    along = mc * r2 / 2.0 + ms * 2.0 * r2 / 5.0
    across = mc * (length**2 / 12.0 + r2 / 4.0) + ms * (
        2.0 * r2 / 5.0 + length**2 / 4.0 + 3.0 * length * radius / 8.0
    )
    uu = np.outer(u, u)
    return Inertial(mc + ms, 0.5 * (a + b), across * (np.eye(3) - uu) + along * uu)


def combined(parts: list[Inertial]) -> Inertial:
    """One body of ``parts`` (at least one, with a positive total mass)."""
    mass = sum(p.mass for p in parts)
    com = sum((p.mass * p.com for p in parts), np.zeros(3)) / mass
    inertia = sum((p.about(com) for p in parts), np.zeros((3, 3)))
    return Inertial(mass, com, inertia)


def box_inertial(size: tuple[float, float, float], density: float) -> Inertial:
    """A solid box of edges ``size`` [m] centred on the origin."""
    x, y, z = size
    mass = density * x * y * z
    diag = [mass * (y * y + z * z), mass * (x * x + z * z), mass * (x * x + y * y)]
    return Inertial(mass, np.zeros(3), np.diag(diag) / 12.0)
