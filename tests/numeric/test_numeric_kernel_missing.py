"""An armkit installed without its compiled LM kernel (an sdist on a machine with no C
compiler: setup.py builds the extension as optional) still imports and runs everything
but numeric LM IK (ik and ik_batch with method 'lm', and arms with no closed form), which raises one ArmkitError saying how to build it; the CLI says it
in one line. Run in a child process with the kernel's import made to fail."""

from __future__ import annotations

import subprocess
import sys
import textwrap

CHILD = textwrap.dedent(
    """
    import sys
    sys.modules["armkit.kinematics._numeric._lmc"] = None  # import fails: not built
    import numpy as np
    import armkit
    from armkit import ArmkitError, Target, ik, ik_batch, load_model
    from armkit.kinematics._numeric import _lm
    assert _lm.KERNEL_MISSING
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
    from armkit.cli import main
    sys.exit(main(["--arm", "so101", "ik", "200", "0", "100", "--method", "lm"]))
    """
)


def test_without_the_kernel_armkit_works_and_lm_says_how_to_build_it() -> None:
    out = subprocess.run([sys.executable, "-c", CHILD], capture_output=True, text=True)
    lines = out.stdout.splitlines()
    assert lines[:5] == ["closed form analytic", "ccd ccd"] + ["refused True"] * 3, out
    assert out.returncode != 0
    err = out.stderr.strip().splitlines()
    assert len(err) == 1 and "C compiler" in err[0] and "Traceback" not in out.stderr, err
