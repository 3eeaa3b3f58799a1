"""Base classes for leaves that act on one agent of the crowd.

Positions are read from plain Python lists the simulation refreshes once per BT tick
(`SimContext.refresh`), because indexing numpy arrays per agent per tick would cost more than
the whole tree.
"""

from __future__ import annotations

import math

from grove_tui.bt.runtime.blackboard import BlackboardRef
from grove_tui.bt.runtime.tree_node import FAILURE, RUNNING, SUCCESS, ConditionNode, StatefulActionNode, SyncActionNode
from grove_tui.crowd.context import AgentContext, SimContext, Snapshot
from grove_tui.errors import BTError

__all__ = ["AgentCondition", "AgentSyncAction", "AgentStatefulAction", "FAILURE", "RUNNING", "SUCCESS",
           "QuietSpec", "bind_agent", "angle_diff"]

# What the simulation checks all quiet agents by at once (Simulation._update_quiet_spec): the leaf
# stays RUNNING while the agent is farther than sqrt(r2) from (x, y) and the clock is before t_end.
QuietSpec = tuple[float, float, float, float]


def bind_agent(node: AgentCondition | AgentSyncAction | AgentStatefulAction, port: str) -> None:
    """Resolve the node's own agent (crowd row) once: its id never changes during a run.

    A tree built without a simulation (validation, fuzzing) has no context: its leaves stay unbound
    (row -1, no `sim`) and are never ticked."""
    ctx = node.ctx
    node.row = -1
    if not isinstance(ctx, AgentContext):
        return
    node.sim = ctx.sim
    node.row = ctx.row
    value = node.inputs.get(port)
    if type(value) is BlackboardRef:
        try:
            value = value.get()
        except BTError:
            value = None
    if value is not None and value != ctx.agent_id:
        node.row = ctx.sim.row(value, f"{node.node_id}.{port}")


def angle_diff(a: float, b: float) -> float:
    d = a - b
    return math.atan2(math.sin(d), math.cos(d))


class AgentCondition(ConditionNode):
    __slots__ = ("sim", "row")
    sim: SimContext
    row: int
    AGENT_PORT = "agent_id"

    def setup(self) -> None:
        bind_agent(self, self.AGENT_PORT)


class AgentSyncAction(SyncActionNode):
    __slots__ = ("sim", "row")
    sim: SimContext
    row: int
    AGENT_PORT = "agent_id"

    def setup(self) -> None:
        bind_agent(self, self.AGENT_PORT)


class AgentStatefulAction(StatefulActionNode):
    """A leaf that runs over several ticks; `started_at` is simulation time, `saved` the intents it
    replaced (restored when it ends or is halted)."""

    __slots__ = ("sim", "row", "started_at", "saved")
    sim: SimContext
    row: int
    started_at: float
    saved: Snapshot | None
    AGENT_PORT = "agent_id"

    def setup(self) -> None:
        bind_agent(self, self.AGENT_PORT)
        self.started_at = 0.0
        self.saved = None

    def elapsed(self) -> float:
        return self.sim.clock.now - self.started_at

    def save_intents(self) -> None:
        self.saved = self.sim.snapshot(self.row)

    def restore_intents(self) -> None:
        if self.saved is not None:
            self.sim.restore(self.row, self.saved)
            self.saved = None
