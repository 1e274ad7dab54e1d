"""Old import path of :mod:`graspcompass.scene.palette` (issue 23): the same module object."""

import sys

from .scene import palette as _module

sys.modules[__name__] = _module
