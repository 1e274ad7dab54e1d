"""The limits on outside input, under their public path ``graspcompass.limits``.

Every name of :mod:`graspcompass.boundary.limits` (the input boundary's folder, issue 21),
re-exported by its ``__all__``, with its documentation.
"""

from .boundary import limits as _home
from .boundary.limits import *  # noqa: F403

__all__ = list(_home.__all__)
__doc__ = _home.__doc__  # the API page shows the module's own documentation
