"""What real physics adds to the simulator (issue 32 item 3): the 001 board task
(``stack red green blue`` on ``board_001``, the OpenManipulator-X) under the rules
and under MuJoCo side by side.

1. Success against how far red really is from where the plan believes it (0..8 mm
   outwards along the arm's line; past 4.5 mm it stands on its holder's rim) and
   the pads' and cubes' friction coefficient (0.3..1.0; the rules have none): "ok",
   or the first thing that went wrong, as the task reports it.
2. The real-time factor: simulated seconds per CPU second of the whole process
   (driver, protocol, simulated devices, world and its physics) for the task,
   under each physics (issue 32's target for MuJoCo: >= 10x).
3. Grip force and slip while ``stack`` holds each cube under MuJoCo (friction 1.0).

Run: .venv/bin/python benchmarks/physics.py [--quick]   (--quick: errors 0, 4, 8 mm;
friction 0.3, 1.0)
"""

from __future__ import annotations

import contextlib
import os
import sys
import tempfile
import time
from dataclasses import replace

import numpy as np

from armkit import Arm, load_model, tasks
from armkit.physics import MujocoPhysics
from armkit.scene import Cube, Rect, Scene, ScenePhysics, load_scene, support_under

CUBES = ("red", "green", "blue")


def truth(scene: Scene, error_mm: float) -> Scene:
    """``scene`` with red ``error_mm`` [mm] farther out along the arm's line than the file
    says, standing on what is under it there (the holder's floor, else its rim)."""
    red = scene.cube("red")
    out = red.position[:2] / np.linalg.norm(red.position[:2])
    xy = red.position[:2] + out * error_mm / 1000.0
    foot = Rect(xy, (red.size / 2, red.size / 2), red.yaw)
    z = support_under(scene.without_cube("red"), foot, 1.0).z
    moved = Cube("red", red.size, np.array([*xy, z]), red.yaw, red.up_face)
    return scene.with_cube(moved)


def run(physics: str, error_mm: float, friction: float) -> tuple[str, float, float, object]:
    """One board task: its outcome, simulated seconds, CPU seconds and the physics."""
    believed = load_scene("board_001")
    real = truth(believed, error_mm)
    attached = (
        MujocoPhysics(replace(real, physics="mujoco"), friction=friction)
        if physics == "mujoco"
        else ScenePhysics(real)
    )
    with Arm(load_model("openmanipulator_x"), driver="sim") as arm:
        world = arm.world
        assert world is not None
        tasks.attach_scene(arm, believed, attached)  # the world as it is...
        plan = tasks.stack(arm.start(), believed, CUBES)  # ...the plan as the file says
        t0, cpu0 = world.now(), time.process_time()
        try:
            tasks.run_verified(arm, plan)
            outcome = "ok"
        except tasks.TaskFailed as exc:
            outcome = exc.detail if len(exc.detail) < 60 else exc.detail[:57] + "..."
        return outcome, world.now() - t0, time.process_time() - cpu0, attached


def success_table(errors: list[float], frictions: list[float]) -> None:
    print("\n1. stack red green blue, red farther out than planned (mm) x friction")
    print(f"{'physics':<8} {'friction':>8} {'error mm':>8}  outcome")
    for physics, fs in (("rules", [frictions[-1]]), ("mujoco", frictions)):
        for friction in fs:
            for error in errors:
                outcome, *_ = run(physics, error, friction)
                shown = "-" if physics == "rules" else f"{friction:.1f}"
                print(f"{physics:<8} {shown:>8} {error:8.1f}  {outcome}", flush=True)


def speed_table() -> MujocoPhysics:
    print("\n2. real-time factor of the board task (simulated s per CPU s, whole process)")
    print(f"{'physics':<8} {'sim s':>7} {'CPU s':>7} {'factor':>7} {'target':>7}")
    found = None
    for physics, target in (("rules", ""), ("mujoco", ">= 10")):
        outcome, sim_s, cpu_s, attached = run(physics, 0.0, 1.0)
        print(f"{physics:<8} {sim_s:7.1f} {cpu_s:7.2f} {sim_s / cpu_s:7.1f} {target:>7}  {outcome}")
        if isinstance(attached, MujocoPhysics):
            found = attached
    assert found is not None
    return found


def grip_table(physics: MujocoPhysics) -> None:
    print("\n3. grip force and slip while stack holds each cube (MuJoCo, friction 1.0)")
    print(f"{'cube':<6} {'held s':>7} {'force N':>8} {'min N':>6} {'slip mm':>8}")
    for name in CUBES:
        samples = [g for g in physics.grips if g.cube == name]
        if not samples:
            continue
        force = np.array([g.force for g in samples])
        slip = max(g.slip for g in samples) * 1000.0
        held = len(samples) * 0.01
        print(f"{name:<6} {held:7.2f} {np.median(force):8.2f} {force.min():6.2f} {slip:8.2f}")


def main() -> None:
    quick = "--quick" in sys.argv[1:]
    errors = [0.0, 4.0, 8.0] if quick else [0.0, 2.0, 4.0, 6.0, 8.0]
    frictions = [0.3, 1.0] if quick else [0.3, 0.5, 0.7, 1.0]
    with tempfile.TemporaryDirectory() as config:
        os.environ["ARMKIT_CONFIG_DIR"] = config
        with contextlib.suppress(AttributeError):
            print(f"load {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
        grip_table(speed_table())
        success_table(errors, frictions)


if __name__ == "__main__":
    main()
