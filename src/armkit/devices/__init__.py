"""Devices: bytes on the wire (USB control transfers, SSC-32 text, Maestro and Dynamixel packets).

Each module imports its client library (pyusb, pyserial, dynamixel-sdk) only
when a device is opened, so ``import armkit`` never needs them.

The shared wire-level pieces other packages build on (the simulator's devices and
the drivers) are re-exported here: the Dynamixel packet codec and the XM430's
control table as modules (``dxl_packet``, ``xm430``, and its manual's NOTEs as data, ``xm430_notes``), the OWI-535's command bytes
(``owi_encode``/``owi_decode``), the serial port, the SDK port handler and the
"port gone" error.
"""

from . import _dxl_packet as dxl_packet
from . import _scs_packet as scs_packet
from . import _sts3215 as sts3215
from . import _xm430 as xm430
from . import _xm430_notes as xm430_notes
from ._dxl_protocol import PortHandler as PortHandler
from ._owi_commands import decode as owi_decode
from ._owi_commands import encode as owi_encode
from ._port import PortGoneError as PortGoneError
from ._serial import SerialPort as SerialPort

__all__ = [
    "PortGoneError",
    "PortHandler",
    "SerialPort",
    "dxl_packet",
    "owi_decode",
    "owi_encode",
    "scs_packet",
    "sts3215",
    "xm430",
    "xm430_notes",
]
