"""``armkit check`` and ``armkit run`` agree on random scripts (issue 26, point 2): on the
simulated OpenManipulator-X, Lynx6 and OWI-535, the line a script's check says fails
first, and why, is the line its run stops at, and the check's time is the run's
simulated time within 1 %.

The scripts (``check_run_scripts.generate``) have moves, lines, joint moves, turns,
grips, speeds, waits, poses, repeats, procedures, every job of the language (pick,
place, move-item, rotate-cube, stack, draw, play; ``search`` in scripts of their own)
and mistakes, drawn from fixed seeds: ``make test`` runs the first 3 per arm,
``.ci/run`` (``ARMKIT_PROFILE=ci``) the first 40, and benchmarks/check_run.py 500,
printing a table.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from check_run_compare import check_and_run
from check_run_scripts import ARMS, JOBS_OF, MOTIONS, SCENES, generate

from armkit.script import Source, check_source, parse
from budget import cases

SCRIPTS = cases(40, 3)  # per arm; benchmarks/check_run.py runs 500


# Known gap (docs/performance.md, "Check equals run"): the check plans a search on the
# sensor's noiseless curve, the simulated GP2D120 adds its noise, so on these seeds the
# run locates the object a few degrees off and misses the grasp the check planned. Each
# must still disagree (a seed that agrees is reported, so it is removed when fixed).
NOISY_SEARCHES = {("lynx6", 5), ("lynx6", 85), ("lynx6", 384), ("openmanipulator_x", 134)}
NOISY_SEARCHES |= {("openmanipulator_x", 220)}


def _disagreements(arm: str, tmp_path: Path, search: bool) -> list[str]:
    found = []
    for seed in range(SCRIPTS):
        folder = tmp_path / f"seed{seed}"
        folder.mkdir()
        outcome = check_and_run(generate(arm, seed, search=search), folder)
        known = search and (arm, seed) in NOISY_SEARCHES
        if (outcome.disagreement() is not None) != known:
            found.append(outcome.report() if not known else f"{arm} seed {seed} agrees now")
    return found


@pytest.mark.parametrize("arm", ARMS)
def test_check_says_what_run_does(arm: str, tmp_path: Path) -> None:
    found = _disagreements(arm, tmp_path, search=False)
    assert not found, f"{len(found)} of {SCRIPTS} scripts:\n\n" + "\n\n".join(found)


@pytest.mark.parametrize("arm", ARMS)
def test_check_says_what_run_does_with_a_search(arm: str, tmp_path: Path) -> None:
    found = _disagreements(arm, tmp_path, search=True)
    assert not found, f"{len(found)} of {SCRIPTS} scripts:\n\n" + "\n\n".join(found)


@pytest.mark.parametrize("arm", ARMS)
def test_the_scripts_have_every_statement_job_and_mistake(arm: str) -> None:
    # the property means little if the generator never writes a job or a mistake
    seen: set[str] = set()
    for seed in range(300):
        script = generate(arm, seed, search=None)
        problems = parse_problems(script.text)
        assert problems == [], f"seed {seed}: {problems}\n{script.text}"
        seen |= script.features
    jobs = {job for scene, jobs in JOBS_OF.items() for job in jobs if arm_uses(arm, scene)}
    wanted = {*MOTIONS[arm], *jobs, "repeat", "define", "pose", "mistake"}
    assert wanted <= seen, f"never written: {sorted(wanted - seen)}"


def parse_problems(text: str) -> list[str]:
    """What the parser says is wrong with ``text``."""
    return [d.message for d in parse(Source("gen.arm", text))[1]]


def arm_uses(arm: str, scene: str | None) -> bool:
    """Whether ``arm``'s scripts are written for ``scene``."""
    return any(name == scene for name, _ in SCENES[arm])


def test_the_first_error_is_the_one_a_run_meets_first() -> None:
    # an error in a body that never runs (repeat 0) is reported but is not where a run
    # stops; the first error met is the one on line 4
    text = "repeat 0\n  turn elbw by 10\nend\nmove xyz 900 0 50\nmove xyz 0 0 -900\n"
    result = check_source(Source("gen.arm", text))
    assert [d.loc.line for d in result.diagnostics] == [2, 4, 5]
    assert result.first_error is not None and result.first_error.loc.line == 4
