"""The model's draft held to the prompt's reading, and the planned grounding report.

The reading (language/reading.py) says which groups the sentence describes: how many people, what
they do, where. The model writes a draft. Each reading group takes the draft group that fits it
best (by label, then by the places and nodes of its tree), and its tree does what the reading says,
nothing the sentence does not ask:

- the tree's core is the plain tree for the reading (`tree_for`): the via places, the destination,
  the queue at its service point, the conversation, the wandering, the wait, the evacuation;
- what the model wrote beyond it is dropped where it changes what the group does (a Queue for a
  walker, a minute of Converse before a walk, people following each other, a detour to a place the
  sentence does not name, a place of the robot's clause); only a pause, a look around or wandering
  at the destination after the core may stay, and it is listed as *added* in the report;
- a stated robot interaction is done for real: a group whose only activity is reacting to the robot
  does it from the start (walks up to it, follows it, steps into its way, keeps away, turns to look),
  not gated on a visibility that may never come; a group with a routine of its own gets HuNavSim's
  reaction pattern around it (ReactiveFallback[IsRobotVisible or IsRobotClose -> ForceFailure(<Reaction>Nav)], routine),
  and the robot's route is planned past it (generation/planning.py);
- a group that should move together gets a JoinGroup step.

Each change is a note. `grounding_report` then writes what the sentence asked as claims a run can
check (scenario/report.py): places, points, partners, paces, each with how long a run needs to show it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Protocol

from grove_tui.crowd.leaves.hunav import ROBOT_REACTION_DEFAULTS, ROBOT_REACTIONS
from grove_tui.generation.picked_places import picked_questions
from grove_tui.generation.approach_at_place import approach_place, approaching_at, at_the_approached_place
from grove_tui.generation.block_at_place import at_the_blocked_place, blocking_at
from grove_tui.bt.format.manifest import NODES
from grove_tui.errors import WorldError
from grove_tui.generation.draft import Draft, DraftGroup, DraftNode, place_at, place_of
from grove_tui.generation.exit_post import claim_radius
from grove_tui.generation.mutual_follow import leads_who_follow_it
from grove_tui.generation.shared_queue import (default_service_time, queue_service_times, service_time_of,
                                               one_service_time_per_queue, with_drafted_service_time,
                                               with_shared_queues)
from grove_tui.generation.guided_claims import guided_out_by
from grove_tui.generation.guided import LED_BEHIND, guided_exit, guided_follow, guided_index
from grove_tui.generation.look_span import glance_or_stare, glancing, look_claim
from grove_tui.generation.passing_look import cued_as_it_passes, passing_looks
from grove_tui.generation.beside_queue import beside_claims
from grove_tui.generation.past_queue import past_or_through
from grove_tui.generation.led_exit import led_exit_of, with_led_exit
from grove_tui.generation.queue_delay import wait_before_queuing
from grove_tui.generation.reaction_routine import routine_of
from grove_tui.generation.run_length import with_run_length
from grove_tui.generation.stay_claims import stay_claims
from grove_tui.generation.robot_errand import errand_claims
from grove_tui.generation.robot_passing import passed_zones
from grove_tui.generation.robot_keep_out import robot_keep_out_claim, robot_kept_out
from grove_tui.language.robot_errands import robot_errand
from grove_tui.generation.route_time import Leg, RouteWalk
from grove_tui.language.model import Count, FieldConfidence, RobotReading
from grove_tui.language.reading import GroupReading, PromptReading, effective_counts
from grove_tui.language.tokens import lemma, words
from grove_tui.scenario.report import (
    FAILS,
    PLANNED,
    Claim,
    GroundingReport,
    GroupGrounding,
    RobotGrounding,
)
from grove_tui.scenario.model import RobotSpec
from grove_tui.world.model import Door, Entity, World, Zone

# Nodes that make a person do something on their own: a tree with none of them leaves its agent
# standing where it spawned (conditions, bookkeeping and robot reactions only fire on cue).
ROUTINE_NODES = frozenset({"GoTo", "Wait", "Queue", "Wander", "Converse", "FollowVelocityField", "FollowAgent",
                           "ConversationFormation", "StopAndWaitTimerAction", "SetGroupWalk", "ApproachAgent",
                           "RegularNav", "LookAtPoint", "ApproachRobot", "BlockRobot", "AvoidRobot",
                           "LookAtRobot"})
STATIONARY_NODES = {"queue": {"Queue"}, "converse": {"Converse", "ConversationFormation"}, "wander": {"Wander"},
                    "wait": {"Wait", "StopAndWaitTimerAction"}}
PACE_FACTORS = {"slow": 0.7, "normal": 1.0, "fast": 1.4}
MOVING_INTENTS = frozenset({"walk", "evacuate", "follow"})
WALKING_NODES = frozenset({"GoTo", "FollowVelocityField", "FollowAgent"})
DEFAULT_WAIT_SECONDS = 60.0  # "a man waits on the bench": long enough to be seen waiting
CONVERSATION_SECONDS = 60.0
SERVICE_TYPES = ("counter", "desk", "reception", "booth", "kiosk", "vending_machine", "machine")
# What the model may leave after the tree's core, listed as "added": a pause, a look, wandering where they arrived.
TRAILING_EXTRAS = frozenset({"Wait", "StopAndWaitTimerAction", "LookAtPoint", "Wander"})
MAX_TRAILING_WAIT = 120.0

# The robot interaction a group does as its whole activity, ungated: (node, ports).
ROBOT_ACTIVITIES: dict[str, tuple[str, dict[str, float]]] = {
    "follow": ("ApproachRobot", {"closest_dist": 1.0, "max_vel": 1.5, "duration": 0.0, "behind": LED_BEHIND}),
    "approach": ("ApproachRobot", {"closest_dist": 0.8, "max_vel": 1.3, "duration": 0.0}),
    "block": ("BlockRobot", {"front_dist": 0.8, "duration": 0.0}),
    "avoid": ("AvoidRobot", {"safe_distance": 3.0, "runaway_vel": 1.2, "duration": 0.0}),
    "look": ("LookAtRobot", {"yaw_tolerance": 0.1}),
}
# Trigger distances for reactions around a routine: far enough that a robot passing the group sets
# them off (HuNavSim's 3-4 m for Scared/Surprised/Threatening would let it slip by unseen).
REACTION_TRIGGER = {"Surprised": 8.0, "Curious": 10.0, "Scared": 5.0, "Threatening": 6.0}
# Distances the outcome checks measure reactions against (metres between centres).
# (centre to centre: room for a few people around the robot when a group comes up to it)
REACTION_DISTANCE = {"follow": 3.0, "approach": 2.5, "block": 2.5, "avoid": 6.0, "look": 10.0}


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
    added: list[str] = field(default_factory=list)  # what the tree does beyond the reading, in words
    reacts_only: bool = False  # its whole activity is reacting to the robot: it starts where the robot passes
    leader_index: int | None = None  # reading index of the group it follows ("follow their guide")
    guided: bool = False  # the robot guides it ("... while the robot guides them to the exit"): behind it, then out


def with_followed_person(reading: PromptReading, world: World) -> PromptReading:
    """The person a robot's clause follows, as a group of the sentence when the reading has none for
    them: "the robot follows a guide from the entrance hall to the auditorium" asks for a guide who
    walks from the entrance hall to the auditorium, with the robot behind. Likewise the person a group
    follows: "six students follow the senior doctor to ward C" has a doctor walking there ahead of them."""
    reading = leads_who_follow_it(_with_people_followed(_subsets_keep_their_activity(reading)))
    robot = reading.robot
    if robot is None or robot.task != "follow" or not robot.follows:
        return reading
    wanted = {lemma(w) for w in words(robot.follows)} - {"a", "an", "the", "one", "him", "her", "them", "someone"}
    if not wanted or any(wanted & ({lemma(w) for w in words(g.who)} | {g.label, lemma(g.label)})
                         for g in reading.groups):
        return reading
    label = lemma(words(robot.follows)[-1])
    count = Count("exact", 1, 1, 1)
    where = [p for p in (robot.start, robot.destination) if p]
    followed = GroupReading(robot.follows, label, count, "walk" if robot.destination else "wait",
                            start=robot.start, destination=robot.destination,
                            location=None if robot.destination else (robot.location or robot.start),
                            via=tuple(robot.via), text=robot.text)
    if not where and not followed.location:
        followed = replace(followed, intent="wander")
    return replace(reading, groups=reading.groups + (followed,))


_NOBODY_IN_PARTICULAR = {"a", "an", "the", "one", "him", "her", "them", "someone", "their", "his", "its", "group",
                         "before", "others", "everyone", "us", "close", "closely", "behind", "right", "just"}


# What some of a group can do to the robot while still doing what the group does ("a dozen passengers
# queue at the counter and some of them glance at the robot": those six queue too, looking as it comes).
# Following, approaching or blocking it takes them out of what the group does.
_ALONG_WITH_THE_GROUP = frozenset({"look"})


def _subsets_keep_their_activity(reading: PromptReading) -> PromptReading:
    """A subset whose own words only react to the robot does its group's activity, with the reaction
    around it: otherwise "some of them" would stand apart, and the group's activity (a queue of a dozen)
    would be done, and claimed, by the rest alone."""
    groups = list(reading.groups)
    for i, group in enumerate(groups):
        parent = group.related_to("subset_of")
        if parent is None or not 0 <= parent < len(groups) or parent == i:
            continue
        whole = groups[parent]
        if group.intent != "robot" or group.robot_interaction not in _ALONG_WITH_THE_GROUP or group.destination \
                or group.via or whole.intent in ("robot", "evacuate") or whole.robot_interaction:
            continue
        groups[i] = replace(group, intent=whole.intent, start=whole.start or group.start,
                            destination=whole.destination, location=whole.location or group.location,
                            via=whole.via, wait_seconds=whole.wait_seconds, waits_first=whole.waits_first,
                            robot_reaction=group.robot_reaction or "Surprised")
    return replace(reading, groups=tuple(groups)) if groups != list(reading.groups) else reading


def _with_people_followed(reading: PromptReading) -> PromptReading:
    added: list[GroupReading] = []
    for group in reading.groups:
        if group.intent != "follow" or not group.follows:
            continue
        wanted = {lemma(w) for w in words(group.follows)} - _NOBODY_IN_PARTICULAR
        if not wanted or any(wanted & ({lemma(w) for w in words(g.who)} | {g.label, lemma(g.label)})
                             for g in (*reading.groups, *added)):
            continue  # a pronoun, or a group the sentence has already
        label = lemma(words(group.follows)[-1])
        # one person ahead of them, along their way; a route-less follow stands where they are
        added.append(GroupReading(group.follows, label, Count("exact", 1, 1, 1),
                                  "walk" if group.destination else "wait", start=group.start,
                                  destination=group.destination,
                                  location=None if group.destination else (group.location or group.start),
                                  via=group.via, text=group.follows))
    return replace(reading, groups=reading.groups + tuple(added)) if added else reading


def robot_places(reading: PromptReading, world: World) -> set[str]:
    """Zones the robot's clause names: a group's place is never taken from them unless its own words say so."""
    robot = reading.robot
    if robot is None:
        return set()
    names = [robot.start, robot.destination, robot.location, *robot.via]
    return {z for z in (world.zone_of_place(n) for n in names if n) if z}


def reconcile(draft: Draft, reading: PromptReading, world: World, default_spawn: str,
              notes: list[str], *, evacuation_field: bool = False) -> list[ReconciledGroup]:
    """Reading groups with honest trees (module doc).

    `evacuation_field`: the preset evacuates along velocity fields, so an evacuating group's plain
    tree follows the field instead of walking to the exit."""
    counts = effective_counts(reading)
    drafts = list(draft.groups)
    unused = list(range(len(drafts)))
    robot_zones = robot_places(reading, world)
    out: list[ReconciledGroup] = []
    for index, group in enumerate(reading.groups):
        count = counts.get(index, 0)
        if count <= 0:
            continue
        pick = _pick_draft(group, drafts, unused, world)
        label = group.label
        added: list[str] = []
        if pick is None:
            tree = tree_for(group, world, evacuation_field)
            notes.append(f"group '{label}': added for '{group.who}' (the model wrote no group for it)")
            spawn = _spawn(group, None, world, default_spawn, tree, robot_zones)
        else:
            unused.remove(pick)
            d = drafts[pick]
            if d.count != count:
                notes.append(f"group '{label}': count {d.count} -> {count} ('{group.who}')")
            if _model_fills(group) and not is_idle(d.tree):
                tree = d.tree  # a sentence that names nobody: the model says what the people do
            else:
                tree, added = honest_tree(d.tree, group, world, notes, label, evacuation_field, robot_zones)
            spawn = _spawn(group, d, world, default_spawn, tree, robot_zones)
        unplaced = not (group.location or group.start or group.destination)
        if _base_intent(group) == "converse" and tree.node == "Wait" and spawn and unplaced:
            # "while two nurses chat": no place named, so they talk where they are (a wait is no talk)
            tree = DraftNode("Converse", {"target": spawn,
                                          "duration": float(group.wait_seconds or CONVERSATION_SECONDS)})
            added.append(f"talks where it starts ({spawn}): the sentence names no place")
        elif _base_intent(group) == "wander" and tree.node == "Wait" and spawn and unplaced:
            # "watching the skaters go round": no place named, so they wander where they are (the report
            # checks a wander there; a wait is no wandering)
            tree = DraftNode("Wander", {"zone": spawn, "duration": float(group.wait_seconds or 0.0)})
            added.append(f"wanders where it starts ({spawn}): the sentence names no place")
        onward = onward_note(group, tree, world)
        if onward is not None:
            added.append(onward)
        behavior = group.robot_reaction or "Regular"
        reacts_only = False
        if group.robot_interaction:
            tree, reacts_only = with_robot_interaction(tree, group)
            tree = cued_as_it_passes(tree, group, reading)  # "looks up as the robot passes the desk"
        guided = False
        if index == guided_index(reading) and not group.robot_interaction and _base_intent(group) in ("evacuate",
                                                                                                      "walk"):
            # "the staff evacuate while the robot guides them to the exit": behind the robot, as people who
            # follow it are, for as long as it drives (planning sets how long), then out on their own
            node, ports = guided_follow(GUIDED_PLACEHOLDER)
            tree, guided = _prepend(DraftNode(node, {**ports}), tree), True
            added.append("follows the robot that guides them, then walks out")
        leader = _leader_index(reading, group)
        if leader is not None and _base_intent(group) == "follow" and not evacuation_field and \
                not any(n.node == "FollowAgent" for n in tree.walk()):
            # "ten tourists follow their guide to the gallery": behind the guide all the way, then there
            tree = _prepend(DraftNode("FollowAgent", {"duration": _following_seconds(world, group),
                                                      "closest_dist": FOLLOW_CLOSEST}), tree)
        if group.together and count > 1 and not any(n.node in ("JoinGroup", "Converse") for n in tree.walk()):
            tree = _prepend(DraftNode("JoinGroup", {}), tree)
            notes.append(f"group '{label}': walks together as the prompt says")
        party = group.count.party_size if group.count.parties and (group.count.party_size or 0) > 1 else None
        out.append(ReconciledGroup(index, label, count, spawn, tree, behavior, party,
                                   PACE_FACTORS.get(group.pace, 1.0), added, reacts_only, leader, guided))
    for i in unused:
        notes.append(f"dropped group '{drafts[i].label}' ({drafts[i].count}): the prompt states no such people")
    out = _behind_their_leader(_at_the_followers_pace(out, reading), world)
    served = one_service_time_per_queue([g.tree for g in out])  # one service time per counter
    return [replace(g, tree=tree) if tree is not g.tree else g for g, tree in zip(out, served)]


GUIDED_PLACEHOLDER = 60.0  # seconds behind the robot until planning knows its drive (guided.guided_seconds)
LEADER_PACE = 0.85  # a guide with a group behind walks at the group's pace, slower than alone


def _at_the_followers_pace(groups: list[ReconciledGroup], reading: PromptReading) -> list[ReconciledGroup]:
    """A group followed by several people ("ten tourists follow their guide") walks a little slower,
    unless its sentence says it hurries, so the ones behind keep up through doors and corners."""
    followed = {g.leader_index for g in groups if g.leader_index is not None and g.count >= 2}
    out = []
    for g in groups:
        r = reading.groups[g.reading_index] if g.reading_index is not None else None
        if g.reading_index in followed and r is not None and r.pace == "normal":
            g = replace(g, speed_factor=round(g.speed_factor * LEADER_PACE, 3),
                        added=g.added + [f"walks at its followers' pace ({LEADER_PACE:g} of its own)"])
        out.append(g)
    return out


FOLLOW_CLOSEST = 1.5  # metres a follower keeps behind the person it follows (FollowAgent's closest_dist)


def _behind_their_leader(groups: list[ReconciledGroup], world: World) -> list[ReconciledGroup]:
    """Followers whose places are their leader's way ("15 kids follow their teacher through the gallery")
    follow for the leader's whole walk, end where the leader ends, then go on to any place of their own
    after it: walking the leader's places again on their own sent them back to the gallery as the
    teacher walked on to the exit."""
    by_reading = {g.reading_index: g for g in groups if g.reading_index is not None}
    out = []
    for g in groups:
        leader = by_reading.get(g.leader_index) if g.leader_index is not None else None
        tree = g.tree
        if leader is not None and tree.node == "Sequence" and any(c.node == "FollowAgent" for c in tree.children):
            ways, own = _goto_targets(leader.tree), _goto_targets(tree)
            # their own places after the leader's (the leader's way, then on to an exit), or none
            onward = own[len(ways):] if own[:len(ways)] == ways else [] if set(own) <= set(ways) else None
            if ways and own and onward is not None:
                seconds = _walk_seconds(world, g.spawn, ways, LEADER_PACE)  # the leader starts among them
                kept = tuple(replace(c, ports={**c.ports, "duration": seconds}) if c.node == "FollowAgent" else c
                             for c in tree.children if c.node != "GoTo")
                legs = tuple(DraftNode("GoTo", {"target": t}) for t in (ways[-1], *onward))
                tree = replace(tree, children=kept + legs)
                g = replace(g, tree=tree)
        out.append(g)
    return out


def _goto_targets(tree: DraftNode) -> list[str]:
    return [str(n.ports["target"]) for n in tree.walk() if n.node == "GoTo" and n.ports.get("target")]


def _walk_seconds(world: World, spawn: str, targets: Sequence[str], pace: float) -> float:
    """About how long a walk from a zone through the targets takes (paths some 1.4 times the straight
    legs, at `pace` m/s, and time to set off), in [20, 900] s."""
    points = [p for p in (_point_of(world, name) for name in (spawn, *targets)) if p is not None]
    metres = 1.4 * sum(math.dist(a, b) for a, b in zip(points, points[1:]))
    return float(min(max(round(metres / pace + 10.0), 20.0), 900.0))


def _leader_index(reading: PromptReading, group: GroupReading) -> int | None:
    """The reading index of the group a following group follows, by the words of `follows`."""
    if not group.follows:
        return None
    follows = {lemma(w) for w in words(group.follows)} - {"a", "an", "the", "their", "his", "her", "its"}
    for i, other in enumerate(reading.groups):
        if other is not group and follows & ({lemma(w) for w in words(other.who)} | {other.label, lemma(other.label)}):
            return i
    return None


def _following_seconds(world: World, group: GroupReading) -> float:
    """How long a follower follows: about the leader's walk from where they start to where they go,
    after which it walks on to the place itself (a minute when the sentence gives no start or place)."""
    places = [p for p in (group.start, group.destination or group.location) if p]
    if len(places) < 2 or any(_point_of(world, p) is None for p in places):
        return 60.0
    return _walk_seconds(world, places[0], places[1:], 1.0)


def _point_of(world: World, name: str) -> tuple[float, float] | None:
    try:
        place = world.find(name)
    except WorldError:
        return None
    if isinstance(place, Zone):
        return place.centroid
    return place.interaction_point if isinstance(place, Entity) else place.position


def _model_fills(group: GroupReading) -> bool:
    """Whether the group is the one a sentence that names nobody is read as ("the cafeteria gets busy"):
    the reader is unsure anyone is there, and the model is asked who is and what they do."""
    named = group.confidence_of("group")
    return named is not None and named.unsure


# ---- matching -------------------------------------------------------------------------------

def _pick_draft(group: GroupReading, drafts: Sequence[DraftGroup], unused: Sequence[int], world: World) -> int | None:
    if not unused:
        return None
    wanted = {group.label, lemma(group.label)} | {lemma(w) for w in words(group.who)}
    places = {world.zone_of_place(p) for p in (group.start, group.destination, group.location) if p}

    def score(i: int) -> float:
        d = drafts[i]
        label = {lemma(w) for w in words(d.label.replace("_", " "))}
        s = 3.0 * len(label & wanted)
        s += sum(1.0 for p in _tree_places(d.tree) if world.zone_of_place(p) in places)
        nodes = {n.node for n in d.tree.walk()}
        if nodes & STATIONARY_NODES.get(group.intent, set()):
            s += 1.0
        return s

    best = max(unused, key=lambda i: (score(i), -i))
    return best if score(best) > 0 else unused[0]


# ---- the honest tree -------------------------------------------------------------------------

def is_idle(tree: DraftNode) -> bool:
    """A tree with no routine action: its agent would stand still unless the robot comes by."""
    return not any(node.node in ROUTINE_NODES for node in tree.walk())


def honest_tree(tree: DraftNode, group: GroupReading, world: World, notes: list[str], label: str,
                evacuation_field: bool = False, robot_zones: set[str] | None = None) -> tuple[DraftNode, list[str]]:
    """The plain tree for the reading, with what the model wrote after doing it kept only when it is a
    pause, a look or wandering where they arrived (returned in words, as "added"). Everything else the
    model wrote that the sentence does not ask for is dropped, with a note."""
    core = with_drafted_service_time(tree_for(group, world, evacuation_field), tree)  # the model's service time
    if is_idle(tree):
        notes.append(f"group '{label}': the model's tree had no action ({_kinds(tree)}); {group.intent} "
                     f"as the prompt says")
        return core, []
    steps = _steps(tree)
    core_steps = _steps(core)
    last = core_steps[-1] if core_steps else None
    # The model's last step that does what the core's last step does (same node kind, same place).
    done_at = -1
    for i, step in enumerate(steps):
        if last is not None and _same_step(world, step, last, group):
            done_at = i
    final_zone = world.zone_of_place(_node_place(last) or "") if last is not None else None
    if done_at >= 0:
        before, after = steps[:done_at], steps[done_at + 1:]
    else:
        # The model never does the core itself: what it does where the core ends (wandering in the
        # ward they are sent to) may follow the core; the rest is dropped.
        after = [s for s in steps if s.node in TRAILING_EXTRAS and _node_place(s) is not None
                 and _trailing_ok(world, s, final_zone, robot_zones or set())]
        before = [s for s in steps if s not in after]
    kept: list[DraftNode] = []
    added: list[str] = []
    dropped = [s for s in before if not any(_same_step(world, s, c, group) for c in core_steps)]
    for step in after:
        if step.node in TRAILING_EXTRAS and _trailing_ok(world, step, final_zone, robot_zones or set()):
            step = _capped(step)
            kept.append(step)
            added.append(_describe(step, final_zone))
        else:
            dropped.append(step)
    dropped = [s for s in dropped if s.node in ROUTINE_NODES]
    if dropped:
        notes.append(f"group '{label}': removed what the sentence does not ask for: "
                     f"{', '.join(_describe(s, None, after=False) for s in dropped)}")
    if done_at < 0 and not dropped:
        notes.append(f"group '{label}': {group.intent} as the prompt says, instead of the model's {_kinds(tree)}")
    if not kept:
        return core, []
    return _append_all(core, kept), added


def _steps(tree: DraftNode) -> list[DraftNode]:
    """The routine leaves of a tree in tick order (control nodes and conditions left out)."""
    return [n for n in tree.walk() if not n.children and NODES.get(n.node) is not None
            and NODES[n.node].category == "action"]


def _same_step(world: World, have: DraftNode, want: DraftNode, group: GroupReading) -> bool:
    if have.node != want.node:
        if not ({have.node, want.node} <= {"Wait", "StopAndWaitTimerAction"}):
            return False
    a, b = _node_place(have), _node_place(want)
    if b is None:
        return a is None or want.node == "FollowVelocityField"
    if a is None:
        return False
    if want.node == "Queue":
        return a == b or _service_in(world, a) == b
    if want.node in ("GoTo", "FollowVelocityField"):
        return _reaches(world, b, [a]) if world.zone_of_place(b) == b else a == b
    return world.zone_of_place(a) == world.zone_of_place(b)


def _trailing_ok(world: World, step: DraftNode, final_zone: str | None, robot_zones: set[str]) -> bool:
    place = _node_place(step)
    if place is None:
        return True
    zone = world.zone_of_place(place)
    return zone is not None and zone == final_zone and zone not in robot_zones


def _capped(step: DraftNode) -> DraftNode:
    ports = dict(step.ports)
    for name in ("duration", "wait_duration"):
        if name in ports:
            try:
                ports[name] = min(float(ports[name]), MAX_TRAILING_WAIT) or MAX_TRAILING_WAIT
            except (TypeError, ValueError):
                ports[name] = MAX_TRAILING_WAIT
    return DraftNode(step.node, ports, step.children)


def _describe(step: DraftNode, zone: str | None, after: bool = True) -> str:
    """A step in words: "waits for 30 s afterwards" (kept after the core), "Wait 30 s" (dropped)."""
    place = _node_place(step)
    value = step.ports.get("duration", step.ports.get("wait_duration"))
    seconds = float(value) if isinstance(value, (int, float)) else 0.0
    duration = f" for {seconds:g} s" if seconds else ""
    if not after:
        return f"{step.node}" + (f"({place})" if place else "") + (f" {seconds:g} s" if seconds else "")
    if step.node in ("Wait", "StopAndWaitTimerAction"):
        return f"waits{duration} afterwards"
    if step.node == "Wander":
        return f"wanders in {place or zone}{duration} afterwards"
    if step.node == "LookAtPoint":
        return "looks around afterwards"
    return f"{step.node}" + (f"({place})" if place else "")


def _base_intent(group: GroupReading) -> str:
    """What the group does apart from reacting to the robot."""
    if group.intent != "robot":
        return group.intent
    routine = routine_of(group)
    if routine is not None:
        return routine  # "queue at the pharmacy and look at the robot": the queue, with the look around it
    if group.destination:
        return "walk"
    return "wait"


def reacts_only(group: GroupReading) -> bool:
    """The group's whole activity is its robot interaction: nowhere to go ("two visitors stare at the
    robot in the lobby" are in the lobby, and what they do there is look at the robot). Followers go
    where the robot goes: "follow the robot through the concourse" names the robot's way, not theirs."""
    if not group.robot_interaction or group.intent != "robot" or routine_of(group) is not None:
        return False
    return group.robot_interaction == "follow" or (not group.destination and not group.via)


