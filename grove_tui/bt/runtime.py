"""BehaviorTree.CPP v4 runtime in Python, in simulation time.

The control nodes and decorators follow BT.CPP 4.8 line by line (sequence_node.cpp, fallback_node.cpp,
reactive_*.cpp, parallel_node.cpp, decorators/*.cpp, tree_node.cpp, bt_factory.cpp tickRoot), including
the details trees depend on:
- a node that returns SKIPPED keeps its stored status (IDLE) and only reports SKIPPED to its parent;
- RunOnce remembers across halts; Repeat and RetryUntilSuccessful hand control back (RUNNING) after a
  child that completed within one tick, as BT.CPP's wake-up logic does inside a Tree;
- ReactiveSequence/ReactiveFallback halt every other child when one is RUNNING;
- the root is reset to IDLE after it completes (Tree::tickExactlyOnce).
Timeout, Delay and TimeDelay read `clock.now` (simulation seconds), never the wall clock, so a
scenario plays the same at any speed. The differential test (tests/test_bt_differential.py) compares
this module with BT.CPP itself through `behaviortreepy`.
"""

from __future__ import annotations

from collections.abc import Mapping
from enum import IntEnum
from typing import Any

from grove_tui.bt.manifest import NODES, SUBTREE, NodeSpec, PortSpec
from grove_tui.bt.hunav_compat import checked_port, satisfied_by_goal_id
from grove_tui.bt.xml import BTError, TreeDocument, TreeElement, blackboard_pointer, convert_literal

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


# ---- blackboard ---------------------------------------------------------------------------------

_MISSING = object()
_ABSENT = object()  # what BlackboardRef asks for, distinct from Blackboard.get's "no default" marker
_TYPE_FAMILY = {"int": "int", "agent": "int", "float": "float", "bool": "bool"}  # everything else: text


class Blackboard:
    """Key/value store of one tree scope, with SubTree remapping ({key}) and `_autoremap` to the parent."""

    __slots__ = ("_values", "_types", "_remap", "_parent", "_autoremap")

    def __init__(self, parent: Blackboard | None = None, autoremap: bool = False, values: Mapping | None = None):
        self._values: dict[str, Any] = dict(values or {})
        self._types: dict[str, str] = {}
        self._remap: dict[str, str] = {}
        self._parent = parent
        self._autoremap = autoremap

    def add_remapping(self, internal: str, external: str) -> None:
        self._remap[internal] = external

    def _owner(self, key: str) -> tuple[Blackboard, str]:
        bb = self
        while True:
            if key in bb._remap:
                key = bb._remap[key]
                bb = bb._parent
                continue
            if key in bb._values or bb._parent is None or not bb._autoremap or key.startswith("_"):
                return bb, key
            bb = bb._parent

    def get(self, key: str, default: Any = _MISSING) -> Any:
        bb, k = self._owner(key)
        value = bb._values.get(k, _MISSING)
        if value is _MISSING:
            if default is _MISSING:
                raise KeyError(key)
            return default
        return value

    def set(self, key: str, value: Any) -> None:
        bb, k = self._owner(key)
        bb._values[k] = value

    def __contains__(self, key: str) -> bool:
        bb, k = self._owner(key)
        return k in bb._values

    def declare(self, key: str, port_type: str, where: str) -> None:
        """Give an entry a type; BTError when two ports of incompatible types share it (as BT.CPP does)."""
        bb, k = self._owner(key)
        family = _TYPE_FAMILY.get(port_type, "text")
        known = bb._types.get(k)
        if known is None or known == "text":
            bb._types[k] = family
        elif family != "text" and family != known:
            raise BTError(f"{where}: blackboard entry {{{key}}} is used as {family} here but as {known} elsewhere")

    def keys(self) -> list[str]:
        return list(self._values)


