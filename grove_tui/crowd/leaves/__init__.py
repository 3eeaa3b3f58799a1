"""The behavior-tree leaves that act on the crowd: base.py (leaves bound to one agent), grove.py (GROVE's
nodes), hunav.py (HuNavSim's), and registry.py, the factory with every leaf, control and decorator.
They set intents on the crowd through grove_tui/crowd/context.py; the SFM step moves the agents."""
