"""graspcompass: the internal force diagram of two-point grasps, by ruler and compass."""

__version__ = "0.1.0"