class BlackboardRef:
    """A port bound to a blackboard entry ("{key}"); values are converted to the port type when read."""

    __slots__ = ("blackboard", "key", "port", "where")

    def __init__(self, blackboard: Blackboard, key: str, port: PortSpec, where: str):
        self.blackboard = blackboard
        self.key = key
        self.port = port
        self.where = where

    def get(self) -> Any:
        value = self.blackboard.get(self.key, _ABSENT)
        if value is _ABSENT:
            raise BTError(f"{self.where}: port {self.port.name!r} reads blackboard entry {{{self.key}}}, "
                          "which is not set")
        if isinstance(value, str) and self.port.type not in ("string", "target"):
            try:
                return convert_literal(self.port, value)
            except ValueError as exc:
                raise BTError(f"{self.where}: port {self.port.name!r} from {{{self.key}}}: {exc}") from None
        if self.port.type == "float" and isinstance(value, int) and not isinstance(value, bool):
            return float(value)
        return value


# ---- node base classes --------------------------------------------------------------------------

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
        raise NotImplementedError

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

    def children(self):
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

    def children(self):
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

    def __init__(self, name: str, inputs: dict[str, Any], outputs: dict[str, str], blackboard: Blackboard,
                 ctx: Any = None, node_id: str | None = None):
        super().__init__(name, node_id)
        self.inputs = inputs
        self.outputs = outputs
        self.blackboard = blackboard
        self.ctx = ctx
        self.setup()

    def setup(self) -> None:
        """Hook for subclasses to cache literal inputs."""

    def get_input(self, name: str, default: Any = None) -> Any:
        value = self.inputs.get(name, default)
        if type(value) is BlackboardRef:
            return value.get()
        return value

    def is_literal(self, name: str) -> bool:
        return name in self.inputs and type(self.inputs[name]) is not BlackboardRef

    def set_output(self, name: str, value: Any) -> None:
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
        raise NotImplementedError

    def on_running(self) -> int:
        raise NotImplementedError

    def on_halted(self) -> None:
        """Undo what on_start set up."""


# ---- control nodes ------------------------------------------------------------------------------

class _OrderedControl(ControlNode):
    """Sequence and Fallback are duals: tick children in order, resuming at the running one, until
    one returns STOP_ON (returned at once, children reset); when all returned CONTINUE_ON or were
    SKIPPED the node returns CONTINUE_ON, or SKIPPED if every child was skipped (BT.CPP v4)."""

    __slots__ = ("current", "skipped")
    STOP_ON = FAILURE
    CONTINUE_ON = SUCCESS

    def __init__(self, name, children, node_id=None):
        super().__init__(name, children, node_id)
        self.current = 0
        self.skipped = 0

    def tick(self) -> int:
        n = len(self.kids)
        if not is_active(self.status):
            self.skipped = 0
        self.status = RUNNING
        while self.current < n:
            child_status = self.kids[self.current].execute_tick()
            if child_status == RUNNING:
                return RUNNING
            if child_status == self.STOP_ON:
                self.reset_children()
                self.current = 0
                return self.STOP_ON
            if child_status == self.CONTINUE_ON:
                self.current += 1
            elif child_status == SKIPPED:
                self.current += 1
                self.skipped += 1
            else:
                raise BTError(f"{self.path} {self.node_id}: a child returned IDLE")
        all_skipped = self.skipped == n
        if self.current == n:
            self.reset_children()
            self.current = 0
            self.skipped = 0
        return SKIPPED if all_skipped else self.CONTINUE_ON

    def halt(self) -> None:
        self.current = 0
        self.skipped = 0
        ControlNode.halt(self)


class Sequence(_OrderedControl):
    __slots__ = ()
    STOP_ON = FAILURE
    CONTINUE_ON = SUCCESS


class SequenceWithMemory(ControlNode):
    __slots__ = ("current", "skipped")

    def __init__(self, name, children, node_id=None):
        super().__init__(name, children, node_id)
        self.current = 0
        self.skipped = 0

    def tick(self) -> int:
        n = len(self.kids)
        if not is_active(self.status):
            self.skipped = 0
        self.status = RUNNING
        while self.current < n:
            child = self.kids[self.current]
            prev = child.status
            child_status = child.execute_tick()
            if child_status == RUNNING:
                return RUNNING
            if child_status == FAILURE:
                # do not reset current: the next tick resumes at the failed child
                for i in range(self.current, n):
                    self.halt_child(i)
                return FAILURE
            if child_status == SUCCESS:
                self.current += 1
                # BT.CPP (inside a Tree, requiresWakeUp() is true) hands the flow back after a child
                # that completed within one tick, so the sequence stays interruptible
                if prev == IDLE and self.current < n:
                    return RUNNING
            elif child_status == SKIPPED:
                self.current += 1
                self.skipped += 1
            else:
                raise BTError(f"{self.path} {self.node_id}: a child returned IDLE")
        all_skipped = self.skipped == n
        if self.current == n:
            self.reset_children()
            self.current = 0
            self.skipped = 0
        return SKIPPED if all_skipped else SUCCESS

    def halt(self) -> None:
        # BT.CPP keeps current_child_idx_ across a halt: the memory survives interruptions
        ControlNode.halt(self)


