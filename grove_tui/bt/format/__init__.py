"""Behavior trees as documents: manifest.py (every node and port, the TreeNodesModel), document.py (the
tree stages pass around), xml.py (the one hardened reader and writer of BT.CPP v4 XML), source.py (the
bounded file read), include.py (`<include>`), ports.py (port values as text) and hunav_compat.py
(HuNavSim 2.0's own node set). Nothing here ticks a tree; grove_tui/bt/runtime/ does."""
