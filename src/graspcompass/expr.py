"""The safe expression parser, under their public path ``graspcompass.expr``.

Every name of :mod:`graspcompass.boundary.expr` (the input boundary's folder, issue 21),
re-exported by its ``__all__``, with its documentation.
"""

from .boundary import expr as _home
from .boundary.expr import *  # noqa: F403

__all__ = list(_home.__all__)
__doc__ = _home.__doc__  # the API page shows the module's own documentation
