"""The behavior-tree runtime in one import, for callers that drive trees rather than extend them.

The runtime is split the way BehaviorTree.CPP and py_trees split theirs:
    tree_node.py    statuses, SimClock, base classes (TreeNode, ControlNode, DecoratorNode, leaves)
    blackboard.py   Blackboard and {key} port references
    controls.py     Sequence, Fallback, Reactive*, Parallel, SequenceWithMemory
    decorators.py   Inverter, Force*, RunOnce, Repeat, Retry, Timeout, Delay, TimeDelay, SubTree
    leaves/         BT.CPP built-ins (btcpp.py), HuNavSim (hunav.py) and GROVE (grove.py) leaves
    factory.py      TreeFactory and BehaviorTree (Tree::tickExactlyOnce, quiescent-tick skipping)
"""

from grove_tui.bt.blackboard import Blackboard, BlackboardRef
from grove_tui.bt.controls import (
    CONTROL_CLASSES, Fallback, Parallel, ReactiveFallback, ReactiveSequence, Sequence, SequenceWithMemory,
)
from grove_tui.bt.decorators import (
    DECORATOR_CLASSES, Delay, ForceFailure, ForceSuccess, Inverter, KeepRunningUntilFailure, Repeat,
    RetryUntilSuccessful, RunOnce, SubTreeNode, TimeDelay, Timeout,
)
from grove_tui.bt.factory import BehaviorTree, LeafClasses, TreeFactory, build_tree_from_text
from grove_tui.bt.leaves.btcpp import BTCPP_LEAVES, AlwaysFailure, AlwaysSuccess, SetBlackboard
from grove_tui.bt.tree_node import (
    FAILURE, IDLE, RUNNING, SKIPPED, STATUS_NAMES, SUCCESS, ConditionNode, ControlNode, DecoratorNode, LeafNode,
    NodeStatus, SimClock, StatefulActionNode, SyncActionNode, TreeNode, is_active, is_completed,
)
from grove_tui.errors import BTError

__all__ = [
    "AlwaysFailure", "AlwaysSuccess", "BTCPP_LEAVES", "BTError", "BehaviorTree", "Blackboard", "BlackboardRef",
    "CONTROL_CLASSES", "ConditionNode", "ControlNode", "DECORATOR_CLASSES", "DecoratorNode", "Delay", "FAILURE",
    "Fallback", "ForceFailure", "ForceSuccess", "IDLE", "Inverter", "KeepRunningUntilFailure", "LeafClasses",
    "LeafNode", "NodeStatus", "Parallel", "RUNNING", "ReactiveFallback", "ReactiveSequence", "Repeat",
    "RetryUntilSuccessful", "RunOnce", "SKIPPED", "STATUS_NAMES", "SUCCESS", "Sequence", "SequenceWithMemory",
    "SetBlackboard", "SimClock", "StatefulActionNode", "SubTreeNode", "SyncActionNode", "TimeDelay", "Timeout",
    "TreeFactory", "TreeNode", "build_tree_from_text", "is_active", "is_completed",
]
