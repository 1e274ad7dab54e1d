"""Old import path of :mod:`graspcompass.scene.layout` (issue 23): the same module object."""

import sys

from .scene import layout as _module

sys.modules[__name__] = _module
