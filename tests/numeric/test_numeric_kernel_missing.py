"""An armkit installed without its compiled parts (an sdist on a machine with no C
compiler: setup.py builds the extensions as optional) still imports and runs everything
but numeric LM IK (method 'lm', and arms with no closed form), which raises one
ArmkitError saying how to build it; the CLI says it in one line. The position-only
boundary search (compiled too) runs its numpy reference in floats, with the same
answers. Run in a child process with the extensions' imports made to fail."""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap

import numpy as np

from armkit import fk, ik, load_model
from armkit.kinematics._chain import chain_of

CHILD = textwrap.dedent(
    """
    import sys
    sys.modules["armkit.kinematics._numeric._lmc"] = None  # import fails: not built
    sys.modules["armkit.kinematics._boundaryc"] = None
    import numpy as np
    import armkit
    from armkit import ArmkitError, Target, ik, ik_batch, load_model
    from armkit.kinematics._numeric import _lm
    from armkit.kinematics import _boundary_fast
    assert _lm.KERNEL_MISSING and _boundary_fast.COMPILED is None
    om = load_model("openmanipulator_x")
    r = ik(om, Target((0.2, 0.0, 0.1), pitch=0.0))
    print("closed form", r.method)
    r = ik(om, Target((0.2, 0.0, 0.1), pitch=0.0), method="ccd")
    print("ccd", r.method)
    for call in (
        lambda: ik(om, Target((0.2, 0.0, 0.1), pitch=0.0), method="lm"),
        lambda: ik(load_model("so101"), Target((0.2, 0.0, 0.1)), method="lm"),
        lambda: ik_batch(load_model("so101"), np.array([[0.2, 0.0, 0.1]]), method="lm"),
    ):
        try:
            call()
        except ArmkitError as e:
            print("refused", "C compiler" in str(e))
    import json
    for p in json.loads(sys.argv[1]):
        print("boundary", ik(om, p).q.round(9).tolist())
    from armkit.cli import main
    sys.exit(main(["--arm", "so101", "ik", "200", "0", "100", "--method", "lm"]))
    """
)


def test_without_the_kernel_armkit_works_and_lm_says_how_to_build_it() -> None:
    om = load_model("openmanipulator_x")
    chain = chain_of(om)
    assert chain.free is not None
    P = fk(om, np.random.default_rng(3).uniform(om.lower, om.upper, (200, om.dof)))[:, :3, 3]
    edge = [p for p in P.tolist() if chain.free(*p, chain.home) == []][:5]
    assert len(edge) == 5
    out = subprocess.run(
        [sys.executable, "-c", CHILD, json.dumps(edge)], capture_output=True, text=True
    )
    lines = out.stdout.splitlines()
    assert lines[:5] == ["closed form analytic", "ccd ccd"] + ["refused True"] * 3, out
    # position-only targets where a joint limit refuses the first pitch: the boundary
    # search runs the lanes in floats, with the compiled search's answers
    assert lines[5:10] == [f"boundary {ik(om, p).q.round(9).tolist()}" for p in edge], out
    assert out.returncode != 0
    err = out.stderr.strip().splitlines()
    assert len(err) == 1 and "C compiler" in err[0] and "Traceback" not in out.stderr, err
