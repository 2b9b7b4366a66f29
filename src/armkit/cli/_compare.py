"""``armkit compare-ik``: every IK method on the same random reachable targets (seed 003)."""

from __future__ import annotations

import argparse
import math
from typing import TYPE_CHECKING, Any

from .._errors import ArmkitError
from .._files import check_output_path
from .._progress import Progress
from ._args import IMAGE_SUFFIXES, integer
from ._ik_tasks import TASKS
from ._table import table

if TYPE_CHECKING:
    from ._compare_methods import MethodScore


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``compare-ik``."""
    p = sub.add_parser(
        "compare-ik",
        help="compare the IK methods (analytic, lm, lm-batch, ccd, jacobian, random) on one arm",
        description="Run every IK method on the same random reachable targets (FK of random joint "
        "vectors inside the limits, fixed seed), each from the home pose, and print: verified "
        "success (FK within 1 mm, and 0.1 deg for pitch/pose tasks, joints inside the limits), "
        "median and p95 time per call [us], median iterations, median position error [mm].",
    )
    p.add_argument(
        "--n",
        type=integer("targets", 1, 100_000),
        default=1000,
        metavar="N",
        help="number of targets, 1..100000 (default 1000)",
    )
    p.add_argument(
        "--seed",
        type=integer("", 0, 2**32 - 1),
        default=0,
        metavar="S",
        help="random seed (default 0)",
    )
    p.add_argument(
        "--task",
        choices=TASKS,
        default=None,
        help="what each target asks for (default: pose for 6 joints, position+pitch for 4-5, "
        "else position)",
    )
    p.add_argument(
        "--repeats",
        type=integer("repeats", 1, 20),
        default=1,
        metavar="R",
        help="time every call R times and keep the fastest, 1..20 (default 1; use 3 on a busy machine)",
    )
    p.add_argument("--plot", metavar="FILE", default=None, help="also write a chart (plot extra)")
    p.set_defaults(func=run_compare)


def run_compare(args: argparse.Namespace) -> int:
    """Print the comparison table; write the chart if asked."""
    from ..model import load_model
    from ._compare_methods import (
        applicable_methods,
        compare_methods,
        default_task,
        reachable_targets,
    )

    model = load_model(args.arm)
    if args.plot:
        check_output_path(args.plot, "--plot", IMAGE_SUFFIXES)
    task = args.task or default_task(model)
    targets = reachable_targets(model, args.n, args.seed, task)
    print(
        f"{model.name}: {args.n} reachable targets, task {task}, seed {args.seed}, from home, "
        f"fastest of {args.repeats}",
        flush=True,
    )
    methods = applicable_methods(model, task)
    with Progress("compare-ik", args.n * len(methods), "calls") as bar:
        done = {m: 0 for m in methods}

        def progress(method: str, n: int) -> None:
            done[method] = n
            bar.update(sum(done.values()), f"method {method}")

        scores = compare_methods(model, targets, methods, args.repeats, progress)
    print(score_table(scores))
    if args.plot:
        plot_scores(scores, args.plot, f"{model.name}, {args.n} targets, {task}")
        print(f"wrote {args.plot}")
    return 0


def score_table(scores: list[MethodScore]) -> str:
    """The table: method, success %, median/p95 [us], iterations, error [mm]."""
    headers = ["method", "success %", "median us", "p95 us", "median iter", "median err mm"]
    rows = [
        [
            s.method,
            f"{100 * s.success:.1f}",
            f"{s.median_s * 1e6:.1f}",
            "-" if math.isnan(s.p95_s) else f"{s.p95_s * 1e6:.1f}",
            "-" if math.isnan(s.median_iterations) else f"{s.median_iterations:.0f}",
            "-" if math.isnan(s.median_error) else f"{s.median_error * 1000:.2g}",
        ]
        for s in scores
    ]
    return table(headers, rows)


def plot_scores(scores: list[MethodScore], path: str, title: str) -> None:
    """Bar charts of success and median time per method, written to ``path``."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise ArmkitError("--plot needs matplotlib: pip install 'armkit[plot]'") from None
    names = [s.method for s in scores]
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    left.bar(names, [100 * s.success for s in scores], color="tab:green")
    left.set_ylabel("verified success [%]")
    left.set_ylim(0, 100)
    right.bar(names, [s.median_s * 1e6 for s in scores], color="tab:blue")
    right.set_yscale("log")
    right.set_ylabel("median time per target [us]")
    for ax in (left, right):
        ax.tick_params(axis="x", rotation=30)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