class Fallback(_OrderedControl):
    __slots__ = ()
    STOP_ON = SUCCESS
    CONTINUE_ON = FAILURE


class ReactiveSequence(ControlNode):
    __slots__ = ("running_child",)

    def __init__(self, name, children, node_id=None):
        super().__init__(name, children, node_id)
        self.running_child = -1

    def tick(self) -> int:
        all_skipped = True
        if self.status == IDLE:
            self.running_child = -1
        self.status = RUNNING
        kids = self.kids
        for index in range(len(kids)):
            child_status = kids[index].execute_tick()
            all_skipped = all_skipped and child_status == SKIPPED
            if child_status == RUNNING:
                for i in range(len(kids)):
                    if i != index:
                        self.halt_child(i)
                if self.running_child == -1:
                    self.running_child = index
                return RUNNING
            if child_status == FAILURE:
                self.reset_children()
                return FAILURE
            if child_status == SKIPPED:
                self.halt_child(index)
            elif child_status != SUCCESS:
                raise BTError(f"{self.path} {self.node_id}: a child returned IDLE")
        self.reset_children()
        return SKIPPED if all_skipped else SUCCESS

    def halt(self) -> None:
        self.running_child = -1
        ControlNode.halt(self)


class ReactiveFallback(ControlNode):
    __slots__ = ("running_child",)

    def __init__(self, name, children, node_id=None):
        super().__init__(name, children, node_id)
        self.running_child = -1

    def tick(self) -> int:
        all_skipped = True
        if self.status == IDLE:
            self.running_child = -1
        self.status = RUNNING
        kids = self.kids
        for index in range(len(kids)):
            child_status = kids[index].execute_tick()
            all_skipped = all_skipped and child_status == SKIPPED
            if child_status == RUNNING:
                for i in range(len(kids)):
                    if i != index:
                        self.halt_child(i)
                if self.running_child == -1:
                    self.running_child = index
                return RUNNING
            if child_status == SUCCESS:
                self.reset_children()
                return SUCCESS
            if child_status == SKIPPED:
                self.halt_child(index)
            elif child_status != FAILURE:
                raise BTError(f"{self.path} {self.node_id}: a child returned IDLE")
        self.reset_children()
        return SKIPPED if all_skipped else FAILURE

    def halt(self) -> None:
        self.running_child = -1
        ControlNode.halt(self)


class Parallel(ControlNode):
    __slots__ = ("success_threshold", "failure_threshold", "completed", "success_count", "failure_count",
                 "threshold_refs")

    def __init__(self, name, children, success_count=-1, failure_count=1, node_id=None):
        super().__init__(name, children, node_id)
        self.threshold_refs = (success_count, failure_count)
        self.success_threshold = success_count if isinstance(success_count, int) else -1
        self.failure_threshold = failure_count if isinstance(failure_count, int) else 1
        self.completed: set[int] = set()
        self.success_count = 0
        self.failure_count = 0

    def _threshold(self, value: int) -> int:
        n = len(self.kids)
        return max(n + value + 1, 0) if value < 0 else value

    def tick(self) -> int:
        s_ref, f_ref = self.threshold_refs
        if type(s_ref) is BlackboardRef:
            self.success_threshold = int(s_ref.get())
        if type(f_ref) is BlackboardRef:
            self.failure_threshold = int(f_ref.get())
        n = len(self.kids)
        required_success = self._threshold(self.success_threshold)
        required_failure = self._threshold(self.failure_threshold)
        if n < required_success:
            raise BTError(f"{self.path} Parallel: success_count {self.success_threshold} is more than its "
                          f"{n} children: it can never succeed")
        if n < required_failure:
            raise BTError(f"{self.path} Parallel: failure_count {self.failure_threshold} is more than its "
                          f"{n} children: it can never fail")
        self.status = RUNNING
        skipped = 0
        for i in range(n):
            if i not in self.completed:
                child_status = self.kids[i].execute_tick()
                if child_status == SKIPPED:
                    skipped += 1
                elif child_status == SUCCESS:
                    self.completed.add(i)
                    self.success_count += 1
                elif child_status == FAILURE:
                    self.completed.add(i)
                    self.failure_count += 1
                elif child_status != RUNNING:
                    raise BTError(f"{self.path} Parallel: a child returned IDLE")
            if self.success_count >= required_success or (
                    self.success_threshold < 0 and self.success_count + skipped >= required_success):
                self._clear()
                self.reset_children()
                return SUCCESS
            if n - self.failure_count < required_success or self.failure_count == required_failure:
                self._clear()
                self.reset_children()
                return FAILURE
        return SKIPPED if skipped == n else RUNNING

    def _clear(self) -> None:
        self.completed.clear()
        self.success_count = 0
        self.failure_count = 0

    def halt(self) -> None:
        self._clear()
        ControlNode.halt(self)