def tree_for(group: GroupReading, world: World, evacuation_field: bool = False) -> DraftNode:
    """The plain tree for a reading: where it says, what it says, nothing more."""
    base = _base_intent(group)
    if base == "evacuate" and evacuation_field:
        destination = group.destination
        if destination and not _is_exit(world, destination) and world.zone_of_place(destination):
            # "they hurry along the screens corridor to the foyer": there, the way the sentence says (the
            # field takes everybody to the exit nearest to them, which need not be by the foyer at all)
            return _sequence([DraftNode("GoTo", {"target": v}) for v in group.via]
                             + [DraftNode("GoTo", {"target": destination})])
        exit_name = destination if destination and _is_exit(world, destination) else \
            _nearest_exit(world, group.start, group.avoid)
        return DraftNode("FollowVelocityField", {"exit": exit_name})
    steps: list[DraftNode] = []
    via = [DraftNode("GoTo", {"target": v}) for v in group.via]
    if base == "queue":
        service = _stationary_place(group, world, "queue") or _service_in(world, group.start or "")
        if service is not None:
            delay = wait_before_queuing(group, service)
            # the wait where they start: at its thing or door when the start is one ("by the departure board")
            there = (DraftNode("GoTo", {"target": group.start}),) if delay and group.start and \
                world.zone_of_place(group.start) != group.start else ()
            first = there + (DraftNode("Wait", {"duration": delay}),) if delay else ()
            return DraftNode("Sequence", {}, first + tuple(via) + (DraftNode("GoTo", {"target": service}),
                                                                   DraftNode("Queue", {"service_point": service})))
        base = "wait"
    if base == "converse":
        spot = group.location or group.start or group.destination
        if spot is not None:
            seconds = float(group.wait_seconds or CONVERSATION_SECONDS)
            return _sequence(via + [DraftNode("Converse", {"target": spot, "duration": seconds})]
                             + _onward_steps(group, world))
        base = "wait"
    if base == "wander":
        zone = world.zone_of_place(group.location or group.destination or group.start or "")
        if zone:
            onward_steps = _onward_steps(group, world)
            # wandering with somewhere to go after it ends ("..., then walk to the cafe"): a while, not for ever
            seconds = float(group.wait_seconds or (DEFAULT_WAIT_SECONDS if onward_steps else 0.0))
            return _sequence(via + [DraftNode("Wander", {"zone": zone, "duration": seconds})] + onward_steps)
        base = "wait"
    if base == "wait":
        if reacts_only(group):
            return DraftNode("Wait", {"duration": float(group.wait_seconds or DEFAULT_WAIT_SECONDS)})
        place = group.location or group.destination
        if place is not None:
            steps.append(DraftNode("GoTo", {"target": place}))
        steps.append(DraftNode("Wait", {"duration": float(group.wait_seconds or DEFAULT_WAIT_SECONDS)}))
        # "wait at goods in for 90 seconds and then walk to the canteen": the wait, then the walk
        return _sequence(via + steps + _onward_steps(group, world))
    # walk, evacuate, follow
    destination = group.destination
    if base in ("walk", "evacuate") and destination and _is_exit(world, destination):
        # "leave through the back door", "walk to the exit": out of the building through that door (the
        # field in an emergency, else the planned way to the door and through it)
        return _sequence(via + [DraftNode("FollowVelocityField", {"exit": destination})])
    if destination is None and base == "evacuate":
        destination = _nearest_exit(world, group.start, group.avoid)
    if destination is None:
        if evacuation_field:
            # "get out", "leave" in an emergency: out along the field to the nearest exit
            return _sequence(via + [DraftNode("FollowVelocityField", {"exit": _nearest_exit(world, group.start,
                                                                                             group.avoid)})])
        start = world.zone_of_place(group.start or "")
        onward = _largest_neighbour(world, start) if start and base == "walk" else None
        if onward is not None:
            # "people leave the big meeting room": out of it, into the largest room next to it
            return _sequence(via + [DraftNode("GoTo", {"target": onward})])
        zone = world.zone_of_place(group.start or group.location or "")
        if zone:
            return _sequence(via + [DraftNode("Wander", {"zone": zone, "duration": 0.0})])
        destination = _nearest_exit(world, None, group.avoid)
    return _sequence(via + [DraftNode("GoTo", {"target": destination})])


