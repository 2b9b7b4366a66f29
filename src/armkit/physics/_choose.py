"""Which physics moves a scene's objects: the scene's ``physics`` field decides."""

from __future__ import annotations

from ..scene import Scene, ScenePhysics
from ._mujoco import MujocoPhysics


def physics_for(scene: Scene, physics: ScenePhysics | None = None) -> ScenePhysics:
    """The physics to attach for ``scene``: ``physics`` (the objects as kept between
    processes, rule-based) or a fresh one, as MuJoCo's when ``scene.physics`` is
    ``"mujoco"`` (its objects and held cube carried over).

    Raises:
        ArmkitError: MuJoCo is asked for but not installed (nothing moved).
    """
    rules = physics if physics is not None else ScenePhysics(scene)
    if scene.physics != "mujoco" or isinstance(rules, MujocoPhysics):
        return rules
    found = MujocoPhysics(replace_physics(scene, rules.scene))
    if rules.holding is not None:
        found.restore(rules.holding.cube, rules.holding.T_tool_object)
    found.events = list(rules.events)
    return found


def replace_physics(scene: Scene, rest: Scene) -> Scene:
    """``rest`` (the objects at rest) keeping ``scene``'s choice of physics."""
    from dataclasses import replace

    return replace(rest, physics=scene.physics)