# ---- decorators ---------------------------------------------------------------------------------

class Inverter(DecoratorNode):
    __slots__ = ()

    def tick(self) -> int:
        self.status = RUNNING
        child_status = self.child.execute_tick()
        if child_status == SUCCESS:
            self.reset_child()
            return FAILURE
        if child_status == FAILURE:
            self.reset_child()
            return SUCCESS
        if child_status == IDLE:
            raise BTError(f"{self.path} Inverter: the child returned IDLE")
        return child_status


class ForceSuccess(DecoratorNode):
    __slots__ = ()

    def tick(self) -> int:
        self.status = RUNNING
        child_status = self.child.execute_tick()
        if is_completed(child_status):
            self.reset_child()
            return SUCCESS
        return child_status


class ForceFailure(DecoratorNode):
    __slots__ = ()

    def tick(self) -> int:
        self.status = RUNNING
        child_status = self.child.execute_tick()
        if is_completed(child_status):
            self.reset_child()
            return FAILURE
        return child_status


class RunOnce(DecoratorNode):
    __slots__ = ("then_skip", "already_ticked", "returned")

    def __init__(self, name, child, then_skip=True, node_id=None):
        super().__init__(name, child, node_id)
        self.then_skip = then_skip
        self.already_ticked = False
        self.returned = IDLE

    def tick(self) -> int:
        skip = self.then_skip.get() if type(self.then_skip) is BlackboardRef else self.then_skip
        if self.already_ticked:
            return SKIPPED if skip else self.returned
        self.status = RUNNING
        status = self.child.execute_tick()
        if is_completed(status):
            self.already_ticked = True
            self.returned = status
            self.reset_child()
        return status


class Repeat(DecoratorNode):
    __slots__ = ("num_cycles", "repeat_count")

    def __init__(self, name, child, num_cycles, node_id=None):
        super().__init__(name, child, node_id)
        self.num_cycles = num_cycles
        self.repeat_count = 0

    def tick(self) -> int:
        cycles = self.num_cycles.get() if type(self.num_cycles) is BlackboardRef else self.num_cycles
        do_loop = self.repeat_count < cycles or cycles == -1
        self.status = RUNNING
        while do_loop:
            prev = self.child.status
            child_status = self.child.execute_tick()
            if child_status == SUCCESS:
                self.repeat_count += 1
                do_loop = self.repeat_count < cycles or cycles == -1
                self.reset_child()
                # BT.CPP returns the flow to the tree after each synchronous cycle (wake-up signal)
                if prev == IDLE and do_loop:
                    return RUNNING
            elif child_status == FAILURE:
                self.repeat_count = 0
                self.reset_child()
                return FAILURE
            elif child_status == RUNNING:
                return RUNNING
            elif child_status == SKIPPED:
                return SKIPPED  # the counter is kept, as BT.CPP does
            else:
                raise BTError(f"{self.path} Repeat: the child returned IDLE")
        self.repeat_count = 0
        return SUCCESS

    def halt(self) -> None:
        self.repeat_count = 0
        DecoratorNode.halt(self)


