"""The pieces the factory (``armkit.connect``) assembles simulated rigs from.

A public face over the simulator's private assembly modules, imported only when a
simulated rig is built (it loads every simulated device and the pseudo-terminal
wire, which ``import armkit`` does not need).
"""

from ._assemble import Persistence as Persistence
from ._assemble import add_owi_arm as add_owi_arm
from ._assemble import add_servo_arm as add_servo_arm
from ._outbox import ByteDevice as ByteDevice
from ._servo_body import GRIPPER as GRIPPER
from ._servo_body import Mount as Mount
from ._wire import Wire as Wire
from ._wire import serial_port as serial_port
