"""Behavior trees: the manifest (manifest.py), hardened BT.CPP v4 XML (xml.py), the v4 runtime in
simulation time (runtime.py), and the HuNavSim/GROVE leaves acting on the crowd (nodes_*.py)."""

from grove_tui.bt.xml import BTError

__all__ = ["BTError"]
