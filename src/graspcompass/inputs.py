"""Values from outside, under their public path ``graspcompass.inputs``.

Every name of :mod:`graspcompass.boundary.inputs` (the input boundary's folder, issue 21),
re-exported by its ``__all__``, with its documentation.
"""

from .boundary import inputs as _home
from .boundary.inputs import *  # noqa: F403

__all__ = list(_home.__all__)
__doc__ = _home.__doc__  # the API page shows the module's own documentation
