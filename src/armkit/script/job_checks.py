"""The jobs' argument checks as ``armkit check`` runs them (``_job_checks``), public for
the job specs (``armkit.jobs``), which reference them by a small function each."""

from ._job_checks import check_draw as check_draw
from ._job_checks import check_move_item as check_move_item
from ._job_checks import check_pick as check_pick
from ._job_checks import check_place as check_place
from ._job_checks import check_play as check_play
from ._job_checks import check_rotate_cube as check_rotate_cube
from ._job_checks import check_search as check_search
from ._job_checks import check_stack as check_stack
