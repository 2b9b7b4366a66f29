"""The OWI-535's three command bytes, as data (seed 000, Tables 1-3).

A command is the set of motors that run and in which direction, plus the
light. Byte 0 holds OR-able flags for the gripper, wrist, elbow and shoulder,
byte 1 the base, byte 2 the light. Directions follow the model's joint
angles: +1 = forwards / towards a larger angle, -1 = backwards; for the
gripper +1 = open, -1 = close.
"""

from __future__ import annotations

from collections.abc import Mapping

from .._errors import InputError

# (motor, direction) -> bit in byte 0
BYTE0_FLAGS: dict[tuple[str, int], int] = {
    ("gripper", -1): 0x01,
    ("gripper", +1): 0x02,
    ("wrist", -1): 0x04,
    ("wrist", +1): 0x08,
    ("elbow", -1): 0x10,
    ("elbow", +1): 0x20,
    ("shoulder", -1): 0x40,
    ("shoulder", +1): 0x80,
}
# (motor, direction) -> value of byte 1 (000: 0x01 = right = positive base angle)
BYTE1_VALUES: dict[tuple[str, int], int] = {("base", +1): 0x01, ("base", -1): 0x02}
LIGHT_ON = 0x01
MOTORS = ("base", "shoulder", "elbow", "wrist", "gripper")


def encode(motion: Mapping[str, int], light: bool, base_reversed: bool = False) -> bytes:
    """The 3 data bytes that run ``motion`` ({motor: +1 | -1}) with the light on or off.

    Motors not in ``motion`` (or with direction 0) are stopped. ``base_reversed``
    swaps the two base values, for units whose base turns the other way.

    Raises:
        ValueError: an unknown motor or a direction other than -1, 0, +1.
    """
    b0, b1 = 0, 0
    for motor, direction in motion.items():
        if direction == 0:
            continue
        key = _checked(motor, direction)
        if motor == "base":
            b1 = BYTE1_VALUES[(motor, -direction if base_reversed else direction)]
        else:
            b0 |= BYTE0_FLAGS[key]
    return bytes((b0, b1, LIGHT_ON if light else 0x00))


def decode(data: bytes, base_reversed: bool = False) -> tuple[dict[str, int], bool]:
    """Inverse of :func:`encode`: ({motor: direction}, light) from 3 bytes.

    Raises:
        ValueError: not 3 bytes, or opposite directions of one motor at once.
    """
    if len(data) != 3:
        raise InputError(f"an OWI-535 command has 3 bytes, got {len(data)}")
    motion: dict[str, int] = {}
    for (motor, direction), bit in BYTE0_FLAGS.items():
        if data[0] & bit:
            if motor in motion:
                raise InputError(f"byte 0x{data[0]:02x} runs the {motor} both ways at once")
            motion[motor] = direction
    for (motor, direction), value in BYTE1_VALUES.items():
        if data[1] == value:
            motion[motor] = -direction if base_reversed else direction
    return motion, bool(data[2] & LIGHT_ON)


def _checked(motor: str, direction: int) -> tuple[str, int]:
    if motor not in MOTORS:
        raise InputError(f"unknown OWI-535 motor {motor!r}; motors are {', '.join(MOTORS)}")
    if direction not in (-1, 1):
        raise InputError(f"direction of the {motor} must be -1, 0 or +1, got {direction}")
    return (motor, direction)
