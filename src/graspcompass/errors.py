"""The package's exceptions, under their public path ``graspcompass.errors``.

Every name of :mod:`graspcompass.boundary.errors` (the input boundary's folder, issue 21),
re-exported by its ``__all__``, with its documentation.
"""

from .boundary import errors as _home
from .boundary.errors import *  # noqa: F403

__all__ = list(_home.__all__)
__doc__ = _home.__doc__  # the API page shows the module's own documentation
