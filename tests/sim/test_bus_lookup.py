"""The simulated Dynamixel bus finds a sync instruction's servo by ID without sorting
every servo (issue 29 item 6: the lookup runs for each ID of each streamed packet):
``by_id`` is pinned to its reference, the first servo of ``present()`` with that ID,
over random buses (duplicate IDs after a change of the ID register, vanished servos,
other baud rates and protocols, the host's rate known or not)."""

from __future__ import annotations

import random

from armkit.sim.dynamixel import SimDynamixelBus


def reference(bus: SimDynamixelBus, servo_id: int) -> object:
    return next((s for s in bus.present() if s.value("ID") == servo_id), None)


def test_by_id_is_the_first_present_servo_with_that_id() -> None:
    rng = random.Random(29)
    for _ in range(300):
        bus = SimDynamixelBus(rng.sample(range(1, 12), rng.randint(1, 6)), clock=lambda: 0.0)
        for servo in bus.servos.values():
            if rng.random() < 0.4:
                servo.set("ID", rng.randint(1, 5))
            if rng.random() < 0.2:
                servo.set("Baud Rate", rng.choice((1, 3)))  # 57,600 or 1,000,000 bit/s
            if rng.random() < 0.1:
                servo.set("Protocol Type", 1)
        for sid in bus.servos:
            if rng.random() < 0.15:
                bus.inject(sid, "vanish")
        bus.hear(b"", 0.0, rng.choice((None, 57_600, 1_000_000)))  # the host's rate
        for servo_id in range(0, 13):
            assert bus.by_id(servo_id) is reference(bus, servo_id)
