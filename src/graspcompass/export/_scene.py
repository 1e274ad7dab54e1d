"""Old import path of :mod:`graspcompass.scene.picture` (issue 23): the same module object."""

import sys

from ..scene import picture as _module

sys.modules[__name__] = _module