def _onward_steps(group: GroupReading, world: World) -> list[DraftNode]:
    onward = walks_on_to(group, world)
    if onward is None:
        return []
    return [DraftNode("FollowVelocityField", {"exit": onward}) if _is_exit(world, onward)
            else DraftNode("GoTo", {"target": onward})]


def walks_on_to(group: GroupReading, world: World) -> str | None:
    """Where a group that waits, talks or wanders somewhere goes once that is over: the reading's
    destination when it is somewhere else ("wait in the lobby for two minutes, then go to the pharmacy",
    "chat in the rest room for a minute and then walk to bay 3"; "wait at the pharmacy" and "walk to the
    cafeteria and wait there" read the same place twice and go nowhere after)."""
    if _base_intent(group) not in ("wait", "converse", "wander") or reacts_only(group) or not group.location \
            or not group.destination:
        return None
    if _is_exit(world, group.destination):
        # "... and then leave through the main entrance": out of the building, though the door is the lobby's
        return group.destination if group.destination != group.location else None
    here, there = world.zone_of_place(group.location), world.zone_of_place(group.destination)
    if there is None or here == there:
        return None
    return group.destination


def _largest_neighbour(world: World, zone: str) -> str | None:
    neighbours = sorted({door.leads_to if door.zone == zone else door.zone for door in world.doors_of(zone)}
                        - {zone, "outside"})
    return max(neighbours, key=lambda z: (world.zone(z).area, z)) if neighbours else None


