"""The model's draft checked against the prompt's reading, repaired only where it contradicts it.

The reading (language/reading.py) says which groups the sentence describes: how many people, what
they do, where. The model writes a draft. Each reading group takes the draft group that fits it
best (by label, then by the places and nodes of its tree); then, and only where they disagree:

- a missing group gets the plain tree for its reading;
- a wrong count is set to the reading's (subsets such as "one of them" are taken out of their parent);
- an idle tree (one with no routine action: only conditions, or only a robot reaction) is replaced;
- a tree that does another thing than the reading's stationary intent (queue, wait, converse,
  wander), or does it elsewhere, is replaced by the plain tree for the reading;
- a destination the tree never reaches is appended as a GoTo step, keeping what the model wrote;
- a group that should move together gets a JoinGroup step;
- a stated robot reaction sets the group's HuNavSim `behavior` and wraps its tree in HuNavSim's
  reaction pattern (ReactiveFallback[IsRobotVisible -> ForceFailure(<Reaction>Nav)], routine).

Each repair is a note. What the model wrote beyond the reading (an extra Wait, a detour) stays.
`grounding_report` then sets what the sentence asked beside what the scenario does.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from grove_tui.bt.leaves.hunav import ROBOT_REACTION_DEFAULTS, ROBOT_REACTIONS
from grove_tui.bt.manifest import NODES
from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.language.reading import GroupReading, PromptReading, effective_counts
from grove_tui.language.tokens import lemma, words
from grove_tui.scenario.report import GroundingCheck, GroundingReport, GroupGrounding
from grove_tui.world.model import Door, Entity, World

# Nodes that make a person do something on their own: a tree with none of them leaves its agent
# standing where it spawned (conditions, bookkeeping and robot reactions only fire on cue).
ROUTINE_NODES = frozenset({"GoTo", "Wait", "Queue", "Wander", "Converse", "FollowVelocityField", "FollowAgent",
                           "ConversationFormation", "StopAndWaitTimerAction", "SetGroupWalk", "ApproachAgent",
                           "RegularNav", "LookAtPoint"})
STATIONARY_NODES = {"queue": {"Queue"}, "converse": {"Converse", "ConversationFormation"}, "wander": {"Wander"},
                    "wait": {"Wait", "StopAndWaitTimerAction", "Queue"}}
PACE_FACTORS = {"slow": 0.7, "normal": 1.0, "fast": 1.4}
MOVING_INTENTS = frozenset({"walk", "evacuate", "follow"})
WALKING_NODES = frozenset({"GoTo", "FollowVelocityField", "FollowAgent"})
DEFAULT_WAIT_SECONDS = 60.0  # "a man waits on the bench": long enough to be seen waiting
SERVICE_TYPES = ("counter", "desk", "reception", "booth", "kiosk", "vending_machine", "machine")


@dataclass
class ReconciledGroup:
    """One group after reconciliation: what post-processing places and writes."""

    reading_index: int | None  # index into reading.groups; None when the prompt has no reading of groups
    label: str
    count: int
    spawn: str
    tree: DraftNode
    behavior: str = "Regular"  # HuNavSim reaction to the robot
    party_size: int | None = None  # "two families of three": social groups of 3
    speed_factor: float = 1.0


def reconcile(draft: Draft, reading: PromptReading, world: World, default_spawn: str,
              notes: list[str], *, evacuation_field: bool = False) -> list[ReconciledGroup]:
    """Reading groups with the draft's trees, repaired where they contradict the reading (module doc).

    `evacuation_field`: the preset evacuates along velocity fields, so an evacuating group's plain
    tree follows the field instead of walking to the exit."""
    counts = effective_counts(reading)
    drafts = list(draft.groups)
    unused = list(range(len(drafts)))
    out: list[ReconciledGroup] = []
    for index, group in enumerate(reading.groups):
        count = counts.get(index, 0)
        if count <= 0:
            continue
        pick = _pick_draft(group, drafts, unused, world)
        label = group.label
        if pick is None:
            tree = tree_for(group, world, evacuation_field)
            notes.append(f"group '{label}': added for '{group.who}' (the model wrote no group for it)")
            spawn = _spawn(group, None, world, default_spawn, tree)
        else:
            unused.remove(pick)
            d = drafts[pick]
            if d.count != count:
                notes.append(f"group '{label}': count {d.count} -> {count} ('{group.who}')")
            tree = _repair(d.tree, group, world, notes, label, evacuation_field)
            spawn = _spawn(group, d, world, default_spawn, tree)
        behavior = group.robot_reaction or "Regular"
        if group.robot_reaction:
            tree = with_reaction(tree, group.robot_reaction)
        if group.together and count > 1 and not any(n.node in ("JoinGroup", "Converse") for n in tree.walk()):
            tree = _prepend(DraftNode("JoinGroup", {}), tree)
            notes.append(f"group '{label}': walks together as the prompt says")
        party = group.count.party_size if group.count.parties and (group.count.party_size or 0) > 1 else None
        out.append(ReconciledGroup(index, label, count, spawn, tree, behavior, party,
                                   PACE_FACTORS.get(group.pace, 1.0)))
    for i in unused:
        notes.append(f"dropped group '{drafts[i].label}' ({drafts[i].count}): the prompt states no such people")
    return out


# ---- matching -------------------------------------------------------------------------------

def _pick_draft(group: GroupReading, drafts: Sequence[DraftGroup], unused: Sequence[int], world: World) -> int | None:
    if not unused:
        return None
    wanted = {group.label, lemma(group.label)} | {lemma(w) for w in words(group.who)}
    places = {_zone_of(world, p) for p in (group.start, group.destination, group.location) if p}

    def score(i: int) -> float:
        d = drafts[i]
        label = {lemma(w) for w in words(d.label.replace("_", " "))}
        s = 3.0 * len(label & wanted)
        s += sum(1.0 for p in _tree_places(d.tree) if _zone_of(world, p) in places)
        nodes = {n.node for n in d.tree.walk()}
        if nodes & STATIONARY_NODES.get(group.intent, set()):
            s += 1.0
        return s

    best = max(unused, key=lambda i: (score(i), -i))
    return best if score(best) > 0 else unused[0]


# ---- repairs --------------------------------------------------------------------------------

def is_idle(tree: DraftNode) -> bool:
    """A tree with no routine action: its agent would stand still unless the robot comes by."""
    return not any(node.node in ROUTINE_NODES for node in tree.walk())


def _repair(tree: DraftNode, group: GroupReading, world: World, notes: list[str], label: str,
            evacuation_field: bool = False) -> DraftNode:
    if is_idle(tree):
        fixed = tree_for(group, world, evacuation_field)
        notes.append(f"group '{label}': the model's tree had no action ({_kinds(tree)}); {group.intent} "
                     f"as the prompt says")
        return fixed
    base = _base_intent(group)
    if base in STATIONARY_NODES:
        place = _stationary_place(group, world, base)
        nodes = [n for n in tree.walk() if n.node in STATIONARY_NODES[base]]
        right_place = place is None or any(_same_place(world, _node_place(n), place, base) for n in nodes)
        if not nodes or not right_place:
            fixed = tree_for(group, world)
            where = f" at {place}" if place else ""
            notes.append(f"group '{label}': {base}{where} as the prompt says, instead of the model's {_kinds(tree)}")
            return fixed
        if base == "wait" and group.wait_seconds:
            tree = _set_wait(tree, group.wait_seconds)
    destination = group.destination
    if destination and not _reaches(world, destination, _tree_places(tree)):
        notes.append(f"group '{label}': goes to {destination} (named in the prompt)")
        tree = _append(tree, DraftNode("GoTo", {"target": destination}))
    elif destination and base in MOVING_INTENTS and not _reaches(world, destination, _walked_places(tree)):
        # "walk from the lobby to ward a" drafted as wandering in ward a: they walk there first, then
        # do what the model added
        notes.append(f"group '{label}': walks to {destination} before the model's {_kinds(tree)}")
        tree = _prepend(DraftNode("GoTo", {"target": destination}), tree)
    return tree


def _walked_places(tree: DraftNode) -> list[str]:
    """Places a tree walks to (GoTo, the evacuation field), not those it only stays in."""
    return [p for node in tree.walk() if node.node in WALKING_NODES for p in [_node_place(node)] if p]


def _base_intent(group: GroupReading) -> str:
    """What the group does apart from reacting to the robot."""
    if group.intent != "robot":
        return group.intent
    if group.destination:
        return "walk"
    return "wait"


def tree_for(group: GroupReading, world: World, evacuation_field: bool = False) -> DraftNode:
    """The plain tree for a reading: where it says, what it says, nothing more."""
    base = _base_intent(group)
    if base == "evacuate" and evacuation_field:
        exit_name = group.destination if _is_exit(world, group.destination) else _nearest_exit(world, group.start)
        return DraftNode("FollowVelocityField", {"exit": exit_name})
    steps: list[DraftNode] = []
    via = [DraftNode("GoTo", {"target": v}) for v in group.via]
    if base == "queue":
        service = _stationary_place(group, world, "queue") or _service_in(world, group.start or "")
        if service is not None:
            return DraftNode("Sequence", {}, tuple(via) + (DraftNode("GoTo", {"target": service}),
                                                           DraftNode("Queue", {"service_point": service})))
        base = "wait"
    if base == "converse":
        spot = group.location or group.start or group.destination
        if spot is not None:
            return DraftNode("Converse", {"target": spot, "duration": 60.0})
        base = "wait"
    if base == "wander":
        zone = _zone_of(world, group.location or group.start or group.destination or "")
        if zone:
            return DraftNode("Wander", {"zone": zone, "duration": 120.0})
        base = "wait"
    if base == "wait":
        place = group.location or group.destination
        if place is not None:
            steps.append(DraftNode("GoTo", {"target": place}))
        steps.append(DraftNode("Wait", {"duration": float(group.wait_seconds or DEFAULT_WAIT_SECONDS)}))
        return DraftNode("Sequence", {}, tuple(via) + tuple(steps)) if len(steps) + len(via) > 1 else steps[0]
    # walk, evacuate, follow
    destination = group.destination
    if destination is None and base == "evacuate":
        destination = _nearest_exit(world, group.start)
    if destination is None:
        zone = _zone_of(world, group.start or group.location or "")
        if zone:
            return DraftNode("Wander", {"zone": zone, "duration": 120.0})
        destination = _nearest_exit(world, None)
    steps = via + [DraftNode("GoTo", {"target": destination})]
    return steps[0] if len(steps) == 1 else DraftNode("Sequence", {}, tuple(steps))


def with_reaction(tree: DraftNode, behavior: str) -> DraftNode:
    """The tree inside HuNavSim's reaction pattern for `behavior`, unless it already reacts."""
    spec = ROBOT_REACTION_DEFAULTS.get(behavior)
    if spec is None or any(n.node in ROBOT_REACTIONS for n in tree.walk()):
        return tree
    node, distance, duration, once = spec
    reaction = DraftNode("Sequence", {}, (
        DraftNode("IsRobotVisible", {"distance": distance}),
        DraftNode("ForceFailure", {}, (DraftNode(node, {"beh_duration": duration, "only_once": once}),)),
    ))
    return DraftNode("ReactiveFallback", {}, (reaction, tree))


