"""Re-homing: drive each joint against a limit, the only absolute reference an
OWI has, so its angle is known again; then back to home. Afterwards the state
is certain."""

from __future__ import annotations

from collections.abc import Callable

from ._driver import TimedDriver

Say = Callable[[str], None]


def rehome(driver: TimedDriver, say: Say = print, joints: tuple[str, ...] | None = None) -> None:
    """Re-home ``joints`` (None = all, in the model file's ``rehome_order``).

    Each joint in turn runs against its ``rehome_to`` limit for longer than a
    full traverse (the gears slip there) and stays there, its angle now that
    limit; from that known pose the arm goes home and the state is certain.
    """
    cfg = driver.config
    order = joints or cfg.rehome_order
    for name in order:
        direction = 1 if cfg.rehome_to[name] == "upper" else -1
        say(f"re-homing the {name}: driving it against its {cfg.rehome_to[name]} limit")
        driver.drive_to_limit(name, direction)
    if joints is None or set(joints) == set(driver.joint_names):  # every angle is a limit now
        driver.set_state(driver.state.with_(uncertain=False, reason="re-homed"))
    driver.move_report(driver.model.home, table=False)
    say("re-homed: the joint angles are known again")
