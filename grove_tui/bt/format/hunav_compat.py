"""HuNavSim 2.0's own node set: the node IDs its agent manager registers and the ports each declares.

GROVE's manifest (bt/format/manifest.py) is a superset: it adds GROVE nodes, keeps 1.0 and 2.0 port variants,
and documents ports HuNavSim's TreeNodesModel.xml lists but the C++ code no longer declares. BT.CPP 4
rejects a port the registered node did not declare, so what GROVE hands to HuNavSim must use exactly
this table. Sources (robotics-upo/hunav_sim, the 2.0 code under `namespace hunav`, as stored in the
public code index; the humble/1.0 branch at afa974340901e244ce15a97e8ebc37c0699a3e6f has none of it):

- simple nodes: `hunav_agent_manager/src/bt_node.cpp`, `BTnode::registerBTNodes()`; its port lists
  `random_ports` (RandomChanceCondition: only `probability`), `go_to_ports` (SetGoal), `pos_ports`...
- stateful nodes: `providedPorts()` of each header in `hunav_agent_manager/include/hunav_agent_manager/`:
  go_to_node.hpp (agent_id, goal_id, time_step, tolerance), approach_agent_node.hpp (agent_id,
  target_agent_id, time_step, duration: no closest_dist/max_vel, they are constants
  `default_closest_dist_`/`default_max_vel_` there), approach_robot_node.hpp, follow_agent_node.hpp,
  block_robot_node.hpp, block_agent_node.hpp, avoid_robot_node.hpp, group_walk_node.hpp,
  conversation_formation_node.hpp, stop_and_wait_timer_action_node.hpp, look_at_*_node.hpp,
  time_delay_decorator.hpp; the stateful conditions (IsAnyoneSpeaking...) from
  behavior_trees/TreeNodesModel.xml@306ec99c4451165c9322ab057ad00a0b6fabdbf8.
- TimeExpiredCondition: time_expired_condition.hpp (seconds, ts, only_once), unchanged since 1.0.

Clocks: StopAndWaitTimerAction, ConversationFormation, TimeDelay and the `duration` of the stateful
nodes measure `std::chrono::steady_clock` (wall) time (their headers keep a `steady_clock::time_point
start_time_`), as do BT.CPP's own Delay and Timeout decorators; TimeExpiredCondition and the *Nav
reactions accumulate the tree's `dt` (simulation time). `CLOCKS` records it per node.
"""

from __future__ import annotations

from dataclasses import dataclass

from grove_tui.bt.format.after_task import (
    HOLD_NAME, ROBOT_RESPONSES, keep_reacting_after_task, run_once_then_hold,
)
from grove_tui.bt.format.document import TreeDocument, node
from grove_tui.bt.format.manifest import NODES
from grove_tui.bt.format.xml import read_tree

# BT.CPP 4 built-ins a HuNavSim tree may use (BehaviorTree.CPP registers them in every factory).
BTCPP_BUILTINS = frozenset(name for name, spec in NODES.items() if spec.origin == "btcpp") | {"SubTree"}


@dataclass(frozen=True)
class HunavNode:
    category: str  # "action" | "condition" | "decorator"
    inputs: tuple[str, ...]
    outputs: tuple[str, ...] = ()
    clock: str = "none"  # "wall" | "simulation" | "none": what its durations measure

    @property
    def ports(self) -> frozenset[str]:
        return frozenset(self.inputs) | frozenset(self.outputs)


_NAV = ("agent_id", "time_step", "beh_duration", "only_once")

