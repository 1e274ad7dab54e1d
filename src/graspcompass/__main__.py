"""``python -m graspcompass``: the command line."""

from .cli import console

console()
