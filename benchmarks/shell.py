"""The shell's response time per command on the simulated OpenManipulator-X.

One ``Session`` (what ``armkit shell`` runs; no process is started per command)
on the simulator. Each command is timed from the line typed to the reply, over
many repetitions, and split into the shell's own work (parse, check on the
model, dispatch) and the time spent inside the driver (the simulator computing
the motion at 1 kHz of simulated time). Target: under 20 ms per command.

Run: .venv/bin/python benchmarks/shell.py [--repeat N]
"""

from __future__ import annotations

import argparse
import os
import statistics
import tempfile
import time
from typing import Any

import numpy as np
from numpy.typing import NDArray

from armkit import Arm
from armkit.connect import open_driver
from armkit.model import load_model
from armkit.script._session import Session

# (label, the lines typed; the last one is timed). Moves alternate so every one moves.
COMMANDS = [
    ("where", ["where"]),
    ("pose NAME = xyz ...", ["pose p = xyz 180 0 80 pitch -90"]),
    ("move POSE (50 mm)", ["move a", "move b"]),
    ("move xyz ... (50 mm)", ["move xyz 180 -25 70 pitch -90", "move xyz 180 25 70 pitch -90"]),
    ("joints ... (5 deg)", ["joints 0 10 -20 95", "joints 5 10 -20 95"]),
    ("turn waist by 2", ["turn waist by 2", "turn waist by -2"]),
    ("line (20 mm, 50 mm/s)", ["line xyz 180 0 70 pitch -90", "line xyz 180 20 70 pitch -90"]),
    ("grip (5 mm)", ["grip 40", "grip 45"]),
    ("a mistake (refused)", ["mvoe a"]),
    ("repeat 3 ... end (3 turns)", ["repeat 3\nturn wrist by 1\nend", "turn wrist by -3"]),
]


class TimedDriver:
    """Passes through to the simulator, adding up the wall time spent inside it."""

    def __init__(self, inner: Any) -> None:
        self.inner, self.clock, self.spent = inner, inner.clock, 0.0

    joint_names = property(lambda self: self.inner.joint_names)

    def _timed(self, name: str, *args: Any, **kwargs: Any) -> Any:
        t0 = time.perf_counter()
        try:
            return getattr(self.inner, name)(*args, **kwargs)
        finally:
            self.spent += time.perf_counter() - t0

    def move(self, q: NDArray[np.float64], **kw: Any) -> None:
        self._timed("move", q, **kw)

    def grip(self, width: float) -> None:
        self._timed("grip", width)

    def read(self) -> NDArray[np.float64]:
        return self._timed("read")  # type: ignore[no-any-return]

    def stop(self) -> None:
        self.inner.stop()

    def close(self) -> None:
        self.inner.close()


def main() -> None:
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=200, help="timings per command")
    args = parser.parse_args()
    os.environ.setdefault("ARMKIT_CONFIG_DIR", tempfile.mkdtemp())
    model = load_model("openmanipulator_x")
    driver = TimedDriver(open_driver(model, "sim"))
    session = Session(Arm(model, driver), base_dir=tempfile.gettempdir())  # type: ignore[arg-type]
    for line in ("pose a = xyz 180 -25 70 pitch -90", "pose b = xyz 180 25 70 pitch -90", "move a"):
        assert session.handle(line).text == "", line
    print(f"armkit shell response per command, simulated {model.name}, {args.repeat} runs each\n")
    print(
        f"{'command':28} {'median ms':>10} {'p95 ms':>8} {'max ms':>8} {'shell ms':>9} {'sim ms':>7}"
    )
    for label, lines in COMMANDS:
        total, inside = [], []
        for k in range(args.repeat):
            line = lines[k % len(lines)]
            before = driver.spent
            t0 = time.perf_counter()
            for part in line.split("\n"):
                session.handle(part)
            total.append((time.perf_counter() - t0) * 1000)
            inside.append((driver.spent - before) * 1000)
        own = [t - s for t, s in zip(total, inside, strict=True)]
        p95 = float(np.percentile(total, 95))
        print(
            f"{label:28} {statistics.median(total):10.2f} {p95:8.2f} {max(total):8.2f} "
            f"{statistics.median(own):9.2f} {statistics.median(inside):7.2f}"
        )
    print("\nshell ms: parse + check on the model + dispatch; sim ms: inside the simulated driver")


if __name__ == "__main__":
    main()