def _set_wait(tree: DraftNode, seconds: float) -> DraftNode:
    ports = dict(tree.ports)
    if tree.node == "Wait":
        ports["duration"] = float(seconds)
    return DraftNode(tree.node, ports, tuple(_set_wait(c, seconds) for c in tree.children))


def _append(tree: DraftNode, step: DraftNode) -> DraftNode:
    if tree.node == "Sequence":
        return DraftNode("Sequence", dict(tree.ports), tree.children + (step,))
    return DraftNode("Sequence", {}, (tree, step))


def _prepend(step: DraftNode, tree: DraftNode) -> DraftNode:
    if tree.node == "Sequence":
        return DraftNode("Sequence", dict(tree.ports), (step,) + tree.children)
    return DraftNode("Sequence", {}, (step, tree))


def _kinds(tree: DraftNode) -> str:
    return ", ".join(sorted({n.node for n in tree.walk()}))


# ---- places ---------------------------------------------------------------------------------

def _target_ports(node: DraftNode) -> list[str]:
    spec = NODES.get(node.node)
    return [p.name for p in spec.ports if p.type == "target"] if spec is not None else []


def _node_place(node: DraftNode) -> str | None:
    return next((node.ports[p] for p in _target_ports(node) if p in node.ports), None)


def _tree_places(tree: DraftNode) -> list[str]:
    return [p for node in tree.walk() for p in [_node_place(node)] if p]


