"""The live 3D view in the browser (viser; ``pip install 'armkit[web]'``).

Importing this package imports viser: ``armkit`` itself never does, the
``armkit view`` command imports it only when run.
"""

from ._chromium import Chromium as Chromium
from ._chromium import find_chromium as find_chromium
from ._picture import RENDER_STEPS as RENDER_STEPS
from ._picture import render_png as render_png
from ._render import Renderer as Renderer
from ._teach import TaughtPose as TaughtPose
from ._teach import Teach as Teach
from ._view import View as View
from ._view import ViewStats as ViewStats
