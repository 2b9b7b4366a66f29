"""What ``compare-ik`` measures: the IK tasks and the methods it runs (names only, so
building the parser loads no kinematics)."""

TASKS = ("position", "position+pitch", "pose")
METHODS = ("analytic", "lm", "lm-batch", "ccd", "jacobian", "random")