def onward_note(group: GroupReading, tree: DraftNode, world: World) -> str | None:
    """What a group the sentence sends out of a place, but nowhere, is given to do: said as added."""
    start = world.zone_of_place(group.start or "")
    if group.destination or not start or _base_intent(group) != "walk":
        return None
    onward = _largest_neighbour(world, start)
    if onward is not None and any(n.node == "GoTo" and n.ports.get("target") == onward for n in tree.walk()):
        return f"walks on to {onward} (the sentence says where they leave, not where they go)"
    return None


def _sequence(steps: list[DraftNode]) -> DraftNode:
    return steps[0] if len(steps) == 1 else DraftNode("Sequence", {}, tuple(steps))


def with_robot_interaction(tree: DraftNode, group: GroupReading) -> tuple[DraftNode, bool]:
    """(tree, reacts_only): the group's robot interaction done for real (module doc)."""
    interaction = group.robot_interaction or ""
    if reacts_only(group) and interaction == "block" and group.location:
        # "two guards stand in the doorway and block the robot": they hold the place and block it there
        return blocking_at(group.location, float(group.wait_seconds or DEFAULT_WAIT_SECONDS),
                           ROBOT_ACTIVITIES["block"][1]["front_dist"], group.together), True
    glance = glancing(group, float(group.wait_seconds or DEFAULT_WAIT_SECONDS)) if reacts_only(group) else None
    if glance is not None:  # "two cleaners glance at the robot as it passes": once, briefly, when it comes
        return glance, True
    if reacts_only(group) and interaction in ROBOT_ACTIVITIES:
        node, ports = ROBOT_ACTIVITIES[interaction]
        ports = dict(ports)
        for speed in ("max_vel", "runaway_vel"):  # "run up to the robot": at the group's pace
            if speed in ports:
                ports[speed] = round(ports[speed] * PACE_FACTORS.get(group.pace, 1.0), 2)
        place = approach_place(group) if interaction == "approach" else None
        if place is not None:  # "children in the playground approach the robot": there, when it comes
            return approaching_at(place, float(group.wait_seconds or DEFAULT_WAIT_SECONDS), ports,
                                  group.together), True
        activity = DraftNode(node, {**ports})
        if group.together:
            return DraftNode("Sequence", {}, (DraftNode("JoinGroup", {}), activity)), True
        return activity, True
    if group.robot_reaction:
        # "walk to the reading room and avoid the robot": the report checks everyone the robot comes within
        # REACTION_DISTANCE of, so the reaction must fire from there, not only from HuNavSim's nearer trigger
        checked_from = REACTION_DISTANCE.get(interaction) if interaction in _CHECKED_FROM_AFAR else None
        return glance_or_stare(with_reaction(tree, group.robot_reaction, checked_from,
                                             keep_away=interaction == "avoid"), group), False
    return tree, False


# Reactions around a routine whose check counts everyone within its distance (keeping away, looking); the
# others are checked nearer than any trigger (coming up to it, blocking it).
_CHECKED_FROM_AFAR = frozenset({"avoid", "look"})


