"""A generated scenario read back as its groups, for refinement (generation/refine.py).

    scene = scene_of(result, world)        # a GenerationResult, fresh or loaded from a bundle
    scene.groups[0].reading, scene.groups[0].members, scene.groups[0].tree

Each group of generation.json's "groups" becomes a `SceneGroup`: the reading it realises, its
members, its tree before ids and points (draft form) and the sentence that asked for it. Bundles
written before the records carried the reading and the tree are read too: the reading comes from
the report's reading (group i is the i-th reading group with people of its own, as post-processing
orders them) and the tree from the first member's XML.

`placed_scene` gives post-processing (`PlacedScene`) what the groups a refinement keeps occupy: ids,
social groups, start points, the points they are sent to, the goal table and people per zone.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, cast

from grove_tui.bt.format.document import TreeDocument, TreeElement
from grove_tui.bt.format.manifest import NODES
from grove_tui.errors import BundleError
from grove_tui.generation.draft import DraftNode, DraftValue, written_ports
from grove_tui.generation.pipeline import GenerationResult, GroupRecord, own_reading
from grove_tui.jsontypes import Parsed
from grove_tui.generation.postprocess import NAVIGATING_EXTRA, KeptMembers, PlacedScene
from grove_tui.language.model import Count, GroupReading, PromptReading, effective_counts
from grove_tui.scenario.model import AgentSpec, Scenario
from grove_tui.world.model import World

Point = tuple[float, float]

# What a tree does, for a group with no reading (a bundle of the older word rules): its first routine node.
_NODE_INTENTS = {"Queue": "queue", "Converse": "converse", "ConversationFormation": "converse", "Wander": "wander",
                 "FollowVelocityField": "evacuate", "FollowAgent": "follow", "Wait": "wait", "GoTo": "walk"}


@dataclass(frozen=True)
class SceneGroup:
    index: int  # position in generation.json's "groups"
    label: str
    count: int
    reading: GroupReading  # what the group is asked to do; its count is the group's people
    members: tuple[int, ...]
    spawn: str
    tree: DraftNode
    behavior: str
    record: GroupRecord  # its generation.json record, kept as it is while the group is untouched
    asked_by: int = 0  # the sentence that asked for it: 0 the first, k the k-th follow-up
    changed_by: tuple[int, ...] = ()  # the follow-ups that changed it


@dataclass
class Scene:
    result: GenerationResult
    world: World
    groups: tuple[SceneGroup, ...]

    @property
    def scenario(self) -> Scenario:
        return self.result.scenario

    @property
    def report(self) -> dict[str, Any]:  # Any: generation.json (GenerationResult.report)
        return self.result.report

    @property
    def steps(self) -> int:
        """Follow-ups applied so far."""
        return len(self.report.get("history", ()))

    @property
    def sentences(self) -> list[str]:
        """Sentence 0 (the prompt), then every follow-up."""
        return [str(self.report.get("prompt", self.scenario.prompt))] + \
            [str(step.get("sentence", "")) for step in self.report.get("history", ())]

    def agents_of(self, group: SceneGroup) -> list[AgentSpec]:
        members = set(group.members)
        return [a for a in self.scenario.agents if a.id in members]

    def document(self, agent: AgentSpec) -> TreeDocument:
        """The agent's tree, as the result holds it (read it; planning edits a copy)."""
        return self.result.trees[agent.tree]


def scene_of(result: GenerationResult, world: World) -> Scene:
    """The scenario's groups as refinement reads them (module doc); BundleError when it has none."""
    records = list(result.report.get("groups") or ())
    if not records:
        raise BundleError("this scenario has no group records in generation.json, so its groups cannot be "
                          "edited; regenerate it with this version of GROVE")
    try:
        return _scene(result, world, records)
    except (KeyError, TypeError, ValueError, AttributeError) as exc:  # a record edited by hand into nonsense
        raise BundleError(f"generation.json \"groups\" cannot be read as the scenario's groups: {exc!r}",
                          hint="regenerate the scenario, or restore its generation.json") from None


def _scene(result: GenerationResult, world: World, records: list[GroupRecord]) -> Scene:
    fallback = _readings_by_position(result.report, records)
    by_id = {a.id: a for a in result.scenario.agents}
    groups = []
    for index, record in enumerate(records):
        members = tuple(int(m) for m in record.get("members", ()))
        missing = [m for m in members if m not in by_id]
        if missing:
            raise BundleError(f"generation.json group '{record.get('label')}' names agents {missing[:5]} that "
                              f"scenario.yaml does not have")
        tree = _tree_of(record, result, [by_id[m] for m in members])
        reading = (GroupReading.from_dict(record["reading"]) if record.get("reading") else fallback.get(index)) or \
            _reading_of_tree(record, tree)
        groups.append(SceneGroup(index, str(record["label"]), int(record["count"]), reading, members,
                                 str(record.get("spawn", "")), tree, str(record.get("behavior", "Regular")),
                                 cast(GroupRecord, dict(record)), int(record.get("asked_by", 0)),
                                 tuple(int(c) for c in record.get("changed_by", ()))))
    return Scene(result, world, tuple(groups))


def _readings_by_position(report: Parsed, records: Sequence[GroupRecord]) -> dict[int, GroupReading]:
    """Record index -> reading, for records that do not carry theirs: result group i realises the i-th
    reading group with people of its own (PlanInputs.with_counts holds the same order)."""
    data = report.get("reading")
    if not data or not data.get("groups"):
        return {}
    reading = PromptReading.from_dict(data)
    order = sorted(effective_counts(reading))
    return {i: own_reading(reading.groups[r], int(records[i]["count"])) for i, r in enumerate(order)
            if i < len(records)}


