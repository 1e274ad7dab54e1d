"""The input boundary: where outside values enter, and the package's errors and limits.

The lowest layer (issue 21): it imports nothing of the package above it.

- :mod:`graspcompass.errors` (here ``boundary.errors``): the named ``ValueError``
  subclasses every layer raises;
- :mod:`graspcompass.limits`: the documented limits on outside input;
- :mod:`graspcompass.expr`: the safe parser of exact expressions;
- :mod:`graspcompass.inputs`: values from outside (numbers, text, arrays);
- ``_infiles`` (bounded file reading), ``_output`` (checked output paths) and
  ``_deadline`` (the command time limit).

The public modules keep their old paths (``graspcompass.errors``, ``graspcompass.limits``,
``graspcompass.expr``, ``graspcompass.inputs``), where they are documented.
"""

from __future__ import annotations

__all__: list[str] = []
