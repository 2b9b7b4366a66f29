"""armkit: drive cheap robot arms by where the gripper should go."""

__version__ = "0.1.0"
