"""Control nodes, after BT.CPP 4.8 (controls/sequence_node.cpp, fallback_node.cpp, reactive_*.cpp,
parallel_node.cpp), including the details trees depend on:
- a child that returns SKIPPED keeps its stored status (IDLE) and only reports SKIPPED to its parent;
- ReactiveSequence/ReactiveFallback halt every other child when one is RUNNING;
- SequenceWithMemory keeps its position across a halt and hands control back after a child that
  completed within one tick, as BT.CPP's wake-up logic does inside a Tree.
"""

from __future__ import annotations

from grove_tui.bt.runtime.blackboard import BlackboardRef
from grove_tui.bt.runtime.tree_node import (
    FAILURE, IDLE, RUNNING, SKIPPED, SUCCESS, ControlNode, TreeNode, is_active,
)
from grove_tui.errors import BTError

class _OrderedControl(ControlNode):
    """Sequence and Fallback are duals: tick children in order, resuming at the running one, until
    one returns STOP_ON (returned at once, children reset); when all returned CONTINUE_ON or were
    SKIPPED the node returns CONTINUE_ON, or SKIPPED if every child was skipped (BT.CPP v4)."""

    __slots__ = ("current", "skipped")
    STOP_ON = FAILURE
    CONTINUE_ON = SUCCESS

    def __init__(self, name: str, children: list[TreeNode], node_id: str | None = None):
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

    def __init__(self, name: str, children: list[TreeNode], node_id: str | None = None):
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

    def __init__(self, name: str, children: list[TreeNode], node_id: str | None = None):
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

    def __init__(self, name: str, children: list[TreeNode], node_id: str | None = None):
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

    def __init__(self, name: str, children: list[TreeNode], success_count: int | BlackboardRef = -1,
                 failure_count: int | BlackboardRef = 1, node_id: str | None = None):
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
        if isinstance(s_ref, BlackboardRef):
            self.success_threshold = int(s_ref.get())
        if isinstance(f_ref, BlackboardRef):
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


CONTROL_CLASSES: dict[str, type[ControlNode]] = {
    "Sequence": Sequence, "SequenceWithMemory": SequenceWithMemory, "Fallback": Fallback,
    "ReactiveSequence": ReactiveSequence, "ReactiveFallback": ReactiveFallback, "Parallel": Parallel,
}
