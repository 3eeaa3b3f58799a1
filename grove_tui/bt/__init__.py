"""Behavior trees, in two layers (BehaviorTree.CPP's and py_trees' split):

- `format/`: trees as documents: the node manifest, the `TreeDocument` stages pass between them, the one
  hardened reader and writer of BT.CPP v4 XML, `<include>`, the port-text codec and HuNavSim's node set.
- `runtime/`: trees that tick in simulation time: tree nodes, blackboard, controls, decorators, the
  factory that builds a runnable tree from a document, and BT.CPP's own leaves.

The runtime reads the format, never the other way round. The leaves that act on pedestrians (GROVE's
and HuNavSim's) sit with the crowd they move, in grove_tui/crowd/leaves/.
"""