def _zone_of(world: World, name: str) -> str | None:
    if not name:
        return None
    try:
        obj = world.find(name)
    except Exception:
        return None
    zone = getattr(obj, "zone", None)
    return zone if isinstance(zone, str) and zone else getattr(obj, "name", None)


def _reaches(world: World, goal: str, places: Sequence[str]) -> bool:
    """Whether a tree visiting `places` goes where the reading sends the group: anywhere in a named
    zone, but to a named door or thing itself."""
    if goal in places:
        return True
    return _zone_of(world, goal) == goal and any(_zone_of(world, p) == goal for p in places)


def _same_place(world: World, have: str | None, want: str, intent: str) -> bool:
    if have is None:
        return False
    if have == want:
        return True
    if intent == "queue":
        return _service_in(world, want) == have or _service_in(world, have) == want
    return _zone_of(world, have) == _zone_of(world, want)


def _stationary_place(group: GroupReading, world: World, intent: str) -> str | None:
    place = group.location or (group.destination if intent in STATIONARY_NODES else None)
    if place is None:
        return None
    if intent == "queue":
        return _service_in(world, place) or place
    return place


def _service_in(world: World, name: str) -> str | None:
    """The service point a place stands for: the entity itself, or its zone's counter or desk."""
    try:
        obj = world.find(name)
    except Exception:
        return None
    if isinstance(obj, Entity):
        return obj.name
    zone = world.zone(obj.zone) if isinstance(obj, Door) else obj
    for wanted in SERVICE_TYPES:
        for e in getattr(zone, "entities", ()):
            if wanted in e.type or wanted in e.name:
                return str(e.name)
    return None


