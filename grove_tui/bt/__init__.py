"""Behavior trees: the node manifest (manifest.py), the tree document stages pass between them
(document.py), the one hardened reader and writer of BT.CPP v4 XML (xml.py) and port-text codec
(ports.py), and the v4 runtime in simulation time: tree_node.py, blackboard.py, controls.py,
decorators.py, factory.py, with the BT.CPP, HuNavSim and GROVE leaves in leaves/."""

from grove_tui.bt.xml import BTError

__all__ = ["BTError"]