def with_reaction(tree: DraftNode, behavior: str, checked_from: float | None = None,
                  keep_away: bool = False) -> DraftNode:
    """The tree inside HuNavSim's reaction pattern for `behavior`, unless it already reacts.

    `checked_from`: the report checks the reaction on everyone the robot comes within that many metres of
    (keeping away, looking at it). The reaction then fires on the robot being that near whatever their
    heading (IsRobotClose): HuNavSim's IsRobotVisible misses a robot behind them, which is where it passes
    people standing in a queue or walking away from it, and the check would count them as not reacting."""
    spec = ROBOT_REACTION_DEFAULTS.get(behavior)
    if spec is None or any(n.node in ROBOT_REACTIONS for n in tree.walk()):
        return tree
    node, distance, duration, once = spec
    reach = max(distance, REACTION_TRIGGER.get(behavior, distance))
    cue = DraftNode("IsRobotVisible", {"distance": reach}) if checked_from is None else \
        DraftNode("IsRobotClose", {"threshold": max(reach, checked_from)})
    response = DraftNode(node, {"beh_duration": duration, "only_once": once})
    if keep_away and checked_from is not None:
        # "avoid the robot": out of the distance the report checks and the cue fires at; ScaredNav flees
        # only inside HuNavSim's 3 m and otherwise stands facing it
        response = DraftNode("AvoidRobot", {"safe_distance": max(reach, checked_from),
                                            "runaway_vel": ROBOT_ACTIVITIES["avoid"][1]["runaway_vel"],
                                            "duration": duration})
    reaction = DraftNode("Sequence", {}, (cue, DraftNode("ForceFailure", {}, (response,))))
    return DraftNode("ReactiveFallback", {}, (reaction, tree))


def _append_all(tree: DraftNode, steps: Sequence[DraftNode]) -> DraftNode:
    for step in steps:
        tree = _append(tree, step)
    return tree


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


def _node_place(node: DraftNode | None) -> str | None:
    if node is None:
        return None
    return next((place_at(node, p) for p in _target_ports(node) if p in node.ports), None)


def _tree_places(tree: DraftNode) -> list[str]:
    return [p for node in tree.walk() for p in [_node_place(node)] if p]


def _reaches(world: World, goal: str, places: Sequence[str]) -> bool:
    """Whether a tree visiting `places` goes where the reading sends the group: anywhere in a named
    zone, but to a named door or thing itself."""
    if goal in places:
        return True
    return world.zone_of_place(goal) == goal and any(world.zone_of_place(p) == goal for p in places)


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


def _nearest_exit(world: World, start: str | None, avoid: Sequence[str] = ()) -> str:
    """The exit nearest where they start, never one the sentence says they do not use."""
    exits = [d for d in world.exits() if d.name not in avoid] or world.exits()
    if not exits:
        return str(world.zones[0].name)
    zone = world.zone_of_place(start or "")
    if zone is None:
        return exits[0].name
    cx, cy = world.zone(zone).centroid
    return min(exits, key=lambda d: (math.hypot(d.position[0] - cx, d.position[1] - cy), d.name)).name


def _spawn(group: GroupReading, d: DraftGroup | None, world: World, default: str, tree: DraftNode,
           robot_zones: set[str] | None = None) -> str:
    """Where the group starts: the reading's start; for stationary groups the place they are; else the
    model's spawn unless it is where they are sent or a place of the robot's clause only, then the
    largest room next to where they go."""
    robot_zones = robot_zones or set()
    for name in (group.start, group.location if _base_intent(group) in STATIONARY_NODES else None):
        zone = world.zone_of_place(name or "")
        if zone:
            return zone
    own = {world.zone_of_place(p) for p in (group.destination, group.location, *group.via) if p}
    spawn = world.zone_of_place(d.spawn) if d is not None else None
    if spawn in robot_zones and spawn not in own:
        spawn = None  # the robot's clause is not where this group is
    spawn = spawn or (default if default not in robot_zones or default in own else None)
    first = next((p for p in _tree_places(tree)), None)
    if spawn is None:
        spawn = world.zone_of_place(first or "") or default
    if first is not None and world.zone_of_place(first) == spawn and _base_intent(group) not in STATIONARY_NODES:
        neighbours = sorted({door.leads_to if door.zone == spawn else door.zone for door in world.doors_of(spawn)}
                            - {spawn, "outside"} - (robot_zones - own))
        if neighbours:
            return max(neighbours, key=lambda z: (world.zone(z).area, z))
    return spawn


# ---- the planned grounding report -------------------------------------------------------------

class PlannedGroup(Protocol):
    """A group as the grounding report reads it: post-processing's GroupPlan, or refine's view of a record."""

    @property
    def index(self) -> int: ...
    @property
    def reading_index(self) -> int | None: ...
    @property
    def label(self) -> str: ...
    @property
    def count(self) -> int: ...
    @property
    def spawn(self) -> str: ...
    @property
    def tree(self) -> DraftNode: ...
    @property
    def member_ids(self) -> Sequence[int]: ...


class PlannedAgent(Protocol):
    """An agent as the grounding report reads it: post-processing's AgentPlan, or refine's view of one."""

    @property
    def id(self) -> int: ...
    @property
    def group_index(self) -> int: ...
    @property
    def start(self) -> tuple[float, float]: ...
    @property
    def targets(self) -> Sequence[tuple[str, tuple[float, float]]]: ...
    @property
    def max_vel(self) -> float: ...


def grounding_report(reading: PromptReading, groups: Sequence[PlannedGroup], agents: Sequence[PlannedAgent],
                     world: World, repairs: Sequence[str] = (), *, robot: RobotSpec | None = None,
                     sentence: PromptReading | None = None,
                     walking_speed: float = 1.0, routes: Mapping[int, Sequence[Leg]] | None = None) -> GroundingReport:
    """What the sentence asked, as claims a run can check, per reading group and for the robot.

    `groups` are post-processing's GroupPlans (reading_index, label, count, spawn, tree, behavior,
    member_ids, added); `agents` its AgentPlans (start, targets, max_vel). `robot` is the planned
    RobotSpec; `sentence` the reading before a user's count edits (default `reading`);
    `walking_speed` the preset's normal pace, for slow and fast; `routes` each agent's planned legs
    (`route_time.planned_routes`), which set how long a run needs for each place (without them,
    straight legs times a detour)."""
    sentence = sentence or reading
    reading = with_led_exit(reading, robot, world)  # "leads a family to the exit": the nearest that fits
    by_reading = {g.reading_index: g for g in groups if getattr(g, "reading_index", None) is not None}
    counts = effective_counts(reading)
    asked_counts = effective_counts(sentence)
    members_of = {g.index: [a for a in agents if a.group_index == g.index] for g in groups}
    robot_seconds = _robot_seconds(robot)
    out: list[GroupGrounding] = []
    unhonoured: list[str] = [f"'{p}' is not a place of world '{world.name}'" for p in reading.unknown_places]
    unhonoured += list(reading.notes)
    if not reading.groups and groups:
        guessed = ", ".join(f"{g.label} x{g.count}" for g in groups)
        unhonoured.append(f"no group of people was read from the sentence: the scenario's groups ({guessed}) are "
                          f"the model's guess, placed by word rules")
    questions: list[str] = []
    for index, r in enumerate(reading.groups):
        g = by_reading.get(index)
        unsure = tuple(question(r.who, r, c) for c in r.confidence if c.unsure) + picked_questions(r.who, r)
        questions += unsure
        if g is None:
            if counts.get(index, 0) > 0:
                unhonoured.append(f"'{r.who}' has no group in the scenario")
            continue
        agents_here = members_of.get(g.index, [])
        original = sentence.groups[index] if index < len(sentence.groups) else r
        claims = [_count_claim(original, asked_counts.get(index, 0), counts.get(index, 0), g)]
        edit = ""
        if counts.get(index, 0) != asked_counts.get(index, 0):
            edit = (f"the sentence asked {asked_counts.get(index, 0)} ('{original.who}'); "
                    f"you changed it to {counts.get(index, 0)}")
        claims += _group_claims(r, g, agents_here, routes or {}, world, reading, by_reading, walking_speed,
                                robot_seconds)
        claims = passing_looks(claims, r, reading, world)  # "looks up as the robot passes the desk"
        if index == guided_index(reading) and robot is not None and not any(c.kind == "robot_follow" for c in claims):
            # "the robot guides them to the exit": that they went with it is asked too, and measured
            claims.append(Claim("robot_follow", "go with the robot, which guides them", "walk where the robot leads",
                                distance=REACTION_DISTANCE["follow"], share=0.9, needs_seconds=robot_seconds + 10.0))
            # they leave at the robot's pace: out once it is there, not at their own
            claims = [replace(c, needs_seconds=max(c.needs_seconds, robot_seconds + 20.0))
                      if c.kind in ("evacuate", "reach") and c.needs_seconds is not None else c for c in claims]
        out.append(GroupGrounding(r.who, g.label, tuple(claims), tuple(g.member_ids),
                                  tuple(getattr(g, "added", ()) or ()), unsure, edit))
    asked_robot = reading.robot
    guided = led_exit_of(reading, guided_exit(reading, groups, agents), world)
    led = guided_index(reading)
    out = guided_out_by(out, led, guided, reading.groups[led].who if led is not None else None)
    if asked_robot is not None and guided is not None:
        asked_robot = replace(asked_robot, destination=guided)  # planning sent it where the guided go
    robot_row = _robot_row(asked_robot, robot, world, agents, _passed_groups(reading, groups, world))
    robot_row = beside_claims(robot_row, asked_robot, groups, reading, robot, _robot_seconds(robot))  # not into a queue
    leader_of = next((g for g in reading.groups if g.robot_interaction == "follow" and g.destination), None)
    if asked_robot is None and robot_row is not None and robot is not None and leader_of is not None \
            and getattr(robot, "task", "cross") == "cross" and leader_of.destination:
        # "three students follow the robot from the foyer to the computer lab": planning drove it there
        seconds = _robot_seconds(robot)
        robot_row = replace(robot_row, task="cross", text=leader_of.text,
                            plan=robot_row.plan.replace(" (the sentence asks nothing of it)", ""),
                            claims=(_place_claim("robot_reach", leader_of.destination,
                                                 f"lead them to {leader_of.destination}", world, 1,
                                                 1.3 * seconds + 10.0),))
    if robot_row is not None:
        questions += robot_row.unsure
    out = with_shared_queues(out, queue_service_times(g.tree for g in groups))  # a shared queue waits for them too
    return with_run_length(GroundingReport(reading.prompt, tuple(out), tuple(dict.fromkeys(unhonoured)),
                                           tuple(repairs), tuple(reading.corrections), robot_row,
                                           tuple(dict.fromkeys(questions))))


