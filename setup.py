"""The compiled part of armkit: the LM IK kernel (src/armkit/kinematics/_numeric/_lmc.c),
built by ``pip install -e .`` (everything else is in pyproject.toml)."""

from setuptools import Extension, setup

setup(
    ext_modules=[
        Extension(
            "armkit.kinematics._numeric._lmc",
            ["src/armkit/kinematics/_numeric/_lmc.c"],
            extra_compile_args=["-O2"],
        )
    ]
)
