"""The jobs, declared once: one ``JobSpec`` per job (its function by reference, its
parameters with their units, defaults, bounds and how each surface writes them), from
which both the script's statement (``armkit.script``) and the CLI's sub-command
(``armkit.cli``) are built. Light to import: no numpy, no job package until a job runs."""

from ._options import NOTHING_PICKED as NOTHING_PICKED
from ._spec import METAVAR as METAVAR
from ._spec import UNIT as UNIT
from ._spec import JobParam as JobParam
from ._spec import JobSpec as JobSpec
from ._spec import as_function_gets as as_function_gets
from ._table import CLI_JOBS as CLI_JOBS
from ._table import JOBS as JOBS
from ._table import job_spec as job_spec
