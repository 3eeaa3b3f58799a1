"""Node statuses, the simulation clock and the base classes every node derives from (BT.CPP's tree_node.h,
control_node.h, decorator_node.h, action_node.h, condition_node.h).

The control nodes live in controls.py, the decorators in decorators.py, the leaves in leaves/; the
factory (factory.py) instantiates a TreeDocument with them.
"""

from __future__ import annotations

from enum import IntEnum
from typing import Any

from grove_tui.bt.format.ports import PortValue
from grove_tui.bt.runtime.blackboard import Blackboard, BlackboardRef
from grove_tui.errors import BTError

# BT.CPP's NodeStatus values; plain ints keep the hot path fast
IDLE, RUNNING, SUCCESS, FAILURE, SKIPPED = 0, 1, 2, 3, 4


class NodeStatus(IntEnum):
    IDLE = IDLE
    RUNNING = RUNNING
    SUCCESS = SUCCESS
    FAILURE = FAILURE
    SKIPPED = SKIPPED


STATUS_NAMES = ("IDLE", "RUNNING", "SUCCESS", "FAILURE", "SKIPPED")


def is_active(status: int) -> bool:
    return status != IDLE and status != SKIPPED


def is_completed(status: int) -> bool:
    return status == SUCCESS or status == FAILURE


class SimClock:
    """Simulation time in seconds; the Simulation advances it, tests set it by hand."""

    __slots__ = ("now",)

    def __init__(self, now: float = 0.0):
        self.now = now


class TreeNode:
    __slots__ = ("name", "node_id", "status", "last", "path", "line")
    category = "action"

    def __init__(self, name: str, node_id: str | None = None):
        self.name = name
        self.node_id = node_id or type(self).__name__
        self.status = IDLE
        self.last = IDLE  # last status returned to the parent, SKIPPED included (for display)
        self.path = ""
        self.line: int | None = None

    def execute_tick(self) -> int:
        new_status = self.tick()
        self.last = new_status
        # BT.CPP: preserve the IDLE state if skipped, but communicate SKIPPED to the parent
        if new_status != SKIPPED:
            self.status = new_status
        return new_status

    def tick(self) -> int:
        """Each node kind's own tick (controls, decorators, leaves); the base class has none."""
        raise NotImplementedError(f"{type(self).__name__} must define tick()")

    def halt(self) -> None:
        """Stop a running activity; the node's own state reset happens in halt_node."""

    def halt_node(self) -> None:
        self.halt()
        self.status = IDLE

    def reset_status(self) -> None:
        self.status = IDLE

    def children(self) -> tuple[TreeNode, ...]:
        return ()


class ControlNode(TreeNode):
    __slots__ = ("kids",)
    category = "control"

    def __init__(self, name: str, children: list[TreeNode], node_id: str | None = None):
        super().__init__(name, node_id)
        self.kids = list(children)

    def children(self) -> tuple[TreeNode, ...]:
        return tuple(self.kids)

    def halt_child(self, index: int) -> None:
        child = self.kids[index]
        if child.status == RUNNING:
            child.halt_node()
        child.status = IDLE

    def reset_children(self) -> None:
        for child in self.kids:
            if child.status == RUNNING:
                child.halt_node()
            child.status = IDLE

    def halt(self) -> None:
        self.reset_children()
        self.status = IDLE


class DecoratorNode(TreeNode):
    __slots__ = ("child",)
    category = "decorator"

    def __init__(self, name: str, child: TreeNode, node_id: str | None = None):
        super().__init__(name, node_id)
        self.child = child

    def children(self) -> tuple[TreeNode, ...]:
        return (self.child,)

    def reset_child(self) -> None:
        if self.child.status == RUNNING:
            self.child.halt_node()
        self.child.status = IDLE

    def halt(self) -> None:
        self.reset_child()
        self.status = IDLE


class LeafNode(TreeNode):
    """A leaf with manifest ports: literal inputs are converted once, {key} inputs read at tick time."""

    __slots__ = ("inputs", "outputs", "blackboard", "ctx")

    def __init__(self, name: str, inputs: dict[str, PortValue | BlackboardRef], outputs: dict[str, str],
                 blackboard: Blackboard, ctx: object = None, node_id: str | None = None):
        super().__init__(name, node_id)
        self.inputs = inputs
        self.outputs = outputs
        self.blackboard = blackboard
        self.ctx = ctx
        self.setup()

    def setup(self) -> None:
        """Hook for subclasses to cache literal inputs (and to take what they need from `ctx`, the
        application's per-agent context, which the runtime only passes along)."""

    def poll(self) -> bool:
        """Side-effect-free: would on_running just return RUNNING now? A leaf that can tell overrides
        this, and only below such a leaf does BehaviorTree.tick skip quiescent ticks (`polls`)."""
        return False

    @classmethod
    def polls(cls) -> bool:
        return cls.poll is not LeafNode.poll

    def get_input(self, name: str, default: PortValue | None = None) -> Any:  # Any: the port's type is the manifest's, known at run time
        """The port's value, read through the blackboard for a {key} port. Any: each port has the type the
        manifest gives it (PortSpec.type), known at run time, so a leaf reads it as that type."""
        value = self.inputs.get(name, default)
        if type(value) is BlackboardRef:
            return value.get()
        return value

    def is_literal(self, name: str) -> bool:
        return name in self.inputs and type(self.inputs[name]) is not BlackboardRef

    def set_output(self, name: str, value: PortValue) -> None:
        key = self.outputs.get(name)
        if key is not None:
            self.blackboard.set(key, value)


class ConditionNode(LeafNode):
    __slots__ = ()
    category = "condition"


class SyncActionNode(LeafNode):
    __slots__ = ()

    def execute_tick(self) -> int:
        status = super().execute_tick()
        if status == RUNNING:
            raise BTError(f"{self.path} {self.node_id}: a synchronous action must not return RUNNING")
        return status


class StatefulActionNode(LeafNode):
    """BT.CPP StatefulActionNode: on_start when IDLE, on_running while RUNNING, on_halted when halted."""

    __slots__ = ()

    def tick(self) -> int:
        prev = self.status
        if prev == IDLE:
            status = self.on_start()
            if status == IDLE:
                raise BTError(f"{self.path} {self.node_id}: on_start must not return IDLE")
            return status
        if prev == RUNNING:
            status = self.on_running()
            if status == IDLE:
                raise BTError(f"{self.path} {self.node_id}: on_running must not return IDLE")
            return status
        return prev

    def halt(self) -> None:
        if self.status == RUNNING:
            self.on_halted()

    def on_start(self) -> int:
        """A stateful action's first tick, as BT.CPP's StatefulActionNode::onStart."""
        raise NotImplementedError(f"{type(self).__name__} must define on_start()")

    def on_running(self) -> int:
        """A stateful action's later ticks, as BT.CPP's StatefulActionNode::onRunning."""
        raise NotImplementedError(f"{type(self).__name__} must define on_running()")

    def on_halted(self) -> None:
        """Undo what on_start set up."""