class RetryUntilSuccessful(DecoratorNode):
    __slots__ = ("num_attempts", "try_count", "all_skipped")

    def __init__(self, name, child, num_attempts, node_id=None):
        super().__init__(name, child, node_id)
        self.num_attempts = num_attempts
        self.try_count = 0
        self.all_skipped = True

    def tick(self) -> int:
        attempts = self.num_attempts.get() if type(self.num_attempts) is BlackboardRef else self.num_attempts
        do_loop = self.try_count < attempts or attempts == -1
        if self.status == IDLE:
            self.all_skipped = True
        self.status = RUNNING
        while do_loop:
            prev = self.child.status
            child_status = self.child.execute_tick()
            self.all_skipped = self.all_skipped and child_status == SKIPPED
            if child_status == SUCCESS:
                self.try_count = 0
                self.reset_child()
                return SUCCESS
            if child_status == FAILURE:
                self.try_count += 1
                do_loop = self.try_count < attempts or attempts == -1
                self.reset_child()
                if prev == IDLE and do_loop:
                    return RUNNING
            elif child_status == RUNNING:
                return RUNNING
            elif child_status == SKIPPED:
                self.reset_child()
                return SKIPPED
            else:
                raise BTError(f"{self.path} RetryUntilSuccessful: the child returned IDLE")
        self.try_count = 0
        return SKIPPED if self.all_skipped else FAILURE

    def halt(self) -> None:
        self.try_count = 0
        DecoratorNode.halt(self)


class KeepRunningUntilFailure(DecoratorNode):
    __slots__ = ()

    def tick(self) -> int:
        self.status = RUNNING
        child_status = self.child.execute_tick()
        if child_status == FAILURE:
            self.reset_child()
            return FAILURE
        if child_status == SUCCESS:
            self.reset_child()
            return RUNNING
        return RUNNING if child_status in (RUNNING, SKIPPED) else self.status


class Timeout(DecoratorNode):
    """Fails and halts the child once `msec` simulation milliseconds have passed since it started."""

    __slots__ = ("msec", "clock", "started_at", "child_halted")

    def __init__(self, name, child, msec, clock: SimClock, node_id=None):
        super().__init__(name, child, node_id)
        self.msec = msec
        self.clock = clock
        self.started_at: float | None = None
        self.child_halted = False

    def tick(self) -> int:
        msec = self.msec.get() if type(self.msec) is BlackboardRef else self.msec
        now = self.clock.now
        if self.started_at is None:
            self.started_at = now
            self.status = RUNNING
            self.child_halted = False
        # BT.CPP's timer halts a still-running child when it fires; in simulation time it fires at a tick
        if msec > 0 and (now - self.started_at) * 1000.0 >= msec - 1e-9 and self.child.status == RUNNING:
            self.child_halted = True
            self.child.halt_node()
        if self.child_halted:
            self.started_at = None
            return FAILURE
        child_status = self.child.execute_tick()
        if is_completed(child_status):
            self.started_at = None
            self.reset_child()
        return child_status

    def halt(self) -> None:
        self.started_at = None
        DecoratorNode.halt(self)


class Delay(DecoratorNode):
    """Returns RUNNING for `delay_msec` simulation milliseconds, then ticks the child."""

    __slots__ = ("delay_msec", "clock", "started_at")

    def __init__(self, name, child, delay_msec, clock: SimClock, node_id=None):
        super().__init__(name, child, node_id)
        self.delay_msec = delay_msec
        self.clock = clock
        self.started_at: float | None = None

    def tick(self) -> int:
        delay = self.delay_msec.get() if type(self.delay_msec) is BlackboardRef else self.delay_msec
        now = self.clock.now
        if self.started_at is None:
            self.started_at = now
            self.status = RUNNING
        if (now - self.started_at) * 1000.0 + 1e-9 >= delay:
            child_status = self.child.execute_tick()
            if is_completed(child_status):
                self.started_at = None
                self.reset_child()
            return child_status
        return RUNNING

    def halt(self) -> None:
        self.started_at = None
        DecoratorNode.halt(self)


