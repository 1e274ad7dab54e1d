"""The characters a reader reads in a mathtext caption (issue 23), written out here
independently of :mod:`graspcompass.render._anim_layout`."""

from __future__ import annotations

import re


def shown(text: str) -> str:
    """``$P_{1x}$`` reads ``P1x``, ``$k_\\mathrm{grasp}(\\theta)$`` reads ``kgrasp(#)``
    (a command is one character)."""
    text = text.replace("\\ ", " ").replace("\\$", "$").replace("$", "")
    text = re.sub(r"\\mathrm\{([^}]*)\}", r"\1", text)
    text = re.sub(r"\\[A-Za-z]+ ?", "#", text)
    return re.sub(r"[{}_^]", "", text)