HUNAV_NODES: dict[str, HunavNode] = {
    # conditions (bt_node.cpp registerSimpleCondition, registerNodeType<TimeExpiredCondition>)
    "TimeExpiredCondition": HunavNode("condition", ("seconds", "ts", "only_once"), clock="simulation"),
    "IsRobotVisible": HunavNode("condition", ("agent_id", "distance")),
    "IsGoalReached": HunavNode("condition", ("agent_id",)),
    "RandomChanceCondition": HunavNode("condition", ("probability",)),
    "IsRobotFacingAgent": HunavNode("condition", ("agent_id",)),
    "IsAgentVisible": HunavNode("condition", ("observer_id", "agent_id", "distance", "field_of_view")),
    "IsRobotClose": HunavNode("condition", ("agent_id", "threshold")),
    "IsAtPosition": HunavNode("condition", ("agent_id", "goal_id", "tolerance")),
    "IsAgentClose": HunavNode("condition", ("observer_id", "target_agent_id", "threshold")),
    "IsAnyoneSpeaking": HunavNode("condition", ("agent_id", "time_step", "distance_threshold", "duration"),
                                  ("speaker_id",), clock="wall"),
    "IsSpeaking": HunavNode("condition", ("agent_id", "time_step", "target_id", "distance_threshold", "duration"),
                            clock="wall"),
    "IsAnyoneLookingAtMe": HunavNode("condition", ("agent_id", "time_step", "distance_threshold", "angle_threshold",
                                                   "duration"), ("observer_id",), clock="wall"),
    "IsLookingAtMe": HunavNode("condition", ("agent_id", "time_step", "target_id", "distance_threshold",
                                             "angle_threshold", "duration"), clock="wall"),
    # simple actions (bt_node.cpp registerSimpleAction)
    "UpdateGoal": HunavNode("action", ("agent_id",)),
    "RegularNav": HunavNode("action", ("agent_id", "time_step")),
    "SurprisedNav": HunavNode("action", _NAV, clock="simulation"),
    "CuriousNav": HunavNode("action", _NAV + ("agent_vel", "stop_distance"), clock="simulation"),
    "ScaredNav": HunavNode("action", _NAV + ("runaway_vel", "scary_force_factor"), clock="simulation"),
    "ThreateningNav": HunavNode("action", _NAV + ("goal_dist",), clock="simulation"),
    "FindNearestAgent": HunavNode("action", ("agent_id",), ("target_agent_id",)),
    "SaySomething": HunavNode("action", ("agent_id", "message")),
    "SetGroupId": HunavNode("action", ("agent_id", "group_id")),
    "SetGoal": HunavNode("action", ("agent_id", "target_x", "target_y", "goal_id")),
    "StopMovement": HunavNode("action", ("agent_id",)),
    "ResumeMovement": HunavNode("action", ("agent_id",)),
    # stateful actions (bt_node.cpp registerNodeType<...>, ports from each header's providedPorts)
    "StopAndWaitTimerAction": HunavNode("action", ("agent_id", "wait_duration"), clock="wall"),
    "ConversationFormation": HunavNode("action", ("main_agent_id", "goal_id", "conversation_duration", "time_step",
                                                  "non_main_agent_ids"), clock="wall"),
    "GoTo": HunavNode("action", ("agent_id", "goal_id", "time_step", "tolerance")),
    "ApproachAgent": HunavNode("action", ("agent_id", "target_agent_id", "time_step", "duration"), clock="wall"),
    "FollowAgent": HunavNode("action", ("agent_id", "target_agent_id", "time_step", "closest_dist", "max_vel",
                                        "duration"), clock="wall"),
    "ApproachRobot": HunavNode("action", ("agent_id", "time_step", "closest_dist", "max_vel", "duration"),
                               clock="wall"),
    "BlockRobot": HunavNode("action", ("agent_id", "time_step", "front_dist", "duration"), clock="wall"),
    "AvoidRobot": HunavNode("action", ("agent_id", "time_step", "safe_distance", "runaway_vel", "duration"),
                            clock="wall"),
    "BlockAgent": HunavNode("action", ("agent_id", "target_agent_id", "time_step", "front_dist", "duration"),
                            clock="wall"),
    "SetGroupWalk": HunavNode("action", ("main_agent_id", "time_step", "duration", "non_main_agent_ids"),
                              clock="wall"),
    "LookAtPoint": HunavNode("action", ("agent_id", "goal_id", "yaw_tolerance")),
    "LookAtAgent": HunavNode("action", ("observer_id", "target_id", "yaw_tolerance")),
    "LookAtRobot": HunavNode("action", ("agent_id", "yaw_tolerance")),
    # decorator (time_delay_decorator.hpp)
    "TimeDelay": HunavNode("decorator", ("delay",), clock="wall"),
}

# BT.CPP's own timed decorators run on the wall clock too (std::chrono timers inside BehaviorTree.CPP).
CLOCKS: dict[str, str] = {name: node.clock for name, node in HUNAV_NODES.items() if node.clock != "none"} | {
    "Delay": "wall", "Timeout": "wall"}

_ANY_NODE_ATTRIBUTES = frozenset({"name", "ID", "_description", "_uid", "_fullpath"})
REACTION_NODES = frozenset({"SurprisedNav", "CuriousNav", "ScaredNav", "ThreateningNav"})


def _read(xml: str | bytes) -> TreeDocument:
    return read_tree(xml, "<hunav tree>")


def restrict_to_hunav_ports(document: TreeDocument) -> TreeDocument:
    """Drop, in place, every attribute of a HuNavSim node that HuNavSim does not declare (BT.CPP 4 would
    refuse it); returns the document.

    GROVE's manifest keeps ports HuNavSim's own TreeNodesModel.xml documents but its C++ no longer
    declares (RandomChanceCondition agent_id, ApproachAgent closest_dist/max_vel); HuNavSim uses its
    built-in values for those, so dropping them is what HuNavSim itself would run.
    """
    for element in document.nodes():
        declared = HUNAV_NODES.get(element.id)
        if declared is None:
            continue
        for attribute in list(element.attributes):
            if attribute not in declared.ports and attribute not in _ANY_NODE_ATTRIBUTES:
                del element.attributes[attribute]
    return document


