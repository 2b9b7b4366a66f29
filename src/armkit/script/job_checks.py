"""The jobs' argument checks as ``armkit check`` runs them (``_job_checks``), public for
the job specs (``armkit.jobs``), which reference them by a small function each."""

from ._job_checks import draw as draw
from ._job_checks import move_item as move_item
from ._job_checks import pick as pick
from ._job_checks import place as place
from ._job_checks import play as play
from ._job_checks import rotate_cube as rotate_cube
from ._job_checks import search as search
from ._job_checks import stack as stack