def reading_questions(reading: PromptReading) -> list[str]:
    """Every question about the fields the reader was unsure of, groups first, then the robot."""
    out = [question(g.who, g, c) for g in reading.groups for c in g.confidence if c.unsure]
    if reading.robot is not None:
        out += [question("the robot", reading.robot, c) for c in reading.robot.confidence if c.unsure]
    return list(dict.fromkeys(out))


def question(who: str, subject: GroupReading | RobotReading, confidence: FieldConfidence) -> str:
    """The question the app asks (and `--strict` refuses with) for an unsure field."""
    value = getattr(subject, confidence.field, None) if confidence.field != "group" else who
    if hasattr(value, "value"):
        value = getattr(value, "value")
    choices = list(dict.fromkeys([str(v) for v in (value,) if v not in (None, "")]
                                 + [str(a) for a in confidence.alternatives]))
    what = f"'{who}' {confidence.field}" if confidence.field != "group" else f"'{who}'"
    text = f"{what}: {' or '.join(choices)}?" if choices else f"{what}?"
    return text + (f" ({confidence.reason})" if confidence.reason else "")


def _count_claim(original: GroupReading, asked: int, wanted: int, g: PlannedGroup) -> Claim:
    c = original.count
    text = str(c.value) if c.kind == "exact" else f"{c.value} ({c.kind} {c.low}-{c.high})"
    if c.parties:
        text += f", {c.parties} x {c.party_size}"
    if asked != c.value:
        text += f"; {asked} of its own"
    plan = f"{g.count} {'person' if g.count == 1 else 'people'}"
    if wanted != asked:
        plan += f" (edited from {asked})"
    if g.count != wanted:
        return Claim("count", text, plan, FAILS, f"the scenario has {g.count}, not {wanted}")
    return Claim("count", text, plan)


def _group_claims(r: GroupReading, g: PlannedGroup, agents: Sequence[PlannedAgent], routes: Mapping[int, Sequence[Leg]],
                  world: World, reading: PromptReading, by_reading: dict[int | None, PlannedGroup],
                  walking_speed: float, robot_seconds: float) -> list[Claim]:
    claims: list[Claim] = []
    n = max(1, g.count)
    speed = min((a.max_vel for a in agents), default=walking_speed) or walking_speed
    timing = _Timing(agents, routes, world, speed)
    if r.start:
        zone = world.zone_of_place(r.start)
        spread = getattr(g, "spawn_zones", None)
        plan = f"across the building ({len(spread)} zones)" if spread else f"start in {g.spawn}"
        ok = not spread and zone == g.spawn
        claims.append(Claim("start", r.start, plan, PLANNED if ok else FAILS,
                            "" if ok else f"they start in {g.spawn if not spread else 'several zones'}", zone=zone,
                            place=r.start, share=1.0))
    tree_nodes = {node.node for node in g.tree.walk()}
    base = _base_intent(r)
    for v in () if reacts_only(r) else r.via:
        claims.append(_place_claim("reach", v, f"walk through {v}", world, n, timing.eta(v)))
    if r.robot_interaction:
        claims.append(_reaction_claim(r, g, robot_seconds, world))
        if reacts_only(r):
            base = "none"
            if r.robot_interaction == "follow" and r.destination:
                # "follow the robot from the foyer to the computer lab": they arrive there behind it
                claims.append(_place_claim("reach", r.destination, f"follow the robot to {r.destination}", world,
                                           n, robot_seconds + timing.eta(r.destination)))
            zone = world.zone_of_place(r.location or "")
            if zone and not r.start:
                # "a cleaner stands in the robot's way in the corridor": that is where they are at first
                claims.append(Claim("start", r.location or zone, f"start in {g.spawn}", PLANNED if zone == g.spawn
                                    else FAILS, "" if zone == g.spawn else f"they start in {g.spawn}", zone=zone,
                                    place=r.location, share=1.0))
    if base == "walk" and _is_exit(world, r.destination):
        base = "evacuate"  # walking out through an exit door is leaving the building through it
    if base == "walk" or base == "follow":
        if r.destination:
            claim = _place_claim("reach", r.destination, f"walk to {r.destination}", world, n,
                                 timing.eta(r.destination))
            if not _reaches(world, r.destination, _tree_places(g.tree)):
                claim = Claim(claim.kind, claim.asked, claim.plan, FAILS, "the trees never go there", zone=claim.zone,
                              place=claim.place, point=claim.point, radius=claim.radius)
            claims.append(claim)
        elif "FollowVelocityField" in tree_nodes:
            shunned = [a for a in r.avoid if _is_exit(world, a)]
            claims.append(Claim("evacuate", "any exit but " + ", ".join(shunned) if shunned else
                                "walk out (no destination named)", "follow the evacuation field to the nearest exit",
                                exits=tuple(d.name for d in world.exits() if d.name not in shunned) if shunned else (),
                                needs_seconds=timing.evacuation_eta(n)))
        elif r.start and world.zone_of_place(r.start):
            # "people leave the big meeting room": out of it, wherever to
            zone = world.zone_of_place(r.start)
            claims.append(Claim("leave", r.start, "walk out" if "Wander" not in tree_nodes else f"wander in {zone}",
                                zone=zone, place=r.start, needs_seconds=timing.eta(None) + 20.0))
        else:
            claims.append(Claim("move", "walk (no destination named)",
                                "wander where they are" if "Wander" in tree_nodes else "walk",
                                needs_seconds=20.0))
        if base == "follow" and r.follows:
            leader = _leader(reading, r, by_reading)
            if leader is not None:
                # a crowd behind one guide stands round them: the ring widens with its size
                claims.append(Claim("follow_person", f"follow {r.follows}", f"walk with {leader.label}",
                                    partners=tuple(leader.member_ids), distance=round(3.0 + 0.5 * math.sqrt(n - 1), 1),
                                    share=0.9))
    elif base == "evacuate":
        exits: tuple[str, ...] = (r.destination,) if r.destination and _is_exit(world, r.destination) else ()
        unsure = r.confidence_of("destination")
        if exits and unsure is not None and unsure.unsure:
            # the reader could not tell which exit ("the nearest exit"): any it weighed
            exits = tuple(dict.fromkeys(e for e in (*exits, *unsure.alternatives) if _is_exit(world, e)))
        if r.destination and not exits:
            claims.append(_place_claim("reach", r.destination, f"evacuate to {r.destination}", world, n,
                                       timing.eta(r.destination)))
        else:
            shunned = [a for a in r.avoid if _is_exit(world, a)]
            if shunned and not exits:
                # "..., not the main doors": any exit but those
                exits = tuple(d.name for d in world.exits() if d.name not in shunned)
            asked = "any exit but " + ", ".join(shunned) if shunned and not r.destination else \
                "any of " + ", ".join(exits) if len(exits) > 1 else r.destination or "any exit"
            claims.append(Claim("evacuate", asked,
                                "follow the evacuation field" if "FollowVelocityField" in tree_nodes else "walk out",
                                exits=exits, needs_seconds=timing.evacuation_eta(n)))
    elif base == "queue":
        service = next((place_of(node, "service_point") for node in g.tree.walk() if node.node == "Queue"), None)
        place = r.location or r.destination or service
        if service is None:
            claims.append(Claim("queue", place or "-", "no queue in the trees", FAILS, "the trees never queue"))
        else:
            service_time = max((service_time_of(node) for node in g.tree.walk() if node.node == "Queue"),
                               default=default_service_time())
            delay = wait_before_queuing(r, service)
            if delay and r.start:
                # "wait by the kiosk for a minute, then queue": the wait where they start, then joins after it
                claims.append(replace_seconds(_place_claim("stay", r.start, f"wait at {r.start} {delay:g} s", world,
                                                           n, timing.eta(r.start) + delay, stay=True), delay))
            later = f" after {delay:g} s" if delay else ""
            claims.append(Claim("queue", (place or service) + later, f"queue at {service}{later}", place=service,
                                zone=world.zone_of_place(service), seconds=delay,
                                needs_seconds=timing.eta(service) + service_time + 15.0 + (delay or 0.0)))
    elif base == "wait":
        place = r.location or r.destination
        seconds = float(r.wait_seconds) if r.wait_seconds else None
        if place:
            claim = _place_claim("stay", place, f"wait at {place}" + (f" {seconds:g} s" if seconds else ""), world,
                                 n, timing.eta(place) + (seconds or 0.0), stay=True)
        else:
            claim = Claim("stay", "where they are", f"wait in {g.spawn}", zone=g.spawn, place=g.spawn,
                          needs_seconds=(seconds or 10.0) + 5.0)
        claims.append(replace_seconds(claim, seconds))
        claims.extend(_onward_claims(r, g, world, timing, n, seconds or DEFAULT_WAIT_SECONDS))
    elif base == "wander":
        zone = world.zone_of_place(r.location or r.destination or r.start or "") or g.spawn
        onward = _onward_claims(r, g, world, timing, n, float(r.wait_seconds or DEFAULT_WAIT_SECONDS))
        # a wander with somewhere to go after it lasts a while (the tree's), judged over that while
        seconds = float(r.wait_seconds) if r.wait_seconds else DEFAULT_WAIT_SECONDS if onward else None
        claims.append(replace_seconds(Claim("wander", zone, f"wander in {zone}", zone=zone, place=zone,
                                            needs_seconds=timing.eta(zone) + max(20.0, seconds or 0.0)), seconds))
        claims.extend(onward)
    elif base == "converse":
        spot = r.location or r.start or r.destination
        zone = world.zone_of_place(spot or "") or g.spawn
        partners = tuple(g.member_ids)
        if "Converse" not in tree_nodes and "ConversationFormation" not in tree_nodes:
            claims.append(Claim("converse", "talk together", "no conversation in the trees", FAILS,
                                "the trees never talk"))
        elif g.count < 2:
            claims.append(Claim("converse", "talk", "one person alone", FAILS, "a conversation needs two people"))
        else:
            claims.append(Claim("converse", "talk together" + (f" in {zone}" if zone else ""),
                                f"a conversation circle in {zone}", zone=zone, place=spot, partners=partners,
                                needs_seconds=timing.eta(spot or zone) + 15.0))
        claims.extend(_onward_claims(r, g, world, timing, n, float(r.wait_seconds or CONVERSATION_SECONDS)))
    if r.pace in ("slow", "fast"):
        normal = walking_speed
        low, high = (0.2, round(0.85 * normal, 2)) if r.pace == "slow" else (round(1.15 * normal, 2), 3.0)
        # "run up to the robot": the pace on the way to it (once there they keep the robot's)
        reach = REACTION_DISTANCE[r.robot_interaction] + 0.5 if r.robot_interaction in ("approach", "follow") \
            else None
        claims.append(Claim("pace", r.pace, f"desired speed {speed:.2f} m/s" + (" on the way to the robot" if reach
                                                                                 else ""),
                            low=low, high=high, distance=reach, needs_seconds=15.0))
    for name in places_kept_out(world, r):
        # "..., avoiding the lifts": never there, all the run long
        claims.append(_keep_out_claim(world, name, g.count))
    return stay_claims(claims, reaction=r.robot_interaction, place=r.location or r.start, spawn=g.spawn, world=world,
                       eta=timing.eta, seconds=float(r.wait_seconds) if r.wait_seconds else None,
                       talks=base == "converse", goes_on=walks_on_to(r, world) is not None or bool(r.destination))