def _reading_of_tree(record: GroupRecord, tree: DraftNode) -> GroupReading:
    """A reading for a group no sentence was read for: its label, count and what its tree does."""
    label, count = str(record["label"]), int(record["count"])
    intent = next((_NODE_INTENTS[n.node] for n in tree.walk() if n.node in _NODE_INTENTS), "walk")
    place = next((v for n in tree.walk() for v in [_first_place(n)] if v), None)
    stationary = intent in ("queue", "converse", "wander", "wait")
    return GroupReading(label, label, Count("exact", count, count, count), intent,
                        location=place if stationary else None, destination=None if stationary else place,
                        text=label)


def _first_place(node: DraftNode) -> str | None:
    spec = NODES.get(node.node)
    for port in spec.ports if spec is not None else ():
        if port.type == "target" and port.name in node.ports:
            return str(node.ports[port.name])
    return None


def _tree_of(record: GroupRecord, result: GenerationResult, agents: Sequence[AgentSpec]) -> DraftNode:
    if record.get("tree"):
        return node_from_dict(record["tree"])
    if not agents:
        raise BundleError(f"generation.json group '{record.get('label')}' has no members and no tree")
    first = agents[0]
    return draft_from_document(result.trees[first.tree])


def node_from_dict(data: Parsed) -> DraftNode:
    """The inverse of draft.node_to_dict."""
    ports = {k: v for k, v in data.items() if k not in ("node", "children")}
    return DraftNode(str(data["node"]), ports, tuple(node_from_dict(c) for c in data.get("children") or ()))


def draft_from_document(document: TreeDocument) -> DraftNode:
    """An agent's tree back in draft form: node types and the ports a model writes, without the ids,
    points and waypoints post-processing and planning filled in."""
    return _draft_node(document.main)


def _draft_node(element: TreeElement) -> DraftNode:
    spec = NODES.get(element.id)
    ports: dict[str, DraftValue] = {}
    for port in written_ports(spec) if spec is not None else ():
        text = element.get(port.name)
        if text is not None:
            ports[port.name] = _value(port.type, text)
    return DraftNode(element.id, ports, tuple(_draft_node(c) for c in element.children))


def _value(kind: str, text: str) -> DraftValue:
    try:
        if kind == "int":
            return int(float(text))
        if kind == "float":
            return float(text)
    except ValueError:
        return text
    if kind == "bool":
        return text.strip().lower() == "true"
    return text


# ---- what kept groups occupy ------------------------------------------------------------------------------

def placed_scene(scene: Scene, kept: Iterable[SceneGroup], changed: Mapping[int, SceneGroup]) -> PlacedScene:
    """What the kept groups occupy, for post-processing the groups placed beside them; `changed` maps
    the GroupPlan index of each changed group to the group it was (its members keep their ids, and
    their start points while the group starts in the same zone)."""
    world = scene.world
    agents = [a for g in kept for a in scene.agents_of(g)]
    everyone = scene.scenario.agents
    targets: dict[str, list[Point]] = {}
    starts_by_zone: dict[str, int] = {}
    ends_by_zone: dict[str, int] = {}
    for agent in agents:
        for name, point in targets_of(scene.document(agent)):
            targets.setdefault(name, []).append(point)
        zone = world.zone_at(*agent.start)
        if zone is not None:
            starts_by_zone[zone.name] = starts_by_zone.get(zone.name, 0) + 1
        if agent.goals and not _follows_field(scene.document(agent)) and agent.zone:
            ends_by_zone[agent.zone] = ends_by_zone.get(agent.zone, 0) + 1
    by_id = {a.id: a for a in everyone}
    kept_members = {index: KeptMembers(g.members, tuple(by_id[m].start for m in g.members), g.spawn,
                                       tuple(tuple(targets_of(scene.document(by_id[m]))) for m in g.members),
                                       tuple(sorted({by_id[m].group for m in g.members if by_id[m].group >= 0})))
                    for index, g in changed.items()}
    goals = tuple((float(p[0]), float(p[1])) for p in scene.report.get("goals", ()))
    return PlacedScene(
        next_id=max((a.id for a in everyone), default=0) + 1,
        next_sfm_group=max((a.group for a in everyone), default=-1) + 1,
        starts=tuple(a.start for a in agents), targets={k: tuple(v) for k, v in targets.items()}, goals=goals,
        starts_by_zone=starts_by_zone, ends_by_zone=ends_by_zone, kept=kept_members)


def targets_of(document: TreeDocument) -> list[tuple[str, Point]]:
    """(RoI name, point) of every node of a tree that sends its agent somewhere, in tick order (the
    nodes post-processing resolves: postprocess.navigation_targets)."""
    out = []
    for element in document.nodes():
        spec = NODES.get(element.id)
        x, y = element.get("x"), element.get("y")
        if spec is None or x is None or y is None or not (spec.navigates or element.id in NAVIGATING_EXTRA):
            continue
        name = next((element.get(p.name) for p in spec.ports if p.type == "target" and element.get(p.name)), None)
        if name:
            out.append((name, (float(x), float(y))))
    return out


def _follows_field(document: TreeDocument) -> bool:
    return any(e.id == "FollowVelocityField" for e in document.nodes())
