"""The jobs on the simulator (issue 12, point 6), printed as tables.

1. 001's board task (rotate three cubes in place, then stack them) on the
   OpenManipulator-X and the Lynx6 (the Lynx6's wrist cannot hold a cube level, so
   it stacks without turning them, the board 20 mm nearer its base): success, the
   largest final pose error of a cube, the task's simulated time, and the planning
   time (CPU, median of 5; target <= 50 ms for the whole task on the OpenManipulator-X).
2. The same with every cube's true position shifted by an unknown offset of 1, 2,
   3 and 5 mm in a random direction (the plan uses the scene's positions): the
   success rate against the offset, i.e. how forgiving the grasp is.
3. 002's search on the Lynx6 at N random placements of its object (servo angle
   35..115 deg, 160..250 mm from the base, turned up to 15 deg from facing the arm),
   the sensor's noise seeded per placement: found %, picked % (in the bin; target
   >= 95 %), median and max localisation error (target median <= 5 mm).

Run: .venv/bin/python benchmarks/tasks.py [N placements, default 200]
"""

from __future__ import annotations

import math
import os
import sys
import time
from dataclasses import replace

import numpy as np

from armkit import Arm, ArmkitError, tasks
from armkit.scene import Cube, Scene, ScenePhysics, load_scene
from armkit.sim import World
from armkit.tasks._plan import pose_error

CUBES = ["green", "red", "blue"]
OFFSETS_MM = (1.0, 2.0, 3.0, 5.0)
TRIALS = 6  # per offset and arm


def board(arm_name: str) -> tuple[Scene, str | None]:
    """The board scene for ``arm_name`` and how it turns the cubes first."""
    scene = load_scene("board_001")
    if arm_name == "lynx6":
        T = np.eye(4)
        T[0, 3] = -0.02
        return replace(scene, T_world_base=T), None
    return scene, "forward"


def board_task(arm_name: str, shift: float = 0.0, seed: int = 0) -> tuple[bool, float, float]:
    """Plan with the scene, run with the cubes shifted ``shift`` [m]: (success, largest
    pose error [mm], simulated time [s])."""
    scene, turn = board(arm_name)
    rng = np.random.default_rng(seed)
    moved = []
    for c in scene.cubes:
        a = rng.uniform(0, 2 * math.pi)
        moved.append(Cube(c.name, c.size, c.position + shift * np.array([math.cos(a), math.sin(a), 0.0]), c.yaw, c.up_face))  # fmt: skip
    world = World()
    arm = Arm(arm_name, "sim", world=world)
    plan = tasks.stack(arm, scene, CUBES, rotate_first=turn, dry_run=True)
    # the true cubes, attached AFTER planning under the scene's own name: running the
    # plan keeps this physics (it attaches a scene's only when none of that name is)
    truth = ScenePhysics(replace(scene, cubes=tuple(moved)))
    tasks.attach_scene(arm, truth.scene, truth)
    assert tasks.attached(arm) is truth
    t0 = world.now()
    try:
        tasks.run_verified(arm, plan, poses=False)
        ok = True
    except ArmkitError:
        ok = False
    assert tasks.attached(arm) is truth, "the run replaced the true cubes' physics"
    errors = [pose_error(truth.cube(c.name), c)[0] * 1000 for c in plan.after.cubes]
    placed = {c.name: c.position for c in moved}
    moved_mm = max(
        float(np.linalg.norm(truth.cube(name).position - placed[name])) * 1000 for name in placed
    )
    assert shift > 0 or not ok or moved_mm > 10, "the cubes never moved: the harness is broken"
    return ok, max(errors), world.now() - t0


def planning_ms(arm_name: str, runs: int = 15) -> tuple[float, float, float]:
    """CPU time of planning the whole board task [ms] over ``runs`` plannings (CPU, not
    wall: on a shared machine the wall time depends on the neighbours): mean, median, max."""
    scene, turn = board(arm_name)
    arm = Arm(arm_name, "sim", world=World())
    times = []
    for _ in range(runs):
        start = time.process_time()
        tasks.stack(arm, scene, CUBES, rotate_first=turn, dry_run=True)
        times.append(time.process_time() - start)
    ms = np.array(times) * 1000
    return float(ms.mean()), float(np.median(ms)), float(ms.max())