class TimeDelay(DecoratorNode):
    """HuNavSim TimeDelay: FAILURE until `delay` simulation seconds have passed, then ticks the child."""

    __slots__ = ("delay", "clock", "started_at")

    def __init__(self, name, child, delay, clock: SimClock, node_id=None):
        super().__init__(name, child, node_id)
        self.delay = delay
        self.clock = clock
        self.started_at: float | None = None

    def tick(self) -> int:
        delay = self.delay.get() if type(self.delay) is BlackboardRef else self.delay
        now = self.clock.now
        if self.started_at is None:
            self.started_at = now
        if now - self.started_at + 1e-9 < delay:
            return FAILURE
        self.status = RUNNING
        child_status = self.child.execute_tick()
        if is_completed(child_status):
            self.started_at = None
            self.reset_child()
        return child_status

    def halt(self) -> None:
        self.started_at = None
        DecoratorNode.halt(self)


class SubTreeNode(DecoratorNode):
    __slots__ = ("tree_id",)

    def __init__(self, name, child, tree_id: str):
        super().__init__(name, child, SUBTREE)
        self.tree_id = tree_id

    def tick(self) -> int:
        if self.status == IDLE:
            self.status = RUNNING
        child_status = self.child.execute_tick()
        if is_completed(child_status):
            self.reset_child()
        return child_status


# ---- BT.CPP built-in leaves ---------------------------------------------------------------------

class AlwaysSuccess(SyncActionNode):
    __slots__ = ()

    def tick(self) -> int:
        return SUCCESS


class AlwaysFailure(SyncActionNode):
    __slots__ = ()

    def tick(self) -> int:
        return FAILURE


class SetBlackboard(SyncActionNode):
    __slots__ = ()

    def tick(self) -> int:
        key = self.get_input("output_key")
        self.blackboard.set(str(key), self.get_input("value"))
        return SUCCESS


CONTROL_CLASSES: dict[str, type[ControlNode]] = {
    "Sequence": Sequence, "SequenceWithMemory": SequenceWithMemory, "Fallback": Fallback,
    "ReactiveSequence": ReactiveSequence, "ReactiveFallback": ReactiveFallback, "Parallel": Parallel,
}
DECORATOR_CLASSES: dict[str, type[DecoratorNode]] = {
    "Inverter": Inverter, "ForceSuccess": ForceSuccess, "ForceFailure": ForceFailure, "RunOnce": RunOnce,
    "Repeat": Repeat, "RetryUntilSuccessful": RetryUntilSuccessful,
    "KeepRunningUntilFailure": KeepRunningUntilFailure, "Timeout": Timeout, "Delay": Delay,
    "TimeDelay": TimeDelay,
}
BTCPP_LEAVES: dict[str, type[LeafNode]] = {
    "AlwaysSuccess": AlwaysSuccess, "AlwaysFailure": AlwaysFailure, "SetBlackboard": SetBlackboard,
}
_CLOCKED = {"Timeout", "Delay", "TimeDelay"}


# ---- the tree -----------------------------------------------------------------------------------

# Nodes that, while their (one) running child stays RUNNING, return RUNNING and change nothing else.
_PASS_THROUGH = (Sequence, SequenceWithMemory, Fallback, SubTreeNode, Inverter, ForceSuccess, ForceFailure, RunOnce,
                 Repeat, RetryUntilSuccessful, KeepRunningUntilFailure)


