"""The BT.CPP v4 runtime in simulation time: tree_node.py (node kinds and statuses), blackboard.py,
controls.py, decorators.py, leaves.py (BT.CPP's own leaves) and factory.py, which builds a runnable tree
from a grove_tui.bt.format document. It knows nothing of pedestrians: their leaves live in
grove_tui/crowd/leaves/."""
