"""HuNavSim 2.0's own node set: the node IDs its agent manager registers and the ports each declares.

GROVE's manifest (bt/manifest.py) is a superset: it adds GROVE nodes, keeps 1.0 and 2.0 port variants,
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

import dataclasses
from dataclasses import dataclass

from lxml import etree

from grove_tui.bt.manifest import NODES

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
_STRUCTURE = frozenset({"root", "BehaviorTree", "TreeNodesModel", "include"})


def _parser() -> etree.XMLParser:
    return etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False,
                           remove_blank_text=True)


def restrict_to_hunav_ports(xml: str) -> str:
    """Drop every attribute of a HuNavSim node that HuNavSim does not declare (BT.CPP 4 would refuse it).

    GROVE's manifest keeps ports HuNavSim's own TreeNodesModel.xml documents but its C++ no longer
    declares (RandomChanceCondition agent_id, ApproachAgent closest_dist/max_vel); HuNavSim uses its
    built-in values for those, so dropping them is what HuNavSim itself would run.
    """
    root = etree.fromstring(xml.encode("utf-8"), _parser())
    for tree in root.iter("BehaviorTree"):
        for element in tree.iter():
            if not isinstance(element.tag, str):
                continue
            node = HUNAV_NODES.get(element.tag)
            if node is None:
                continue
            for attribute in list(element.attrib):
                if attribute not in node.ports and attribute not in _ANY_NODE_ATTRIBUTES:
                    del element.attrib[attribute]
    return etree.tostring(root, pretty_print=True, encoding="unicode")


def hunav_loading_problems(xml: str) -> list[str]:
    """Why HuNavSim 2.0's factory would refuse this tree: unregistered node IDs, undeclared ports.

    Checks exactly what BT.CPP 4's XML parser checks against the registered manifests; an empty list
    means `createTreeFromFile` gets past node creation (port *values* are read at tick time).
    """
    root = etree.fromstring(xml.encode("utf-8"), _parser())
    problems: list[str] = []
    tree_ids = {tree.get("ID") for tree in root.iter("BehaviorTree")}
    for tree in root.iter("BehaviorTree"):
        for element in tree.iter():
            if not isinstance(element.tag, str) or element is tree:
                continue
            where = f"line {element.sourceline}: <{element.tag}>"
            if element.tag == "SubTree":
                if element.get("ID") not in tree_ids:
                    problems.append(f"{where} calls BehaviorTree {element.get('ID')!r}, not in this file")
                continue
            if element.tag in BTCPP_BUILTINS:
                continue
            node = HUNAV_NODES.get(element.tag)
            if node is None:
                problems.append(f"{where} is not a node HuNavSim 2.0 registers")
                continue
            for attribute in element.attrib:
                if attribute not in node.ports and attribute not in _ANY_NODE_ATTRIBUTES:
                    problems.append(f"{where} has port {attribute!r}, which HuNavSim's {element.tag} does not "
                                    f"declare (it declares {', '.join(node.inputs + node.outputs)})")
    return problems


def node_ids(xml: str) -> list[str]:
    """Node IDs used in the trees of a document (in document order, repeated)."""
    root = etree.fromstring(xml.encode("utf-8"), _parser())
    return [el.tag for tree in root.iter("BehaviorTree") for el in tree.iter()
            if isinstance(el.tag, str) and el is not tree]


def _element(tag: str, attributes: dict[str, str], children=()) -> etree._Element:
    element = etree.Element(tag, attributes)
    for child in children:
        element.append(child)
    return element


def hold_forever(wait_seconds: float) -> etree._Element:
    """A leaf-level subtree that stands still and never completes.

    HuNavSim ticks every agent's root on every step and BT.CPP 4 resets a root that returned SUCCESS
    or FAILURE, so a tree that simply ends is started again (bt_node.cpp `tree_tick`, every
    ComputeAgents call). KeepRunningUntilFailure turns each completed wait into RUNNING and restarts it.
    """
    return _element("KeepRunningUntilFailure", {"name": "hold_final_state"}, [
        _element("StopAndWaitTimerAction", {"agent_id": "{id}", "wait_duration": f"{wait_seconds:g}"})])


def wrap_for_hunav(xml: str, *, reaction: tuple[str, float, float, bool] | None, hold_seconds: float,
                   looping: frozenset[str]) -> str:
    """Make a GROVE tree behave in HuNavSim as it does in GROVE.

    - The main tree's body runs once (ForceSuccess: a failing step ends the routine, as in GROVE, where
      a finished tree leaves the agent where it is) and then holds, standing where it ended; so the
      final state survives HuNavSim's per-step ticking of the root. Trees that loop HuNavSim-style
      (a node of `looping`, e.g. RegularNav, completes every tick by design) are left as they are.
    - `reaction` (node, trigger distance m, duration s, only once) wraps the routine in the pattern
      GROVE's simulation uses (simulation.with_robot_reaction) and HuNavSim 1.0's BTSurprisedNav.xml
      used: ReactiveFallback[Sequence[IsRobotVisible, ForceFailure(<Reaction>Nav)], routine]. HuNavSim
      2.0 reacts to the robot only through the tree (no built-in reaction), so the tree must carry it.
    """
    root = etree.fromstring(xml.encode("utf-8"), _parser())
    main_id = root.get("main_tree_to_execute")
    trees = root.findall("BehaviorTree")
    main = next((t for t in trees if t.get("ID") == main_id), trees[0] if trees else None)
    if main is None:
        return xml
    bodies = [child for child in main if isinstance(child.tag, str)]
    if len(bodies) != 1:
        return xml
    body = bodies[0]
    used = {el.tag for t in trees for el in t.iter() if isinstance(el.tag, str)}
    already = any(el.get("name") == "hold_final_state" for t in trees for el in t.iter() if isinstance(el.tag, str))
    if used & looping or already:  # looping by design, or wrapped by an earlier export (re-export of an import)
        return xml
    main.remove(body)
    routine = _element("SequenceWithMemory", {"name": "run_once_then_hold"},
                       [_element("ForceSuccess", {}, [body]), hold_forever(hold_seconds)])
    reaction_nodes = {"SurprisedNav", "CuriousNav", "ScaredNav", "ThreateningNav"}
    if reaction is not None and not (used & reaction_nodes):
        node, distance, duration, once = reaction
        trigger = _element("Sequence", {"name": f"react_{node}"}, [
            _element("IsRobotVisible", {"agent_id": "{id}", "distance": f"{distance:g}"}),
            _element("ForceFailure", {}, [_element(node, {
                "agent_id": "{id}", "time_step": "{dt}", "beh_duration": f"{duration:g}",
                "only_once": "true" if once else "false"})]),
        ])
        routine = _element("ReactiveFallback", {"name": "robot_reaction"}, [trigger, routine])
    main.append(routine)
    return etree.tostring(root, pretty_print=True, encoding="unicode")


def prefix_node_ids(xml: str, names: frozenset[str], prefix: str) -> str:
    """Rename nodes `names` to `prefix + name` in trees and in a TreeNodesModel (ID attributes)."""
    root = etree.fromstring(xml.encode("utf-8"), _parser())
    for element in root.iter():
        if not isinstance(element.tag, str):
            continue
        if element.tag in names:
            element.tag = prefix + element.tag
        if element.tag in ("Action", "Condition", "Decorator", "Control") and element.get("ID") in names:
            element.set("ID", prefix + element.get("ID"))
    return etree.tostring(root, pretty_print=True, encoding="unicode", xml_declaration=False)


def checked_port(spec, port):
    """The port as GROVE checks a literal for it: HuNavSim's own nodes get no bounds.

    HuNavSim declares its ports without limits (BT::InputPort<double>(...) in bt_node.cpp and the node
    headers), and its shipped trees use values such as ThreateningNav goal_dist="20"; a tree HuNavSim
    runs must not be refused here. The manifest's bounds still shape what the language model may write.
    """
    if spec.origin != "hunavsim" or (port.min is None and port.max is None):
        return port
    return dataclasses.replace(port, min=None, max=None)


def satisfied_by_goal_id(port, given_ports) -> bool:
    """A navigation `target` given instead as HuNavSim's `goal_id` (a global goal of the scenario).

    HuNavSim 2.0's GoTo names its destination only by goal_id (go_to_node.hpp); GROVE's GoTo accepts
    that form too (the runtime resolves the id in the scenario's global goals), so a HuNavSim tree and
    an exported GROVE tree validate without a `target`.
    """
    return port.type == "target" and "goal_id" in given_ports


def label_clocks(xml: str) -> str:
    """Name every unnamed timed node after the clock HuNavSim runs it on (`CLOCKS`), e.g.
    `StopAndWaitTimerAction name="StopAndWaitTimerAction (wall clock)"`: GROVE counts simulation
    seconds everywhere, HuNavSim counts wall-clock seconds in these, and the file should say so where
    a reader looks (Groot2 shows the name)."""
    root = etree.fromstring(xml.encode("utf-8"), _parser())
    for tree in root.iter("BehaviorTree"):
        for element in tree.iter():
            if isinstance(element.tag, str) and element.tag in CLOCKS and element.get("name") is None:
                element.set("name", f"{element.tag} ({CLOCKS[element.tag]} clock)")
    return etree.tostring(root, pretty_print=True, encoding="unicode")
