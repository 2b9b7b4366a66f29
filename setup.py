"""The compiled part of armkit: the LM IK kernel (src/armkit/kinematics/_numeric/_lmc.c),
built by ``pip install -e .`` (everything else is in pyproject.toml).

The extension is optional: where no C compiler is found the install still succeeds and
armkit works, except numeric LM IK, which then raises an ArmkitError saying how to build
it (kinematics/_numeric/_lm.py; tests/numeric/test_numeric_kernel_missing.py)."""

from setuptools import Extension, setup

setup(
    ext_modules=[
        Extension(
            "armkit.kinematics._numeric._lmc",
            ["src/armkit/kinematics/_numeric/_lmc.c"],
            extra_compile_args=["-O2"],
            optional=True,
        )
    ]
)