def _onward_claims(r: GroupReading, g: PlannedGroup, world: World, timing: _Timing, n: int,
                   waited: float) -> list[Claim]:
    """Where the group goes once its wait, talk or wander is over ("..., then walk to bay 3"): reached
    after it, or out through the exit it names."""
    onward = walks_on_to(r, world)
    if onward is None:
        return []
    if _is_exit(world, onward):
        return [Claim("evacuate", onward, f"then leave through {onward}", exits=(onward,),
                      needs_seconds=timing.evacuation_eta(n) + waited)]
    claim = _place_claim("reach", onward, f"then walk to {onward}", world, n, timing.eta(onward) + waited)
    if not _reaches(world, onward, _tree_places(g.tree)):
        claim = Claim(claim.kind, claim.asked, claim.plan, FAILS, "the trees never go there",
                      zone=claim.zone, place=claim.place, point=claim.point, radius=claim.radius)
    # the walk comes after the wait: an arrival before `waited` seconds is a doorway's margin, not the walk
    return [replace(claim, seconds=waited) if claim.status != FAILS else claim]


def places_kept_out(world: World, group: GroupReading) -> tuple[str, ...]:
    """The places but exits a group's sentence says it keeps out of, when it neither starts, waits, passes
    nor ends there ("walk to the café, avoiding the lifts"); an exit ruled out is the exit choice's."""
    exits = {d.name for d in world.exits()}
    own = {world.zone_of_place(p) for p in (group.start, group.destination, group.location, *group.via) if p}
    return tuple(a for a in group.avoid if a not in exits and a not in own)


def _keep_out_claim(world: World, name: str, members: int) -> Claim:
    if isinstance(world.find(name), Zone):
        return Claim("keep_out", name, f"plan round {name}", zone=name, place=name, share=1.0, needs_seconds=30.0)
    point = _point_of(world, name) or (0.0, 0.0)  # a door or a thing: the reading named it, so it is found
    return Claim("keep_out", name, f"plan round {name}", place=name, point=(round(point[0], 3), round(point[1], 3)),
                 radius=1.0, share=1.0, needs_seconds=30.0)


def replace_seconds(claim: Claim, seconds: float | None) -> Claim:
    if seconds is None:
        return claim
    return Claim(claim.kind, claim.asked + f" for {seconds:g} s", claim.plan, claim.status, claim.evidence,
                 claim.needs_seconds, claim.zone, claim.place, claim.point, claim.radius, seconds=seconds,
                 share=claim.share)


def _reaction_claim(r: GroupReading, g: PlannedGroup, robot_seconds: float, world: World | None = None) -> Claim:
    interaction = r.robot_interaction or ""
    kind = f"robot_{interaction}"
    nodes = [node.node for node in g.tree.walk() if node.node in ROBOT_ACTIVITY_NODES or node.node in ROBOT_REACTIONS]
    plan = ", ".join(dict.fromkeys(nodes)) or "no reaction in the trees"
    asked = f"{interaction} at the robot" if interaction == "look" else f"{interaction} the robot"
    if not nodes:
        return Claim(kind, asked, plan, FAILS, "the trees never react to the robot")
    share = 0.5 if interaction == "block" else 0.9
    claim = Claim(kind, asked, plan, distance=REACTION_DISTANCE.get(interaction, 3.0), share=share,
                  needs_seconds=robot_seconds + 10.0)
    claim = look_claim(claim, r) if interaction == "look" else claim  # a glance or a stare
    claim = at_the_approached_place(claim, r, g, world) if interaction == "approach" and world is not None \
        and reacts_only(r) else claim
    return at_the_blocked_place(claim, r, g, world) if interaction == "block" and world is not None else claim


ROBOT_ACTIVITY_NODES = frozenset(node for node, _ in ROBOT_ACTIVITIES.values())


def _place_claim(kind: str, place: str, plan: str, world: World, n: int, eta: float, stay: bool = False) -> Claim:
    """A claim about being at a place: a zone's polygon, or near a door's or thing's point."""
    try:
        obj = world.find(place)
    except Exception:
        return Claim(kind, place, plan, FAILS, f"'{place}' is not a place of the world")
    if isinstance(obj, Entity):
        point = obj.interaction_point
    elif isinstance(obj, Door):
        point = obj.inward_point(0.6)
    else:
        return Claim(kind, place, plan, zone=obj.name, place=place, needs_seconds=round(eta, 1))
    # people sent to one point stand beside each other: the more of them, the wider the spot
    radius = (2.0 if stay else 1.0) + 0.5 * math.sqrt(n)
    radius = claim_radius(obj, radius) if isinstance(obj, Door) else radius  # beside an exit's opening (exit_post)
    return Claim(kind, place, plan, place=place, point=(round(float(point[0]), 3), round(float(point[1]), 3)),
                 radius=round(radius, 2), needs_seconds=round(eta, 1))