def table_board() -> None:
    print("001 board task (rotate and stack three cubes; Lynx6: stack only); the cubes")
    print("moved by the simulator, their error from the plan's poses measured after the run")
    print(
        "plan ms: CPU of planning the whole task, 15 plannings (target <= 50 ms, OpenManipulator-X)"
    )
    print(f"{'arm':18s} {'success':>7s} {'max err mm':>10s} {'task s':>7s} "
          f"{'plan mean':>9s} {'median':>7s} {'max':>7s}")  # fmt: skip
    for name in ("openmanipulator_x", "lynx6"):
        ok, err, t = board_task(name)
        mean, med, worst = planning_ms(name)
        print(f"{name:18s} {'yes' if ok else 'NO':>7s} {err:10.2f} {t:7.1f} "
              f"{mean:9.1f} {med:7.1f} {worst:7.1f}")  # fmt: skip
    print()
    print(f"unknown offsets of every cube: success rate over {TRIALS} placements (no cube")
    print("missed, dropped or tipped) / median of the largest cube error from the plan [mm]")
    print(f"{'arm':18s} " + " ".join(f"{o:>13.0f}mm" for o in OFFSETS_MM))
    for name in ("openmanipulator_x", "lynx6"):
        cells = []
        for off in OFFSETS_MM:
            runs = [board_task(name, off / 1000, seed) for seed in range(TRIALS)]
            wins = sum(ok for ok, _, _ in runs)
            err = float(np.median([e for _, e, _ in runs]))
            cells.append(f"{100 * wins / TRIALS:6.0f}% {err:6.1f}mm")
        print(f"{name:18s} " + " ".join(cells))
    print()


def placement(rng: np.random.Generator) -> Cube:
    """A random object on 002's field (see the module doc)."""
    angle = math.radians(rng.uniform(35.0, 115.0)) - math.pi / 2
    r = rng.uniform(0.16, 0.25)
    yaw = angle + math.radians(rng.uniform(-15.0, 15.0))
    return Cube("object", 0.025, np.array([r * math.cos(angle), r * math.sin(angle), 0.0]), yaw)


def search_once(scene: Scene, cube: Cube, seed: int) -> tuple[bool, bool, float | None]:
    """(found, picked into the bin, localisation error [mm] or None)."""
    arm = Arm("lynx6", "sim", world=World())
    placed = replace(scene, cubes=(cube,))
    try:
        result = tasks.search(arm, placed, seed=seed)
    except ArmkitError:
        result = None
    physics = tasks.attached(arm)
    if result is None or not result.found or result.position is None or physics is None:
        return result is not None and result.found, False, None
    error = float(np.linalg.norm(result.position[:2] - cube.position[:2] * 1000))  # mm
    box = scene.container("bin")
    inside = bool(np.all(np.abs(physics.cube("object").center[:2] - box.position[:2]) < 0.04))
    return True, inside, error


def table_search(n: int) -> None:
    scene = load_scene("search_002")
    rng = np.random.default_rng(2)
    rows = [search_once(scene, placement(rng), seed) for seed in range(n)]
    errors = [e for _, _, e in rows if e is not None]
    found = 100 * sum(f for f, _, _ in rows) / n
    picked = 100 * sum(p for _, p, _ in rows) / n
    print(f"002 search on the Lynx6, {n} random placements, sensor noise 10 mV")
    print(f"{'found':>7s} {'picked':>7s} {'median err mm':>14s} {'max err mm':>11s}")
    med = float(np.median(errors)) if errors else float("nan")
    worst = max(errors) if errors else float("nan")
    print(f"{found:6.1f}% {picked:6.1f}% {med:14.2f} {worst:11.2f}")


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    start = time.perf_counter()
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    table_board()
    table_search(n)
    print(f"\n(benchmark ran {time.perf_counter() - start:.0f} s)")
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")


if __name__ == "__main__":
    main()
