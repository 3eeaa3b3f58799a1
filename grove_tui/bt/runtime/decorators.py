"""Decorators, after BT.CPP 4.8 (decorators/*.cpp), plus HuNavSim's TimeDelay and the SubTree node.

RunOnce remembers across halts; Repeat and RetryUntilSuccessful hand control back (RUNNING) after a
child that completed within one tick, as BT.CPP's wake-up logic does inside a Tree. Timeout, Delay
and TimeDelay read `clock.now` (simulation seconds), never the wall clock, so a scenario plays the
same at any speed.
"""

from __future__ import annotations

from collections.abc import Callable

from grove_tui.bt.runtime.blackboard import BlackboardRef
from grove_tui.bt.format.manifest import SUBTREE
from grove_tui.bt.runtime.tree_node import (
    FAILURE, IDLE, RUNNING, SKIPPED, SUCCESS, DecoratorNode, SimClock, TreeNode, is_completed,
)
from grove_tui.errors import BTError

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

    def __init__(self, name: str, child: TreeNode, then_skip: bool | BlackboardRef = True, node_id: str | None = None):
        super().__init__(name, child, node_id)
        self.then_skip = then_skip
        self.already_ticked = False
        self.returned = IDLE

    def tick(self) -> int:
        skip = self.then_skip.get() if isinstance(self.then_skip, BlackboardRef) else self.then_skip
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

    def __init__(self, name: str, child: TreeNode, num_cycles: int | BlackboardRef, node_id: str | None = None):
        super().__init__(name, child, node_id)
        self.num_cycles = num_cycles
        self.repeat_count = 0

    def tick(self) -> int:
        cycles = self.num_cycles.get() if isinstance(self.num_cycles, BlackboardRef) else self.num_cycles
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

    def __init__(self, name: str, child: TreeNode, num_attempts: int | BlackboardRef, node_id: str | None = None):
        super().__init__(name, child, node_id)
        self.num_attempts = num_attempts
        self.try_count = 0
        self.all_skipped = True

    def tick(self) -> int:
        attempts = self.num_attempts.get() if isinstance(self.num_attempts, BlackboardRef) else self.num_attempts
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

    def __init__(self, name: str, child: TreeNode, msec: int | BlackboardRef, clock: SimClock,
                 node_id: str | None = None):
        super().__init__(name, child, node_id)
        self.msec = msec
        self.clock = clock
        self.started_at: float | None = None
        self.child_halted = False

    def tick(self) -> int:
        msec = self.msec.get() if isinstance(self.msec, BlackboardRef) else self.msec
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

    def __init__(self, name: str, child: TreeNode, delay_msec: int | BlackboardRef, clock: SimClock,
                 node_id: str | None = None):
        super().__init__(name, child, node_id)
        self.delay_msec = delay_msec
        self.clock = clock
        self.started_at: float | None = None

    def tick(self) -> int:
        delay = self.delay_msec.get() if isinstance(self.delay_msec, BlackboardRef) else self.delay_msec
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

    def __init__(self, name: str, child: TreeNode, delay: float | BlackboardRef, clock: SimClock,
                 node_id: str | None = None):
        super().__init__(name, child, node_id)
        self.delay = delay
        self.clock = clock
        self.started_at: float | None = None

    def tick(self) -> int:
        delay = self.delay.get() if isinstance(self.delay, BlackboardRef) else self.delay
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

    def __init__(self, name: str, child: TreeNode, tree_id: str):
        super().__init__(name, child, SUBTREE)
        self.tree_id = tree_id

    def tick(self) -> int:
        if self.status == IDLE:
            self.status = RUNNING
        child_status = self.child.execute_tick()
        if is_completed(child_status):
            self.reset_child()
        return child_status


# Callable[..., DecoratorNode]: each decorator takes its own ports positionally after (name, child), and
# the clocked ones the clock; the factory passes them in manifest order.
DECORATOR_CLASSES: dict[str, Callable[..., DecoratorNode]] = {
    "Inverter": Inverter, "ForceSuccess": ForceSuccess, "ForceFailure": ForceFailure, "RunOnce": RunOnce,
    "Repeat": Repeat, "RetryUntilSuccessful": RetryUntilSuccessful,
    "KeepRunningUntilFailure": KeepRunningUntilFailure, "Timeout": Timeout, "Delay": Delay,
    "TimeDelay": TimeDelay,
}
# decorators that read the simulation clock: the factory passes it to them
CLOCKED_DECORATORS = frozenset({"Timeout", "Delay", "TimeDelay"})