def hunav_loading_problems(xml: str | bytes) -> list[str]:
    """Why HuNavSim 2.0's factory would refuse this tree: unregistered node IDs, undeclared ports.

    Checks what BT.CPP 4's XML parser checks against the registered manifests; an empty list means
    `createTreeFromFile` gets past node creation (port *values* are read at tick time).
    """
    document = _read(xml)
    problems: list[str] = []
    for element in document.nodes():
        where = f"line {element.line}: <{element.id}>"
        if element.id == "SubTree":
            if element.subtree_id not in document.trees:
                problems.append(f"{where} calls BehaviorTree {element.subtree_id!r}, not in this file")
            continue
        if element.id in BTCPP_BUILTINS:
            continue
        declared = HUNAV_NODES.get(element.id)
        if declared is None:
            problems.append(f"{where} is not a node HuNavSim 2.0 registers")
            continue
        for attribute in element.attributes:
            if attribute not in declared.ports and attribute not in _ANY_NODE_ATTRIBUTES:
                problems.append(f"{where} has port {attribute!r}, which HuNavSim's {element.id} does not "
                                f"declare (it declares {', '.join(declared.inputs + declared.outputs)})")
    return problems


def wrap_for_hunav(document: TreeDocument, *, reaction: tuple[str, float, float, bool] | None, hold_seconds: float,
                   looping: frozenset[str]) -> TreeDocument:
    """Make a GROVE tree behave in HuNavSim as it does in GROVE (in place; returns the document).

    - The main tree's body runs once (ForceSuccess: a failing step ends the routine, as in GROVE, where
      a finished tree leaves the agent where it is) and then holds, standing where it ended; so the
      final state survives HuNavSim's per-step ticking of the root. A tree that already reacts to the
      robot around its routine gets the hold inside that reaction: the person keeps reacting after the
      routine, as in GROVE's simulation (bt/format/after_task.py). Trees that loop HuNavSim-style
      (a node of `looping`, e.g. RegularNav, completes every tick by design) and trees already
      wrapped (a re-export of an imported export) are left as they are.
    - `reaction` (node, trigger distance m, duration s, only once) wraps the routine in the pattern
      GROVE's simulation uses (simulation.with_robot_reaction) and HuNavSim 1.0's BTSurprisedNav.xml
      used: ReactiveFallback[Sequence[IsRobotVisible, ForceFailure(<Reaction>Nav)], routine]. HuNavSim
      2.0 reacts to the robot only through the tree (no built-in reaction), so the tree must carry it;
      a tree that already deals with the robot (a reaction or ApproachRobot, AvoidRobot...) is not
      wrapped again, as GROVE's simulation does not wrap it (simulation.with_robot_reaction).
    """
    used = {element.id for element in document.nodes()}
    wrapped = any(element.get("name") == HOLD_NAME for element in document.nodes())
    if used & looping or wrapped:
        return document
    main = document.trees[document.main_tree_id]
    if len(main.children) != 1:
        return document
    if keep_reacting_after_task(document, hold_seconds):
        # the tree reacts to the robot around its routine: the hold goes inside, so the person keeps
        # reacting once the routine is over, as in GROVE's simulation (bt/format/after_task.py)
        return document
    routine = run_once_then_hold(main.children[0], hold_seconds)
    if reaction is not None and not (used & ROBOT_RESPONSES):
        node_id, distance, duration, once = reaction
        trigger = node("Sequence", [
            node("IsRobotVisible", agent_id="{id}", distance=f"{distance:g}"),
            node("ForceFailure", [node(node_id, agent_id="{id}", time_step="{dt}", beh_duration=f"{duration:g}",
                                       only_once="true" if once else "false")]),
        ])
        trigger.set("name", f"react_{node_id}")
        routine = node("ReactiveFallback", [trigger, routine])
        routine.set("name", "robot_reaction")
    main.children[0] = routine
    return document


def prefix_node_ids(document: TreeDocument, names: frozenset[str], prefix: str) -> TreeDocument:
    """Rename nodes `names` to `prefix + name`, in place, in trees and TreeNodesModels (ID attributes)."""
    for element in document.nodes():
        if element.tag in names:
            element.tag = prefix + element.tag
    for model in document.models:
        for element in model.walk():
            model_id = element.get("ID")
            if element.tag in ("Action", "Condition", "Decorator", "Control") and model_id is not None \
                    and model_id in names:
                element.set("ID", prefix + model_id)
    return document


def label_clocks(document: TreeDocument) -> TreeDocument:
    """Name every unnamed timed node after the clock HuNavSim runs it on (`CLOCKS`), in place, e.g.
    `StopAndWaitTimerAction name="StopAndWaitTimerAction (wall clock)"`: GROVE counts simulation
    seconds everywhere, HuNavSim counts wall-clock seconds in these, and the file should say so where
    a reader looks (Groot2 shows the name)."""
    for element in document.nodes():
        if element.id in CLOCKS and element.get("name") is None:
            element.set("name", f"{element.id} ({CLOCKS[element.id]} clock)")
    return document