def _is_exit(world: World, name: str | None) -> bool:
    return bool(name) and any(d.name == name for d in world.exits())


def _nearest_exit(world: World, start: str | None) -> str:
    exits = world.exits()
    if not exits:
        return str(world.zones[0].name)
    zone = _zone_of(world, start or "")
    if zone is None:
        return exits[0].name
    cx, cy = world.zone(zone).centroid
    return min(exits, key=lambda d: (math.hypot(d.position[0] - cx, d.position[1] - cy), d.name)).name


def _spawn(group: GroupReading, d: DraftGroup | None, world: World, default: str, tree: DraftNode) -> str:
    """Where the group starts: the reading's start; for stationary groups the place they are; else the
    model's spawn unless it is where they are sent, then the largest room next to it."""
    for name in (group.start, group.location if _base_intent(group) in STATIONARY_NODES else None):
        zone = _zone_of(world, name or "")
        if zone:
            return zone
    spawn = _zone_of(world, d.spawn) if d is not None else None
    spawn = spawn or default
    first = next((p for p in _tree_places(tree)), None)
    if first is not None and _zone_of(world, first) == spawn and _base_intent(group) not in STATIONARY_NODES:
        neighbours = sorted({door.leads_to if door.zone == spawn else door.zone for door in world.doors_of(spawn)}
                            - {spawn, "outside"})
        if neighbours:
            return max(neighbours, key=lambda z: (world.zone(z).area, z))
    return spawn


# ---- the grounding report -------------------------------------------------------------------

_INTENT_NODES = {"queue": {"Queue"}, "converse": {"Converse", "ConversationFormation"}, "wander": {"Wander"},
                 "wait": {"Wait", "StopAndWaitTimerAction", "Queue"},
                 # with no destination named, walking along the evacuation field (to the nearest exit) is walking
                 "walk": {"GoTo", "Wander", "FollowVelocityField"},
                 "follow": {"GoTo", "FollowAgent", "Wander"}, "evacuate": {"GoTo", "FollowVelocityField"}}
# A walk with a destination must walk there; wandering is a walk only when no destination is named.


