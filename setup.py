"""The compiled parts of armkit, built by ``pip install -e .`` (everything else is in
pyproject.toml): the LM IK kernel (src/armkit/kinematics/_numeric/_lmc.c) and the
position-only closed form's boundary search (src/armkit/kinematics/_boundaryc.c).

Both are optional: where no C compiler is found the install still succeeds and armkit
works, except numeric LM IK, which then raises an ArmkitError saying how to build it
(kinematics/_numeric/_lm.py), and the boundary search runs its numpy reference in floats
(tests/numeric/test_numeric_kernel_missing.py)."""

from setuptools import Extension, setup

setup(
    ext_modules=[
        Extension(
            "armkit.kinematics._numeric._lmc",
            ["src/armkit/kinematics/_numeric/_lmc.c"],
            extra_compile_args=["-O2"],
            optional=True,
        ),
        Extension(
            "armkit.kinematics._boundaryc",
            ["src/armkit/kinematics/_boundaryc.c"],
            extra_compile_args=["-O2"],
            optional=True,
        ),
    ]
)