class BehaviorTree:
    """One instantiated tree: tick it once per BT period (Tree::tickExactlyOnce).

    Quiescent ticks are skipped without changing the semantics: when the only running leaf sits below
    pass-through nodes (and reactive nodes whose earlier children are side-effect-free conditions) and
    that leaf's `poll()` says its on_running would just return RUNNING, a full tick would change no
    state at all, so `tick` re-checks the reactive guards, polls the leaf and returns RUNNING.
    tests/test_simulation_fastpath.py runs scenarios both ways and compares them.
    """

    __slots__ = ("root", "blackboard", "nodes", "source", "clock", "fast", "quiet")

    def __init__(self, root: TreeNode, blackboard: Blackboard, nodes: list[TreeNode], source: str, clock: SimClock):
        self.root = root
        self.blackboard = blackboard
        self.nodes = nodes
        self.source = source
        self.clock = clock
        self.fast = True  # allow quiescent-tick skipping
        self.quiet: tuple[LeafNode, tuple[tuple[TreeNode, int], ...]] | None = None

    def tick(self) -> int:
        quiet = self.quiet
        if quiet is not None:
            leaf, guards = quiet
            for condition, expected in guards:
                if condition.tick() != expected:
                    break
            else:
                if leaf.poll():
                    return RUNNING
        root = self.root
        status = root.execute_tick()
        if status == SUCCESS or status == FAILURE:
            root.status = IDLE
            self.quiet = None
        elif status == RUNNING and self.fast:
            self.quiet = self._quiescent_path()
        else:
            self.quiet = None
        return status

    def _quiescent_path(self):
        node = self.root
        guards: list[tuple[TreeNode, int]] = []
        while True:
            if node.status != RUNNING:
                return None
            if isinstance(node, LeafNode):
                return (node, tuple(guards)) if getattr(node, "poll", None) is not None else None
            if isinstance(node, _PASS_THROUGH):
                if isinstance(node, DecoratorNode):
                    node = node.child
                else:
                    node = node.kids[node.current]
                continue
            if isinstance(node, (ReactiveFallback, ReactiveSequence)):
                expected = FAILURE if isinstance(node, ReactiveFallback) else SUCCESS
                kids = node.kids
                running = next((i for i, kid in enumerate(kids) if kid.status == RUNNING), -1)
                if running < 0:
                    return None
                for kid in kids[:running]:
                    guard = _pure_guard(kid, expected)
                    if guard is None:
                        return None
                    guards.append(guard)
                node = kids[running]
                continue
            return None

    def halt(self) -> None:
        self.root.halt_node()

    def status_list(self) -> list[tuple[str, str, str]]:
        """(path, name, status) of every node in depth-first order.

        A node reset to IDLE after it completed shows its last result (SUCCESS/FAILURE/SKIPPED), as
        Groot2 does, so a finished tree still tells how it ended; a halted node shows IDLE.
        """
        out = []
        for node in self.nodes:
            shown = node.status if node.status != IDLE or node.last == RUNNING else node.last
            label = node.node_id if node.name == node.node_id else f"{node.node_id} {node.name!r}"
            out.append((node.path, label, STATUS_NAMES[shown]))
        return out

    def leaves(self) -> list[LeafNode]:
        return [n for n in self.nodes if isinstance(n, LeafNode)]


def _pure_guard(node: TreeNode, expected: int) -> tuple[TreeNode, int] | None:
    """(condition, status) whose side-effect-free tick decides what re-ticking `node` returns, if any."""
    if isinstance(node, ConditionNode):
        return (node, expected) if getattr(node, "PURE", False) else None
    if isinstance(node, Inverter) and expected in (SUCCESS, FAILURE):
        return _pure_guard(node.child, SUCCESS if expected == FAILURE else FAILURE)
    if expected == FAILURE and node.status == IDLE and (
            isinstance(node, ReactiveSequence) or (isinstance(node, Sequence) and node.current == 0)):
        return _pure_guard(node.kids[0], FAILURE)  # a sequence whose first child fails fails at once
    return None


LeafClasses = Mapping[str, type[LeafNode]]