def grounding_report(reading: PromptReading, groups: Sequence[Any], agents: Sequence[Any], world: World,
                     repairs: Sequence[str] = ()) -> GroundingReport:
    """What the sentence asked beside what the scenario does, per reading group.

    `groups` are post-processing's GroupPlans (reading_index, label, count, spawn, tree, behavior,
    member_ids); `agents` its AgentPlans."""
    by_reading = {g.reading_index: g for g in groups if getattr(g, "reading_index", None) is not None}
    counts = effective_counts(reading)
    out: list[GroupGrounding] = []
    unhonoured: list[str] = [f"'{p}' is not a place of world '{world.name}'" for p in reading.unknown_places]
    unhonoured += list(reading.notes)
    if not reading.groups and groups:
        # The older word rules placed the model's groups: say that nothing here was read from the
        # sentence rather than let the report look clean.
        guessed = ", ".join(f"{g.label} x{g.count}" for g in groups)
        unhonoured.append(f"no group of people was read from the sentence: the scenario's groups ({guessed}) are "
                          f"the model's guess, placed by word rules")
    for index, r in enumerate(reading.groups):
        g = by_reading.get(index)
        if g is None:
            if counts.get(index, 0) > 0:
                unhonoured.append(f"'{r.who}' has no group in the scenario")
            continue
        checks = [_check_count(r, counts.get(index, 0), g)]
        spread = getattr(g, "spawn_zones", None)  # a crowd the sentence places nowhere, spread over the building
        checks.append(_check_place("start", r.start, f"across the building ({len(spread)} zones)" if spread else g.spawn,
                                   world, zone_level=True))
        places = _tree_places(g.tree)
        if r.destination:
            does = r.destination if _reaches(world, r.destination, places) else (places[-1] if places else "nowhere")
            checks.append(GroundingCheck("destination", r.destination, does, does == r.destination,
                                         "" if does == r.destination else "the trees never go there"))
        else:
            checks.append(GroundingCheck("destination", "-", places[-1] if places else "-", True,
                                         "the sentence names none"))
        checks.append(_check_behavior(r, g, world))
        asked = r.robot_reaction or "-"
        does = getattr(g, "behavior", "Regular")
        reacts = any(n.node in ROBOT_REACTIONS for n in g.tree.walk())
        if r.robot_reaction:
            ok = does == r.robot_reaction and reacts
            checks.append(GroundingCheck("robot reaction", asked, does + (" (in tree)" if reacts else ""), ok,
                                         "" if ok else "the reaction is not in the agents' trees"))
        else:
            checks.append(GroundingCheck("robot reaction", asked, does, True, "the sentence asks for none"))
        out.append(GroupGrounding(r.who, g.label, tuple(checks), tuple(g.member_ids)))
    return GroundingReport(reading.prompt, tuple(out), tuple(dict.fromkeys(unhonoured)), tuple(repairs),
                           tuple(reading.corrections))


def _check_count(r: GroupReading, wanted: int, g: Any) -> GroundingCheck:
    c = r.count
    asked = str(c.value) if c.kind == "exact" else f"{c.value} ({c.kind} {c.low}-{c.high})"
    if c.parties:
        asked += f", {c.parties} x {c.party_size}"
    if wanted != c.value:
        asked += f"; {wanted} of its own"
    ok = g.count == wanted
    return GroundingCheck("count", asked, str(g.count), ok, "" if ok else "the group's size differs")


def _check_place(field: str, asked: str | None, does: str, world: World, zone_level: bool) -> GroundingCheck:
    if not asked:
        return GroundingCheck(field, "-", does, True, "the sentence names none")
    want = _zone_of(world, asked) if zone_level else asked
    ok = want == does
    return GroundingCheck(field, asked, does, ok, "" if ok else f"they start in {does}")


def _check_behavior(r: GroupReading, g: Any, world: World) -> GroundingCheck:
    base = _base_intent(r)
    nodes = {n.node for n in g.tree.walk()}
    asked = r.intent + (f" ({r.robot_interaction} the robot)" if r.robot_interaction else "")
    if r.wait_seconds:
        asked += f" {r.wait_seconds:g} s"
    if is_idle(g.tree):
        return GroundingCheck("behavior", asked, "nothing (idle tree)", False, "the tree has no action")
    wanted = _INTENT_NODES.get(base, set())
    if base in MOVING_INTENTS and r.destination:
        wanted = set(WALKING_NODES)
    does = ", ".join(sorted(nodes & ROUTINE_NODES)) or "nothing"
    ok = bool(nodes & wanted)
    reason = ""
    if not ok:
        reason = f"no {'/'.join(sorted(wanted))} node"
    if base == "follow" and "FollowAgent" not in nodes:
        reason = "following one person is played as walking to the same place"
    return GroundingCheck("behavior", asked, does, ok, reason)