class _Timing:
    """How long a group needs to get to its places: the slowest member's route at the group's pace."""

    def __init__(self, agents: Sequence[PlannedAgent], routes: Mapping[int, Sequence[Leg]], world: World,
                 speed: float) -> None:
        self.agents, self.routes, self.world, self.speed = agents, routes, world, max(speed, 0.1)

    def eta(self, place: str | None) -> float:
        """Seconds the slowest member needs to get to `place` (its whole route for None), plus slack."""
        if not self.agents:
            return 30.0
        longest = max(self._route_metres(a, place) for a in self.agents)
        return round(longest / self.speed + 10.0, 1)

    def evacuation_eta(self, n: int) -> float:
        exits = self.world.exits()
        if not self.agents or not exits:
            return 60.0
        if all(self.routes.get(a.id) for a in self.agents):
            # each evacuee's planned way out (its field's path, or its waypoints to the door)
            longest = max(RouteWalk(a.start, self.routes[a.id]).to_end() for a in self.agents)
        else:
            longest = 1.8 * max(min(math.dist(a.start, d.position) for d in exits) for a in self.agents)
        # the last of n people through a door about 1 person/s/m wide
        flow = sum(d.width for d in exits) or 1.0
        return round(longest / self.speed + n / flow + 10.0, 1)

    def _route_metres(self, agent: PlannedAgent, upto: str | None) -> float:
        """Weighted metres from the agent's start along its legs, up to its first target at `upto`
        (`route_time.Leg.weighted`: a planned path with a margin, a straight leg with a detour)."""
        world = self.world
        walk = RouteWalk(agent.start, self.routes.get(agent.id, ()))
        zone = world.zone_of_place(upto or "") if upto else None
        for name, point in getattr(agent, "targets", ()):
            walk.to(point)
            if upto is not None and (name == upto or (zone is not None and world.zone_of_place(name) == zone
                                                      and world.zone_of_place(upto) == upto)):
                return walk.metres
        if upto is None:
            return walk.to_end()
        if zone is not None:
            # not among the targets: as the crow flies to the zone's centre
            try:
                return walk.straight_to(world.zone(zone).centroid)
            except Exception:
                return walk.metres
        return walk.metres


def _robot_seconds(robot: RobotSpec | None) -> float:
    """How long the robot takes along its planned path (the time a reaction to it needs at most)."""
    if robot is None or not getattr(robot, "path", None):
        return 30.0
    path = list(robot.path)
    length = sum(math.dist(a, b) for a, b in zip(path, path[1:]))
    return round(length / max(float(robot.max_vel), 0.1), 1)


def _leader(reading: PromptReading, r: GroupReading, by_reading: dict[int | None, PlannedGroup]) -> PlannedGroup | None:
    index = _leader_index(reading, r)
    return by_reading.get(index) if index is not None else None


# ---- the robot's row --------------------------------------------------------------------------

# How near the robot must come to people it is asked to drive through ("through the queue"), in metres.
PASSING_DISTANCE = 2.0


@dataclass(frozen=True)
class _StayingGroup:
    label: str
    zone: str
    members: tuple[int, ...]
    queue_at: str | None  # the service point of a group that queues there


def _passed_groups(reading: PromptReading, groups: Sequence[PlannedGroup], world: World) -> list[_StayingGroup]:
    """The planned groups the robot is asked to pass where they stay (`robot_passing.passed_zones`)."""
    zones = passed_zones(reading, world)
    out: list[_StayingGroup] = []
    for g in groups:
        zone = zones.get(g.reading_index) if g.reading_index is not None else None
        if zone is None or g.reading_index is None:
            continue
        service = next((place_of(node, "service_point") for node in g.tree.walk() if node.node == "Queue"), None)
        queues = "queue" in (reading.groups[g.reading_index].intent, routine_of(reading.groups[g.reading_index]))
        out.append(_StayingGroup(g.label, zone, tuple(g.member_ids), service if queues else None))
    return out


def _robot_row(asked: RobotReading | None, robot: RobotSpec | None, world: World,
               agents: Sequence[PlannedAgent], staying: Sequence[_StayingGroup] = ()) -> RobotGrounding | None:
    if robot is None:
        if asked is None:
            return None
        return RobotGrounding(asked.task, asked.text, (Claim(f"robot_{asked.task}", asked.task, "no robot",
                                                             FAILS, "the scenario has no robot"),))
    path = list(getattr(robot, "path", ()) or (robot.start, robot.goal))
    length = sum(math.dist(a, b) for a, b in zip(path, path[1:]))
    seconds = length / max(float(robot.max_vel), 0.1)
    task = getattr(robot, "task", "cross")
    follows = tuple(getattr(robot, "follows", ()) or ())
    if task == "wait":
        plan = f"wait at ({robot.start[0]:.1f}, {robot.start[1]:.1f})"
    elif task == "follow":
        # its way is planned as it goes, behind the people it follows
        plan = (f"follow agent{'s' if len(follows) != 1 else ''} {', '.join(map(str, follows)) or '(nobody)'} "
                f"from ({robot.start[0]:.1f}, {robot.start[1]:.1f})")
    else:
        plan = (f"{task} from ({robot.start[0]:.1f}, {robot.start[1]:.1f}) to ({robot.goal[0]:.1f}, "
                f"{robot.goal[1]:.1f}), {length:.0f} m")
    if asked is None:
        return RobotGrounding("pass", "", (), plan + " (the sentence asks nothing of it)")
    unsure = tuple(question("the robot", asked, c) for c in asked.confidence if c.unsure) + \
        picked_questions("the robot", asked)
    claims: list[Claim] = []
    errand = robot_errand(asked) if robot.stops or task == "cross" else None
    if errand is not None and (robot.stops or errand.pickup is None):  # to the pick-up first, then the drop-off
        claims.extend(errand_claims(errand, robot, world, seconds))
    elif asked.task in ("cross", "patrol"):
        if asked.start:
            claims.append(_robot_start_claim(asked.start, robot, world))
        for v in asked.via:
            claim = _place_claim("robot_via", v, f"drive through {v}", world, 1, seconds * 1.3 + 10.0)
            claims.append(claim)
            zone = world.zone_of_place(v)
            for group in (g for g in staying if g.zone == zone):
                # "drives through the queue", "threads its way through the crowd of visitors in the waiting
                # room": through the people there, while they are there, not only through the room
                claims.append(past_or_through(Claim(  # "past them": beside them, one claim (past_queue.py)
                    "robot_passes", f"through the {group.label}s in {zone}", f"drive through {zone} past them",
                    zone=zone, place=group.queue_at, partners=group.members, distance=PASSING_DISTANCE,
                    needs_seconds=round(seconds * 1.3 + 10.0, 1)), asked, group.label))
        if asked.destination:
            kind = "robot_patrol" if asked.task == "patrol" else "robot_reach"
            plan_text = f"{'patrol to' if kind == 'robot_patrol' else 'drive to'} {asked.destination}"
            claim = _place_claim(kind, asked.destination, plan_text, world, 1,
                                 (2.6 if kind == "robot_patrol" else 1.3) * seconds + 10.0)
            claims.append(claim)
        elif asked.task == "patrol" and asked.location and asked.via and world.zone_of_place(asked.location):
            # "patrols between the entrance and the reading tables": out to the place it names and back,
            # checked at that place, never at wherever its planned round happens to end
            claims.append(_place_claim("robot_patrol", asked.location, f"patrol to {asked.location} and back",
                                       world, 1, 2.6 * seconds + 10.0))
        elif asked.task == "patrol":
            claims.append(Claim("robot_patrol", asked.location or "its round", "drive its round and back",
                                point=(round(robot.goal[0], 3), round(robot.goal[1], 3)), radius=1.0,
                                needs_seconds=round(2.6 * seconds + 10.0, 1)))
    elif asked.task == "wait":
        where = asked.location or asked.destination or asked.start
        wait = asked.wait_seconds
        # "waits at the cloakroom for two minutes": the asked seconds there are the claim, so a shorter run
        # cannot earn it (the probe judges the window from its arrival, as a group's stay)
        claim = Claim("robot_stay", where or "where it is", f"wait at ({robot.start[0]:.1f}, "
                      f"{robot.start[1]:.1f})", point=(round(robot.start[0], 3), round(robot.start[1], 3)),
                      radius=1.0, place=where, needs_seconds=(wait or 5.0) + 5.0)
        claims.append(replace_seconds(claim, wait))
    elif asked.task == "follow":
        follows = tuple(getattr(robot, "follows", ()) or ())
        if follows:
            claims.append(Claim("robot_follow_person", "follow " + (asked.follows or asked.text or "someone"),
                                f"follow agents {', '.join(map(str, follows))}", partners=follows, distance=3.0,
                                needs_seconds=30.0))
        else:
            claims.append(Claim("robot_follow_person", "follow someone", "nobody to follow", FAILS,
                                "no group of the sentence is the one the robot follows"))
    for name in robot_kept_out(world, asked):
        # "..., avoiding the cafeteria": never there, measured on its trajectory (✗ now if the plan goes in)
        claims.append(robot_keep_out_claim(_keep_out_claim(world, name, 1), world, path, seconds))
    return RobotGrounding(asked.task, asked.text, tuple(claims), plan, unsure)


def _robot_start_claim(start: str, robot: RobotSpec, world: World) -> Claim:
    zone = world.zone_of_place(start)
    actual = world.zone_at(robot.start[0], robot.start[1])
    ok = zone is not None and actual is not None and actual.name == zone
    return Claim("robot_reach", f"start in {start}", f"start at ({robot.start[0]:.1f}, {robot.start[1]:.1f})",
                 PLANNED if ok else FAILS, "" if ok else f"it starts in {actual.name if actual else 'no zone'}",
                 zone=zone, place=start, needs_seconds=0.0)
