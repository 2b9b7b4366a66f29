"""Pictures of arms (matplotlib, imported only when a picture is asked for)."""

from ._pose import plot_pose as plot_pose