class TreeFactory:
    """Instantiates parsed TreeDocuments with the leaf classes of a node set."""

    def __init__(self, leaf_classes: LeafClasses, nodes: Mapping[str, NodeSpec] = NODES):
        self.leaf_classes = dict(BTCPP_LEAVES)
        self.leaf_classes.update(leaf_classes)
        self.nodes = nodes

    def create(self, document: TreeDocument, blackboard: Blackboard | None = None, ctx: Any = None,
               clock: SimClock | None = None) -> BehaviorTree:
        blackboard = blackboard if blackboard is not None else Blackboard()
        clock = clock if clock is not None else SimClock()
        nodes: list[TreeNode] = []
        root = self._build(document, document.main, blackboard, ctx, clock, nodes, "0", (document.main_tree_id,))
        return BehaviorTree(root, blackboard, nodes, document.source, clock)

    def _inputs(self, spec: NodeSpec, element: TreeElement, blackboard: Blackboard, where: str):
        inputs: dict[str, Any] = {}
        outputs: dict[str, str] = {}
        for port in spec.ports:
            text = element.ports.get(port.name)
            if port.direction == "out":
                if text is not None:
                    key = blackboard_pointer(text)
                    if key is None:
                        raise BTError(f"{where}: output port {port.name!r} must be a {{key}}")
                    blackboard.declare(key, port.type, where)
                    outputs[port.name] = key
                continue
            if text is None:
                default = port.default
                key = blackboard_pointer(default) if isinstance(default, str) else None
                if key is not None:
                    inputs[port.name] = BlackboardRef(blackboard, key, port, where)
                elif default is not None:
                    inputs[port.name] = default
                elif port.required and not satisfied_by_goal_id(port, element.ports):
                    raise BTError(f"{where}: missing required port {port.name!r}")
                continue
            key = blackboard_pointer(text)
            if key is not None:
                blackboard.declare(key, port.type, where)
                inputs[port.name] = BlackboardRef(blackboard, key, checked_port(spec, port), where)
            else:
                try:
                    inputs[port.name] = convert_literal(checked_port(spec, port), text)
                except ValueError as exc:
                    raise BTError(f"{where}: port {port.name!r}: {exc}") from None
        return inputs, outputs

    def _build(self, document: TreeDocument, element: TreeElement, blackboard: Blackboard, ctx, clock,
               nodes: list[TreeNode], path: str, call_chain: tuple[str, ...]) -> TreeNode:
        where = f"{document.source}:{element.line}" if element.line else document.source
        index = len(nodes)
        nodes.append(None)  # reserve the depth-first slot before the children
        if element.id == SUBTREE:
            tree_id = element.subtree_id
            if tree_id in call_chain:
                raise BTError(f"{where}: SubTree recursion through {tree_id!r}")
            if tree_id not in document.trees:
                raise BTError(f"{where}: SubTree refers to unknown BehaviorTree {tree_id!r}")
            child_bb = Blackboard(parent=blackboard, autoremap=element.autoremap)
            for port_name, value in element.ports.items():
                key = blackboard_pointer(value)
                if key is not None:
                    child_bb.add_remapping(port_name, key)
                else:
                    child_bb.set(port_name, value)
            child = self._build(document, document.trees[tree_id], child_bb, ctx, clock, nodes, path + "/0",
                                call_chain + (tree_id,))
            node: TreeNode = SubTreeNode(element.name, child, tree_id)
        else:
            spec = self.nodes.get(element.id)
            if spec is None:
                raise BTError(f"{where}: unknown node {element.id!r}")
            inputs, outputs = self._inputs(spec, element, blackboard, where)
            if spec.category == "control":
                kids = [self._build(document, c, blackboard, ctx, clock, nodes, f"{path}/{i}", call_chain)
                        for i, c in enumerate(element.children)]
                cls = CONTROL_CLASSES.get(element.id)
                if cls is None:
                    raise BTError(f"{where}: no implementation for control node {element.id!r}")
                if cls is Parallel:
                    node = Parallel(element.name, kids, inputs.get("success_count", -1), inputs.get("failure_count", 1))
                else:
                    node = cls(element.name, kids)
            elif spec.category == "decorator":
                if len(element.children) != 1:
                    raise BTError(f"{where}: {element.id} needs exactly one child")
                child = self._build(document, element.children[0], blackboard, ctx, clock, nodes, path + "/0",
                                    call_chain)
                cls = DECORATOR_CLASSES.get(element.id)
                if cls is None:
                    raise BTError(f"{where}: no implementation for decorator {element.id!r}")
                args = [inputs[p.name] for p in spec.ports if p.name in inputs]
                if element.id in _CLOCKED:
                    node = cls(element.name, child, *args, clock=clock)
                else:
                    node = cls(element.name, child, *args)
            else:
                cls = self.leaf_classes.get(element.id)
                if cls is None:
                    raise BTError(f"{where}: no implementation for node {element.id!r} in this runtime")
                node = cls(element.name, inputs, outputs, blackboard, ctx, element.id)
            node.node_id = element.id
        node.path = path
        node.line = element.line
        nodes[index] = node
        return node


def build_tree_from_text(text: str, leaf_classes: LeafClasses, *, nodes: Mapping[str, NodeSpec] = NODES,
                         blackboard: Blackboard | None = None, ctx: Any = None, clock: SimClock | None = None,
                         source: str = "<string>") -> BehaviorTree:
    from grove_tui.bt.xml import parse_tree_text

    document = parse_tree_text(text, source, nodes)
    return TreeFactory(leaf_classes, nodes).create(document, blackboard, ctx, clock)

