"""Old import path of :mod:`graspcompass.scene.labelling` (issue 23): the same module object."""

import sys

from .scene import labelling as _module

sys.modules[__name__] = _module
