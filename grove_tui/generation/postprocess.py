"""Post-processing: the model's draft becomes one BehaviorTree.CPP v4 file per agent.

The model only names node types, places and counts. Everything a model tracks badly is done here,
deterministically from the seed: the groups are the reading's, the draft repaired only where it
contradicts them (generation/reconcile.py); agents get ids 1..N, groups get ids, leaders and member
lists, every `target` name is resolved to a point by the preset's goal sampling, spawn points are
sampled in free space of the spawn zone at least two radii apart, and auto ports are filled so each
file is self-contained. Nothing here reads the sentence: the reading (language/) is the only ear.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
import shapely

from grove_tui.bt.format.document import TreeDocument, TreeElement
from grove_tui.bt.format.manifest import NODES, NodeSpec, PortSpec
from grove_tui.crowd.coordination import conversation_radius, queue_line_direction
from grove_tui.bt.format.ports import format_port_value
from grove_tui.bt.format.xml import write_tree
from grove_tui.generation.draft import Draft, DraftNode, place_at
from grove_tui.errors import GenerationError, PlanningError, PromptError
from grove_tui.generation.presets import Preset
from grove_tui.generation.reconcile import places_kept_out, reconcile
from grove_tui.generation.exit_post import off_the_opening
from grove_tui.generation.led_start import led_destination
from grove_tui.generation.rois import RoISelection
from grove_tui.language.model import GroupReading, PromptReading, effective_counts
from grove_tui.navigation.grid import OccupancyGrid
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.navigation.velocity_field import least_congested_exits, nearest_exits
from grove_tui.world.model import Door, Entity, World, Zone

Point = tuple[float, float]

# Centres at least this far apart at the start: wider than any default body (0.5 m), so nobody starts
# overlapping, and people start with room to move.
SPAWN_SPACING = 0.7
GOAL_SPACING = 0.8  # distinct goal points in one zone, so arrivals do not pile onto one spot
QUEUE_SPACING = 0.6  # the Queue node's default slot spacing
# Highest density we accept for a zone's free floor: standing crowds reach 2-3 people/m^2, but a
# scenario that starts at that density cannot move; beyond 1.5/m^2 we tell the user.
MAX_DENSITY = 1.5
GROUPING_NODES = frozenset({"JoinGroup", "Converse"})
MAX_WALKING_GROUP = 5  # people who walk as one social group (observed groups are mostly 2-4)


@dataclass
class AgentPlan:
    """One agent after post-processing, before the operational layer adds waypoints."""

    id: int
    group_index: int  # index of the reconciled draft group
    sfm_group: int  # social-force group id, -1 for none
    label: str
    start: Point
    spawn_zone: str
    targets: list[tuple[str, Point]]  # navigation targets in tree order (RoI name, point)
    zone: str  # zone the agent is headed for
    tree: DraftNode
    document: TreeDocument | None = None  # the agent's behavior tree, auto ports filled, waypoints empty
    max_vel: float = 1.0
    field_id: str | None = None
    exit: str | None = None
    behavior: str = "Regular"  # HuNavSim reaction to the robot, from the prompt's reading

    @property
    def xml(self) -> str:
        """The agent's tree as BT.CPP v4 text."""
        return write_tree(self.document) if self.document is not None else ""


@dataclass
class GroupPlan:
    index: int
    label: str
    count: int
    spawn: str
    tree: DraftNode
    who: str = ""  # the reading's words for them ("ten patients"), for messages
    member_ids: list[int] = field(default_factory=list)
    sfm_group: int = -1
    field_id: str | None = None
    parties: dict[int, list[int]] = field(default_factory=dict)  # social-group id -> its members
    behavior: str = "Regular"  # HuNavSim reaction to the robot
    reading_index: int | None = None  # the prompt reading's group this one realises
    party_size: int | None = None  # "two families of three": social groups of this size
    speed_factor: float = 1.0  # the reading's pace: slow / fast walkers
    # zone -> people, when an evacuation group the sentence places nowhere is too large for one zone
    # and starts spread over the building (_spread_unplaced_evacuees); empty: everyone in `spawn`.
    spawn_zones: dict[str, int] = field(default_factory=dict)
    added: list[str] = field(default_factory=list)  # what its tree does beyond the reading, in words
    # Its whole activity is reacting to the robot and the sentence places it nowhere: planning starts
    # it where the robot passes (generation/planning.py, place_robot_reactors).
    reacts_only: bool = False
    reactor_zone: str | None = None  # where the sentence puts such a group: it starts there, by the robot's route
    # such a group follows the robot ("the robot guides eight tourists"), or is guided out by it before
    # walking out on its own ("the staff evacuate while the robot guides them to the exit", not
    # reacts_only): it starts behind the robot's start, not ahead on its route, where it would crowd
    # the robot's front
    follows_robot: bool = False
    exit_asked: str | None = None  # the exit its sentence sends it through ("leave through the back door")
    leader_index: int | None = None  # reading index of the group it follows: FollowAgent's target
    exits_shunned: tuple[str, ...] = ()  # exits its sentence says it does not use ("not the main doors")
    places_shunned: tuple[str, ...] = ()  # other places it keeps out of on its way ("avoiding the lifts")


@dataclass
class PostProcessed:
    agents: list[AgentPlan]
    groups: list[GroupPlan]
    exit: str | None  # the evacuation's first exit (emergency); every exit in use is in `exits`
    goals: list[Point]  # global goal table: goal_id - 1 -> point (HuNavSim 2.0 global_goals)
    notes: list[str]  # what was repaired, for generation.json
    exits: list[str] = field(default_factory=list)  # the exits evacuees use, each person its nearest


# ---- populations ----------------------------------------------------------------------------

def _preset_overlay(tree: DraftNode, preset: Preset, selection: RoISelection, notes: list[str],
                    label: str) -> DraftNode:
    """What the preset itself requires of every tree: under the emergency preset, following the
    evacuation field to the exit."""
    kinds = {n.node for n in tree.walk()}
    if preset.velocity == "field" and "FollowVelocityField" not in kinds:
        exit_name = next(iter(selection.exits), None)
        if exit_name is not None:
            notes.append(f"group '{label}': follows the evacuation field (emergency preset)")
            return DraftNode("Sequence", {}, (tree, DraftNode("FollowVelocityField", {"exit": exit_name})))
    return tree


def check_population(world: World, grid: OccupancyGrid, preset: Preset, selection: RoISelection,
                     reading: PromptReading) -> None:
    """Refuse, before any model runs, what the sentence asks that no scenario can be (a negative or
    zero count, no words at all, nobody), head counts no selected zone could hold, and groups larger
    than the preset allows."""
    if reading.problems:
        raise PromptError(reading.problems[0])
    counts = effective_counts(reading)
    if not counts:
        raise PromptError("the sentence leaves nobody in the scenario: say who is there and what they do")
    total = sum(counts.values())
    zones = list(selection.named_zones or selection.zones)
    placed = [m for m in selection.matches if m.reason not in ("default", "preset", "world")]
    if preset.velocity == "field" and not placed:
        # An evacuation the prompt places nowhere may start anywhere in the building (postprocess
        # spreads a group too large for one zone), so the building's floor is what must hold it.
        zones = [z.name for z in world.zones]
    if total and zones:
        space = FreeSpace(world, grid)
        capacity = sum(space.capacity(z) for z in zones)
        if total > capacity:
            area = sum(space.free_area(z) for z in zones)
            raise PromptError(f"{total} people do not fit in {', '.join(zones)}: about {area:.0f} m^2 of free floor "
                              f"holds at most {capacity} at a plausible density ({MAX_DENSITY:g}/m^2)")
    for index, count in counts.items():
        if count > preset.limits.max_count:
            raise PromptError(f"'{reading.groups[index].who}' asks for {count} people in one group; preset "
                              f"'{preset.name}' allows at most {preset.limits.max_count} per group")


def _check_limits(groups: Sequence[GroupPlan], preset: Preset) -> None:
    for g in groups:
        if g.count > preset.limits.max_count:
            raise PromptError(f"'{g.who or g.label}' asks for {g.count} people in one group; preset "
                              f"'{preset.name}' allows at most {preset.limits.max_count} per group")


def _tree_places(tree: DraftNode) -> set[str]:
    places = set()
    for node in tree.walk():
        for port in _target_ports(NODES[node.node]):
            if port in node.ports:
                places.add(place_at(node, port))
    return places


# ---- free-space sampling --------------------------------------------------------------------

class FreeSpace:
    """Free cells of the inflated grid per zone, restricted to the part connected to the zone's doors."""

    def __init__(self, world: World, grid: OccupancyGrid) -> None:
        self.world = world
        self.grid = grid
        self._cells: dict[str, np.ndarray] = {}
        free = ~np.asarray(grid.occupied, dtype=bool)
        self._labels = _components(free)
        self._main = self._main_component()
        self._taken: dict[str, list[Point]] = {}
        self._clearance: np.ndarray | None = None  # metres to the nearest occupied cell, built on first use
        exits = [door.position for door in world.exits()] if hasattr(world, "exits") else []
        self._exit_points = np.asarray(exits, dtype=float).reshape(-1, 2)

    def _main_component(self) -> int:
        counts = np.bincount(self._labels[self._labels > 0].ravel()) if np.any(self._labels > 0) else np.zeros(1)
        return int(np.argmax(counts)) if len(counts) > 1 else 1

    def cells(self, zone_name: str) -> np.ndarray:
        """(K, 2) world points of free cell centres inside the zone, in the world's main free component."""
        if zone_name in self._cells:
            return self._cells[zone_name]
        zone = self.world.zone(zone_name)
        g = self.grid
        x0, y0, x1, y1 = zone.polygon.bounds
        r0, c0 = g.world_to_cell(x0, y0)
        r1, c1 = g.world_to_cell(x1, y1)
        h, w = g.occupied.shape
        rows = np.arange(max(0, min(r0, r1)), min(h, max(r0, r1) + 1))
        cols = np.arange(max(0, min(c0, c1)), min(w, max(c0, c1) + 1))
        grid_rows, grid_cols = np.meshgrid(rows, cols, indexing="ij")
        rr, cc = grid_rows.ravel(), grid_cols.ravel()
        keep = (~np.asarray(g.occupied)[rr, cc]) & (self._labels[rr, cc] == self._main)
        rr, cc = rr[keep], cc[keep]
        xs = g.origin[0] + (cc + 0.5) * g.resolution
        ys = g.origin[1] + (rr + 0.5) * g.resolution
        inside = shapely.contains_xy(zone.polygon, xs, ys)
        pts = np.stack([xs[inside], ys[inside]], axis=1) if np.any(inside) else np.zeros((0, 2))
        self._cells[zone_name] = pts
        return pts

    def reserve(self, key: str, points: Sequence[Point]) -> None:
        """Points later samples with `key` keep their spacing from, as if sampled before (people a
        refinement keeps)."""
        self._taken.setdefault(key, []).extend((float(p[0]), float(p[1])) for p in points)

    def clearance(self, pts: np.ndarray) -> np.ndarray:
        """Metres from each point to the nearest occupied cell of the grid (walls, furniture, inflated)."""
        if self._clearance is None:
            from scipy import ndimage

            free = ~np.asarray(self.grid.occupied, dtype=bool)
            self._clearance = ndimage.distance_transform_edt(free) * self.grid.resolution
        g = self.grid
        cols = np.clip(((pts[:, 0] - g.origin[0]) / g.resolution).astype(int), 0, self._clearance.shape[1] - 1)
        rows = np.clip(((pts[:, 1] - g.origin[1]) / g.resolution).astype(int), 0, self._clearance.shape[0] - 1)
        clearance: np.ndarray = self._clearance[rows, cols] + float(getattr(g, "inflation", 0.0))
        return clearance

    def free_area(self, zone_name: str) -> float:
        return len(self.cells(zone_name)) * self.grid.resolution ** 2

    def capacity(self, zone_name: str) -> int:
        # Inflation shrank the free area by a radius all round; people's centres live there but their
        # bodies stand on the zone's whole walkable floor, which is what density is measured on.
        walkable = self.world.walkable().intersection(self.world.zone(zone_name).polygon).area
        return int(math.floor(walkable * MAX_DENSITY))

    def sample(self, zone_name: str, n: int, rng: np.random.Generator, spacing: float, *,
               key: str, cluster: Point | None = None, avoid: Sequence[Point] = ()) -> list[Point]:
        """n points in the zone, pairwise >= spacing apart and from earlier samples with the same key.

        Without `cluster` the points are spread over the zone (random order, greedy acceptance);
        with it they are the acceptable points nearest to `cluster`, so a family starts together.
        """
        if n <= 0:
            return []
        pts = self.cells(zone_name)
        if len(pts) == 0:
            raise GenerationError(f"zone '{zone_name}' has no free floor to place anyone on")
        if len(self._exit_points):
            # Nobody starts on an exit: an evacuee there would leave at its first step, and anyone
            # else would be pushed outside by the people behind.
            near = np.hypot(pts[:, None, 0] - self._exit_points[None, :, 0],
                            pts[:, None, 1] - self._exit_points[None, :, 1]).min(axis=1) < SPAWN_EXIT_CLEARANCE
            if near.all():
                raise GenerationError(f"zone '{zone_name}' has no free floor farther than "
                                      f"{SPAWN_EXIT_CLEARANCE} m from an exit to place anyone on")
            pts = pts[~near]
        taken = self._taken.setdefault(key, [])
        blockers = list(taken) + list(avoid)
        order = rng.permutation(len(pts))
        if cluster is not None:
            d = np.hypot(pts[order, 0] - cluster[0], pts[order, 1] - cluster[1])
            order = order[np.argsort(d, kind="stable")]
        chosen: list[Point] = []
        bucket: dict[tuple[int, int], list[Point]] = {}
        cell = spacing

        def ok(p: Point) -> bool:
            bx, by = int(math.floor(p[0] / cell)), int(math.floor(p[1] / cell))
            for dx in (-1, 0, 1):
                for dy in (-1, 0, 1):
                    for q in bucket.get((bx + dx, by + dy), ()):
                        if (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2 < spacing * spacing:
                            return False
            return True

        def add(p: Point) -> None:
            bucket.setdefault((int(math.floor(p[0] / cell)), int(math.floor(p[1] / cell))), []).append(p)

        for q in blockers:
            add(q)
        for idx in order:
            p = (round(float(pts[idx, 0]), 3), round(float(pts[idx, 1]), 3))
            if ok(p):
                add(p)
                chosen.append(p)
                if len(chosen) == n:
                    break
        if len(chosen) < n:
            raise GenerationError(f"zone '{zone_name}' cannot hold {n} more people at least {spacing:.1f} m apart "
                                  f"(free floor {self.free_area(zone_name):.0f} m^2, {len(taken)} already there)")
        taken.extend(chosen)
        return chosen


# Spawns keep this far from every exit door's centre: twice the distance at which an evacuee
# counts as gone (crowd.leaves.grove.EXIT_RADIUS, 0.6 m), so no one is born evacuated or in the doorway.
SPAWN_EXIT_CLEARANCE = 1.2
# A conversation circle's centre keeps its radius plus this from walls and furniture (a body and a step
# round it), and this much more from the zone's doors.
CIRCLE_CLEARANCE = 0.6
CIRCLE_DOOR_MARGIN = 1.0
CIRCLE_NEAR_THING = 5.0  # metres: a circle "by" a thing or door stands within this of it


def _components(free: np.ndarray) -> np.ndarray:
    """8-connected labels of free cells (0 = occupied)."""
    from scipy import ndimage

    labels, _ = ndimage.label(free, structure=np.ones((3, 3), dtype=int))
    return np.asarray(labels)


# ---- targets --------------------------------------------------------------------------------

class TargetResolver:
    """Turns RoI names into points by the preset's goal sampling; seeded, spread, reproducible."""

    def __init__(self, world: World, grid: OccupancyGrid, space: FreeSpace, preset: Preset, rng: np.random.Generator) -> None:
        self.world, self.grid, self.space, self.preset, self.rng = world, grid, space, preset, rng
        self.group_points: dict[tuple[int, str], Point] = {}
        self.party_points: dict[tuple[int, str], Point] = {}  # (SFM group, zone) -> its first member's point
        self._lines: dict[str, Point] = {}  # service point -> heading of its queue line

    def snap(self, p: Point, label: str) -> Point:
        if self.grid.is_free(p[0], p[1]):
            return (round(float(p[0]), 3), round(float(p[1]), 3))
        q = self.grid.nearest_free(p[0], p[1], max_dist=3.0)
        if q is None:
            raise GenerationError(f"'{label}' has no free floor within 3 m of {p[0]:.1f}, {p[1]:.1f}")
        return (round(float(q[0]), 3), round(float(q[1]), 3))

    def reserve(self, name: str, points: Sequence[Point]) -> None:
        """Points people a refinement keeps were sent to for RoI `name`: new people sent there stand
        apart from them (the queue slots themselves continue through the served counts)."""
        try:
            obj = self.world.find(name)
        except Exception:
            return
        for key in (f"beside:{name}", f"goal:{obj.name}", f"queue:{name}"):
            self.space.reserve(key, points)

    def zone_of(self, name: str) -> str:
        obj = self.world.find(name)
        # Doors and entities name their zone; a zone is its own.
        return str(getattr(obj, "zone")) if hasattr(obj, "interaction_point") or hasattr(obj, "leads_to") else obj.name

    def resolve(self, name: str, *, node: str, slot: int | None = None, party: int = -1) -> Point:
        """The point `node` sends one person to at `name`. `party`: the walking group (SFM group) the
        person walks in, whose members' points in a zone are next to each other."""
        obj = self.world.find(name)
        if isinstance(obj, Entity):
            base = self.snap(obj.interaction_point, name)
            if self.preset.goal_sampling == "sequential" and slot is not None and node != "Queue":
                return self._queue_slot(obj, base, slot)
            if node == "Queue":
                return base
            return self._beside(name, obj.zone, base, slot)
        if isinstance(obj, Door):
            if node == "FollowVelocityField":
                return (round(obj.position[0], 3), round(obj.position[1], 3))
            if obj.exit:  # standing at an exit without leaving: beside its opening (exit_post)
                return self._beside(name, obj.zone, off_the_opening(obj, lambda p: self.snap(p, name)), slot)
            return self._beside(name, obj.zone, self.snap(obj.inward_point(0.6), name), slot)
        if node == "Queue":
            # A queue needs a service point; a zone named as one is served at its counter-like entity.
            service = _service_entity(obj)
            if service is not None:
                return self.resolve(service.name, node=node, slot=slot)
        if party >= 0 and node == "GoTo":
            # A group walking together arrives together: points spread over the zone would have its
            # members pulled apart by their goals and held together by the group's forces, and they
            # stall short of every point.
            anchor = self.party_points.get((party, obj.name))
            (p,) = self.space.sample(obj.name, 1, self.rng, GOAL_SPACING, key=f"goal:{obj.name}", cluster=anchor)
            self.party_points.setdefault((party, obj.name), p)
            return p
        (p,) = self.space.sample(obj.name, 1, self.rng, GOAL_SPACING, key=f"goal:{obj.name}")
        return p

    def circle_centre(self, name: str, radius: float) -> Point:
        """Where a conversation circle of `radius` stands in a zone: a free point at least the circle and a
        body from walls and furniture, and a body further from the zone's doors (people come in through
        them); a door or thing keeps its own point. Falls back to the roomiest point of the zone."""
        obj = self.world.find(name)
        near: Point | None = None
        if isinstance(obj, (Entity, Door)):
            # "chat by the fountain": a free circle beside it, as close to it as room allows
            near = self.resolve(name, node="Converse")
            zone_name = obj.zone
        else:
            zone_name = obj.name
        pts = self.space.cells(zone_name)
        if near is not None and len(pts):
            pts = pts[np.hypot(pts[:, 0] - near[0], pts[:, 1] - near[1]) <= CIRCLE_NEAR_THING]
        if not len(pts):
            return near if near is not None else self.resolve(name, node="Converse")
        room = self.space.clearance(pts)
        doors = np.asarray([d.position for d in self.world.doors_of(zone_name)], dtype=float).reshape(-1, 2)
        if len(doors):
            to_door = np.min(np.hypot(pts[:, None, 0] - doors[None, :, 0], pts[:, None, 1] - doors[None, :, 1]), axis=1)
            room = np.minimum(room, to_door - CIRCLE_DOOR_MARGIN)
        need = radius + CIRCLE_CLEARANCE
        ok = np.flatnonzero(room >= need)
        if not len(ok):
            best = int(np.argmax(room))
            return (round(float(pts[best, 0]), 3), round(float(pts[best, 1]), 3))
        if near is not None:
            k = int(ok[np.argmin(np.hypot(pts[ok, 0] - near[0], pts[ok, 1] - near[1]))])
        else:
            k = int(ok[self.rng.integers(len(ok))])
        return (round(float(pts[k, 0]), 3), round(float(pts[k, 1]), 3))

    def _beside(self, name: str, zone: str, base: Point, slot: int | None) -> Point:
        """The k-th person sent to one door or thing stands next to the ones before, not on top of them:
        people sharing one goal point would jostle for it for the rest of the run."""
        if not slot:
            return base
        (p,) = self.space.sample(zone, 1, self.rng, GOAL_SPACING, key=f"beside:{name}", cluster=base, avoid=(base,))
        return p

    def _queue_slot(self, entity: Entity, base: Point, k: int) -> Point:
        """Sequential allocation: the k-th person sent to a service point walks to the k-th place of its line.

        The line is the one the simulation's queue will form (crowd.coordination.queue_line_direction, the
        heading with the most free floor, preferring straight out from the counter), so nobody is sent
        behind shelves the line never crosses; where it would leave the zone or hit an obstacle the
        person is sent to the nearest free spot of the zone instead.
        """
        if k == 0:
            return base
        if entity.name not in self._lines:
            from grove_tui.generation.formations import GridSpace

            direction, _ = queue_line_direction(GridSpace(self.world, self.grid), entity.name, base, QUEUE_SPACING)
            self._lines[entity.name] = direction
        dx, dy = self._lines[entity.name]
        norm = math.hypot(dx, dy) or 1.0
        p = (base[0] + dx / norm * QUEUE_SPACING * k, base[1] + dy / norm * QUEUE_SPACING * k)
        zone = self.world.zone(entity.zone)
        if self.grid.is_free(*p) and zone.polygon.contains(shapely.Point(p)):
            return (round(p[0], 3), round(p[1], 3))
        (q,) = self.space.sample(entity.zone, 1, self.rng, QUEUE_SPACING, key=f"queue:{entity.name}", cluster=base)
        return q


def _service_entity(zone: Zone) -> Entity | None:
    for wanted in ("counter", "desk", "reception", "booth", "vending_machine", "machine", "kiosk"):
        for e in zone.entities:
            if wanted in e.type or wanted in e.name:
                return e
    return zone.entities[0] if zone.entities else None


# ---- trees ----------------------------------------------------------------------------------

def _target_ports(spec: NodeSpec) -> list[str]:
    return [p.name for p in spec.ports if p.type == "target"]


NAVIGATING_EXTRA = frozenset({"Queue", "FollowVelocityField"})  # resolved to a point, though they do not walk


def navigation_targets(tree: DraftNode) -> list[tuple[DraftNode, str]]:
    """(node, target port) pairs in tick order for every node that moves the agent to a place."""
    out = []
    for node in tree.walk():
        spec = NODES[node.node]
        if spec.navigates or node.node in NAVIGATING_EXTRA:
            for port in _target_ports(spec):
                if port in node.ports:
                    out.append((node, port))
    return out


class TreeWriter:
    """Per-agent behavior-tree documents from a draft tree: model-written ports verbatim, auto ports filled."""

    def __init__(self, resolver: TargetResolver) -> None:
        self.resolver = resolver
        self.goal_ids: dict[Point, int] = {}
        self.leaders: dict[int, int] = {}  # reading index -> the first member of that group (whom followers follow)

    def goal_id(self, p: Point) -> int:
        if p not in self.goal_ids:
            self.goal_ids[p] = len(self.goal_ids) + 1
        return self.goal_ids[p]

    def write(self, agent: AgentPlan, group: GroupPlan, targets: dict[int, Point]) -> TreeDocument:
        tree_id = f"agent_{agent.id}"
        return TreeDocument.single(tree_id, self._node(agent.tree, agent, group, targets))

    def _node(self, node: DraftNode, agent: AgentPlan, group: GroupPlan, targets: dict[int, Point]) -> TreeElement:
        spec = NODES[node.node]
        attrs: dict[str, str] = {}
        point = targets.get(id(node))
        party = group.parties.get(agent.sfm_group, group.member_ids)
        others = [m for m in party if m != agent.id]
        for port in spec.ports:
            if port.direction != "in":
                continue
            name = port.name
            if name in node.ports:
                attrs[name] = format_port_value(node.ports[name])
                continue
            if not port.auto:
                if port.default is not None:
                    attrs[name] = format_port_value(port.default)
                continue
            value = self._auto_value(spec, port, agent, group, others, point)
            if value is not None:
                attrs[name] = value
        children = [self._node(c, agent, group, targets) for c in node.children]
        return TreeElement(node.node, attrs, children)

    def _auto_value(self, spec: NodeSpec, port: PortSpec, agent: AgentPlan, group: GroupPlan, others: list[int],
                    point: Point | None) -> str | None:
        name, kind = port.name, port.type
        if kind == "agent" and isinstance(port.default, str) and port.default.startswith("{"):
            return port.default  # the agent's own id, from the blackboard
        if kind == "float" and isinstance(port.default, str) and port.default.startswith("{"):
            return port.default  # {dt}
        if kind == "agent" and spec.name == "FollowAgent" and group.leader_index in self.leaders:
            return str(self.leaders[group.leader_index])  # "follow their guide": the guide
        if kind == "agent":
            # The other agent of a pair: the leader for members, the next member for the leader.
            if others:
                leader = group.parties.get(agent.sfm_group, group.member_ids)[0]
                return str(leader if leader != agent.id else others[0])
            return None
        if kind == "agents":
            ids = others if name == "non_main_agent_ids" else group.parties.get(agent.sfm_group, group.member_ids)
            return ",".join(str(i) for i in ids)
        if name in ("x", "target_x") and point is not None:
            return format_port_value(point[0])
        if name in ("y", "target_y") and point is not None:
            return format_port_value(point[1])
        if name == "goal_id" and point is not None:
            return str(self.goal_id(point))
        if name == "group_id":
            return str(max(agent.sfm_group, 0))
        if name == "field":
            return agent.field_id
        if kind == "point_list":
            return ""
        return None


# ---- the stage ------------------------------------------------------------------------------

def postprocess(world: World, grid: OccupancyGrid, preset: Preset, draft: Draft, selection: RoISelection, seed: int,
                reading: PromptReading, allowed_nodes: Sequence[str] = ()) -> PostProcessed:
    """Draft -> agents with ids, spawns, resolved targets and per-agent trees (waypoints still empty).

    The groups are the reading's; the draft is repaired only where it contradicts it
    (generation/reconcile.py). `allowed_nodes`: the nodes this request offered the model."""
    notes: list[str] = []
    groups = plan_groups(world, preset, draft, selection, reading, notes)
    return place_groups(world, grid, preset, groups, selection, seed, reading, notes)


def plan_groups(world: World, preset: Preset, draft: Draft, selection: RoISelection, reading: PromptReading,
                notes: list[str] | None = None, first_index: int = 0) -> list[GroupPlan]:
    """The scenario's groups with their final trees (before ids, spawns and points): the reading's
    groups with the draft reconciled to them. Repairs go to `notes`. `first_index` numbers the groups
    from there (a refinement's new groups follow the kept ones)."""
    notes = [] if notes is None else notes
    default_spawn = selection.zones[0] if selection.zones else world.zones[0].name
    groups = [GroupPlan(first_index + i, r.label, r.count, r.spawn, r.tree, reading.groups[r.reading_index].who
                        if r.reading_index is not None else "", behavior=r.behavior, reading_index=r.reading_index,
                        party_size=r.party_size, speed_factor=r.speed_factor, added=list(r.added),
                        reacts_only=r.reacts_only, leader_index=r.leader_index,
                        reactor_zone=_reactor_zone(world, reading.groups[r.reading_index or 0]) if r.reacts_only
                        else None,
                        follows_robot=r.guided or (r.reacts_only and
                                                   reading.groups[r.reading_index or 0].robot_interaction == "follow"),
                        exit_asked=_exit_asked(world, reading.groups[r.reading_index or 0]),
                        exits_shunned=_exits_shunned(world, reading.groups[r.reading_index or 0]),
                        places_shunned=places_kept_out(world, reading.groups[r.reading_index or 0]))
              for i, r in enumerate(reconcile(draft, reading, world, default_spawn, notes,
                                              evacuation_field=preset.velocity == "field"))]
    if not groups:
        raise GenerationError("the prompt's groups leave nobody in the scenario")
    for g in groups:
        # The preset's evacuation is for those the sentence evacuates: a guard who waits by the
        # door during a drill waits (nothing unasked).
        if g.reading_index is not None and reading.groups[g.reading_index].intent == "evacuate":
            g.tree = _preset_overlay(g.tree, preset, selection, notes, g.label)
    return groups


@dataclass(frozen=True)
class KeptMembers:
    """The members a changed group keeps in a refinement: their ids, and where they stand when the
    group still starts in `zone` (else they are placed again)."""

    ids: tuple[int, ...]
    starts: tuple[Point, ...]
    zone: str
    # per member, (RoI name, point) of each place its tree sent it to: a member whose tree still goes
    # to the same places in the same order goes to the same points
    targets: tuple[tuple[tuple[str, Point], ...], ...] = ()
    sfm_groups: tuple[int, ...] = ()  # the social groups its members formed, reused while they fit


@dataclass(frozen=True)
class PlacedScene:
    """What a refinement keeps of a scenario, which the groups placed next must not collide with.

    `starts`: everyone kept (new people start at least SPAWN_SPACING from them); `targets`: the points
    kept people are sent to, by RoI name (new people queue behind them, stand beside them);
    `goals`: the goal table (goal_id - 1 -> point); `starts_by_zone` / `ends_by_zone`: kept people per
    zone, for the capacity check; `kept`: by GroupPlan index, the members a changed group keeps."""

    next_id: int
    next_sfm_group: int
    starts: tuple[Point, ...] = ()
    targets: Mapping[str, tuple[Point, ...]] = field(default_factory=dict)
    goals: tuple[Point, ...] = ()
    starts_by_zone: Mapping[str, int] = field(default_factory=dict)
    ends_by_zone: Mapping[str, int] = field(default_factory=dict)
    kept: Mapping[int, KeptMembers] = field(default_factory=dict)


def place_groups(world: World, grid: OccupancyGrid, preset: Preset, groups: list[GroupPlan], selection: RoISelection,
                 seed: int,
                 reading: PromptReading | None = None, notes: list[str] | None = None,
                 scene: PlacedScene | None = None) -> PostProcessed:
    """Planned groups -> agents: ids, spawns in free space, targets resolved to points, one tree
    document per agent. With a `scene` (a refinement), ids and social groups continue after the kept
    ones, nobody starts on a kept person and people sent to a kept queue line up behind it."""
    rng = np.random.default_rng([int(seed) & 0xFFFFFFFF, 0x6A09E667])
    notes = [] if notes is None else notes
    space = FreeSpace(world, grid)
    if scene is not None:
        space.reserve("spawn", list(scene.starts) + [p for kept in scene.kept.values() for p in kept.starts])
    if preset.velocity == "field" and reading is not None:
        _spread_unplaced_evacuees(groups, reading, space, world, notes)
    _check_capacity(groups, space, world, scene)
    _check_limits(groups, preset)
    resolver = TargetResolver(world, grid, space, preset, rng)
    exit_names = _evacuation_exits(world, selection, notes) if preset.velocity == "field" else []
    exit_name = exit_names[0] if exit_names else None

    agents: list[AgentPlan] = []
    next_id = scene.next_id if scene is not None else 1
    sfm_groups = scene.next_sfm_group if scene is not None else 0
    for g in groups:
        kept = scene.kept.get(g.index) if scene is not None else None
        kept_ids = list(kept.ids[:g.count]) if kept is not None else []
        g.member_ids = kept_ids + list(range(next_id, next_id + g.count - len(kept_ids)))
        next_id += g.count - len(kept_ids)
        kept_starts = list(kept.starts[:g.count]) if kept is not None and kept.zone == g.spawn and \
            not g.spawn_zones else []
        node_types = {n.node for n in g.tree.walk()}
        # Who walks as one social group: the whole group for a conversation, and walking groups of at
        # most MAX_WALKING_GROUP ("25 staff walk together" are colleagues in small groups, not one
        # 25-person formation held together by group forces).
        parties = [g.count]
        if node_types & GROUPING_NODES and g.count > 1:
            g.sfm_group = sfm_groups
            if g.party_size and "Converse" not in node_types and g.count > g.party_size:
                # "two families of three": the parties the sentence states
                parties = [g.party_size] * (g.count // g.party_size) + ([g.count % g.party_size]
                                                                       if g.count % g.party_size else [])
            elif "Converse" not in node_types and g.count > MAX_WALKING_GROUP:
                n = math.ceil(g.count / MAX_WALKING_GROUP)
                parties = [g.count // n + (1 if i < g.count % n else 0) for i in range(n)]
                sizes = f"{min(parties)}-{max(parties)}" if min(parties) != max(parties) else str(parties[0])
                notes.append(f"group '{g.label}': {g.count} people walk together as {n} groups of {sizes}")
            own = kept.sfm_groups if kept is not None else ()
            if own and len(parties) <= len(own) and own == tuple(range(own[0], own[0] + len(own))):
                g.sfm_group = own[0]  # a changed group keeps its social groups' ids
            else:
                sfm_groups += len(parties)
        if preset.velocity == "field" and "FollowVelocityField" in node_types:
            g.field_id = f"group_{g.index + 1}"  # the group's first field; per exit below when it splits
        first = 0
        for zone, size, k in _spawn_chunks(g, parties):
            party = g.sfm_group + k if g.sfm_group >= 0 else -1
            fixed = kept_starts[first:first + size]
            cluster = None
            # a social group starts together; so do people who follow someone ("six tourists follow her":
            # the tour group around its guide, not spread over the hall, the last one 15 m off)
            if (party >= 0 or g.leader_index is not None) and len(fixed) < size:
                (cluster,) = space.sample(zone, 1, rng, 0.1, key=f"anchor:{zone}:{g.index}:{k}")
            starts = fixed + (space.sample(zone, size - len(fixed), rng, SPAWN_SPACING, key="spawn",
                                           cluster=cluster) if len(fixed) < size else [])
            if party >= 0:
                g.parties.setdefault(party, []).extend(g.member_ids[first:first + size])
            for agent_id, start in zip(g.member_ids[first:first + size], starts):
                agents.append(AgentPlan(agent_id, g.index, party, g.label, start, zone, [], zone, g.tree,
                                        max_vel=round(preset.max_vel * g.speed_factor, 3), field_id=g.field_id,
                                        exit=exit_name, behavior=g.behavior))
            first += size

    _leaders_among_their_followers(groups, agents, space, rng)
    if len(exit_names) > 1:
        _assign_exits(world, grid, groups, agents, exit_names, notes, preset.exit_choice)

    writer = TreeWriter(resolver)
    writer.leaders = {g.reading_index: g.member_ids[0] for g in groups if g.reading_index is not None and g.member_ids}
    served: dict[str, int] = {}
    if scene is not None:
        writer.goal_ids.update({p: i + 1 for i, p in enumerate(scene.goals)})
        for name, points in scene.targets.items():
            served[name] = len(points)
            resolver.reserve(name, points)
    by_index = {g.index: g for g in groups}
    kept_targets = {m: t for kept in (scene.kept.values() if scene is not None else ())
                    for m, t in zip(kept.ids, kept.targets)}
    for agent in agents:
        g = by_index[agent.group_index]
        tree = _with_exit(agent.tree, agent.exit) if agent.exit else agent.tree
        agent.tree = tree
        targets: dict[int, Point] = {}
        slots: dict[str, int] = {}
        before = kept_targets.get(agent.id, ())
        for k, (node, port) in enumerate(navigation_targets(tree)):
            name = place_at(node, port)
            if name not in slots:
                # This agent's place in the line of everyone sent to `name` (sequential goal allocation).
                slots[name] = served.get(name, 0)
                served[name] = slots[name] + 1
            if k < len(before) and before[k][0] == name and node.node != "FollowVelocityField":
                point = before[k][1]  # a kept member goes where it went
                if node.node == "Converse":
                    resolver.group_points.setdefault((g.index, name), point)  # newcomers join its circle
            elif node.node == "Converse":
                # One circle per group: everyone resolves the same centre.
                point = _group_point(resolver, g, name)
            else:
                point = resolver.resolve(name, node=node.node, slot=slots[name], party=agent.sfm_group)
            targets[id(node)] = point
            agent.targets.append((name, point))
        if agent.targets:
            agent.zone = resolver.zone_of(agent.targets[-1][0])
        agent.document = writer.write(agent, g, targets)
    goals = [p for p, _ in sorted(writer.goal_ids.items(), key=lambda kv: kv[1])]
    return PostProcessed(agents, groups, exit_name, goals, notes, exit_names)


def _leaders_among_their_followers(groups: Sequence[GroupPlan], agents: Sequence[AgentPlan], space: FreeSpace,
                                   rng: np.random.Generator) -> None:
    """The person a group follows starts among them ("ten tourists follow their guide": the guide stands
    with the tour group, not across the hall), when they start in the same zone."""
    for follower in groups:
        leader = next((g for g in groups if follower.leader_index is not None and g is not follower
                       and g.reading_index == follower.leader_index), None)
        if leader is None or leader.spawn != follower.spawn or not leader.member_ids:
            continue
        behind = [a.start for a in agents if a.group_index == follower.index]
        ahead = next((a for a in agents if a.id == leader.member_ids[0]), None)
        if not behind or ahead is None:
            continue
        centre = (sum(p[0] for p in behind) / len(behind), sum(p[1] for p in behind) / len(behind))
        (ahead.start,) = space.sample(leader.spawn, 1, rng, SPAWN_SPACING, key="spawn", cluster=centre)


def _exit_asked(world: World, group: GroupReading) -> str | None:
    """The exit a group's sentence names; None when it names none or the reader was unsure which
    ("the nearest exit": each person then takes their own nearest)."""
    exits = {d.name for d in world.exits()}
    unsure = group.confidence_of("destination")
    if unsure is not None and unsure.unsure:
        return None
    return group.destination if group.destination in exits else None


def _exits_shunned(world: World, group: GroupReading) -> tuple[str, ...]:
    """The exits a group's sentence says it does not use ("..., not the main doors")."""
    exits = {d.name for d in world.exits()}
    return tuple(a for a in group.avoid if a in exits)


def _reactor_zone(world: World, group: GroupReading) -> str | None:
    """The zone a group that reacts to the robot is put in by its sentence: where they are, or where
    they follow it through."""
    # people the robot leads are where it picks them up, not already where it takes them (led_start)
    for name in (group.start, group.location, *group.via, *led_destination(group)):
        if name:
            zone = world.zone_of_place(name) or ""
            if zone:
                return zone
    return None


def _group_point(resolver: TargetResolver, group: GroupPlan, name: str) -> Point:
    key = (group.index, name)
    if key not in resolver.group_points:
        # A circle of the group's talkers (each social party its own): its spots must all be free floor,
        # clear of walls and doorways, or the last to arrive cannot reach theirs.
        talkers = max((len(m) for m in group.parties.values()), default=group.count) if group.parties else group.count
        resolver.group_points[key] = resolver.circle_centre(name, conversation_radius(max(talkers, 2)))
    return resolver.group_points[key]


def _field_start(world: World, grid: OccupancyGrid, agent: AgentPlan) -> Point:
    """Where an evacuee starts to follow the field: the place of the last step that walks it somewhere
    before the field in its tree (a zone's anchor, a thing's point), else its spawn."""
    last: str | None = None
    for node, port in navigation_targets(agent.tree):
        if node.node == "FollowVelocityField":
            break
        last = place_at(node, port)
    if last is None:
        return agent.start
    try:
        place = world.find(last)
    except Exception:
        return agent.start
    point = place.interaction_point if isinstance(place, Entity) else \
        place.position if isinstance(place, Door) else place.anchor
    free = grid.nearest_free(float(point[0]), float(point[1]), max_dist=2.0)
    return agent.start if free is None else (float(free[0]), float(free[1]))


def _with_exit(tree: DraftNode, exit_name: str) -> DraftNode:
    """Every FollowVelocityField of the agent's tree leads to the agent's exit."""
    ports = dict(tree.ports)
    if tree.node == "FollowVelocityField":
        ports["exit"] = exit_name
    return DraftNode(tree.node, ports, tuple(_with_exit(c, exit_name) for c in tree.children))


def _spread_unplaced_evacuees(groups: Sequence[GroupPlan], reading: PromptReading, space: FreeSpace, world: World,
                              notes: list[str]) -> None:
    """An evacuation group that the sentence places nowhere ("500 people evacuate") and that is too
    large for the zone the draft starts it in, starts spread over the building instead: every zone
    with free floor takes a share in proportion to that floor (largest remainders), so the crowd is
    as dense everywhere. A group the sentence does place keeps its zone, and the capacity check
    refuses it there if it does not fit."""
    zones = [z.name for z in world.zones if space.capacity(z.name) >= 1 and len(space.cells(z.name))]
    for g in groups:
        if g.reading_index is None or not 0 <= g.reading_index < len(reading.groups):
            continue
        asked = reading.groups[g.reading_index]
        if asked.start or asked.location or g.count <= space.capacity(g.spawn):
            continue
        area = np.array([space.free_area(z) for z in zones])
        shares = g.count * area / area.sum()
        counts = np.floor(shares).astype(int)
        # Largest remainders; ties by zone order, so the split is deterministic.
        for i in np.argsort(-(shares - counts), kind="stable")[: g.count - int(counts.sum())]:
            counts[i] += 1
        g.spawn_zones = {zone: int(n) for zone, n in zip(zones, counts) if n > 0}
        first_zone = max(g.spawn_zones, key=lambda z: (g.spawn_zones[z], z))
        notes.append(f"group '{g.label}': {g.count} people do not fit in {g.spawn} (at most {space.capacity(g.spawn)}) "
                     f"and the sentence places them nowhere, so they start across the building: "
                     f"{len(g.spawn_zones)} zones in proportion to their free floor")
        g.spawn = first_zone


def _spawn_chunks(group: GroupPlan, parties: Sequence[int]) -> list[tuple[str, int, int]]:
    """(zone, people, party index) in spawning order. A spread group's social parties each start in
    one zone, handed to the zone with the most places left; one party spread over zones (or no
    parties) fills each zone's share."""
    if not group.spawn_zones:
        return [(group.spawn, size, k) for k, size in enumerate(parties)]
    if len(parties) == 1:
        return [(zone, n, 0) for zone, n in group.spawn_zones.items()]
    left = dict(group.spawn_zones)
    chunks = []
    for k, size in enumerate(parties):
        zone = max(left, key=lambda z: (left[z], z))
        left[zone] -= size
        chunks.append((zone, size, k))
    return chunks


def _check_capacity(groups: Sequence[GroupPlan], space: FreeSpace, world: World, scene: PlacedScene | None = None) -> None:
    """Everyone must fit, at a plausible density, both where they start and where they end up
    (with the people a refinement keeps)."""
    ends: dict[str, int] = dict(scene.ends_by_zone) if scene is not None else {}
    starts: dict[str, int] = dict(scene.starts_by_zone) if scene is not None else {}
    for g in groups:
        for zone, n in (g.spawn_zones or {g.spawn: g.count}).items():
            starts[zone] = starts.get(zone, 0) + n
        places = [place_at(node, port) for node, port in navigation_targets(g.tree)
                  if node.node != "FollowVelocityField"]
        if places:
            zone = world.zone_of_place(places[-1]) or g.spawn  # a door or entity means its zone
            ends[zone] = ends.get(zone, 0) + g.count
    for counts in (ends, starts):
        for zone, n in counts.items():
            cap = space.capacity(zone)
            if n > cap:
                raise PromptError(
                    f"{n} people do not fit in zone '{zone}': its free floor of about "
                    f"{space.free_area(zone):.0f} m^2 holds at most {cap} at a plausible density ({MAX_DENSITY:g}/m^2)")


def _evacuation_exits(world: World, selection: RoISelection, notes: list[str]) -> list[str]:
    """The exits evacuees may use: those the prompt names, else every exit of the world.

    Each person then leaves through the nearest of them (_assign_exits): "the nearest exit"
    is each person's own, not one exit shared by the whole crowd (issue 19).
    """
    exits = {d.name: d for d in world.exits()}
    if not exits:
        raise GenerationError(f"world '{world.name}' has no exit door to evacuate through")
    named = [m.name for m in selection.matches if m.reason == "prompt" and m.name in exits]
    if named:
        return list(dict.fromkeys(named))
    # The prompt allows every exit: a small model's tree naming one does not restrict the crowd to it.
    notes.append(f"evacuation exits: {', '.join(sorted(exits))} (each person takes the nearest)")
    return sorted(exits)


def _assign_exits(world: World, grid: OccupancyGrid, groups: Sequence[GroupPlan], agents: Sequence[AgentPlan],
                  exit_names: Sequence[str], notes: list[str], how: str = "nearest") -> None:
    """Each evacuee's exit: the nearest by walking distance, or with `how` "least_congested" the one it
    expects to be out of soonest (preset exit_choice); a group split over exits gets one field per exit."""
    evacuees = [a for a in agents if a.field_id is not None]
    if not evacuees:
        return
    exits = {d.name: d for d in world.exits()}
    doors = {name: exits[name] for name in exit_names}
    # where each sets off along the field: its spawn, or the place its tree walks to first ("hurry to the
    # south entrance hall" then out: the exit nearest to that hall, not back past where they came from)
    starts = [_field_start(world, grid, a) for a in evacuees]
    try:
        planner = ThetaStarPlanner(grid, landmarks=0)
        if how == "least_congested":
            choice = least_congested_exits(planner, {n: (d.position, d.width) for n, d in doors.items()}, starts,
                                           [a.max_vel for a in evacuees])
        else:
            choice = nearest_exits(planner, {n: d.position for n, d in doors.items()}, starts)
    except PlanningError as exc:
        raise GenerationError(f"an evacuee cannot reach any exit: {exc}") from None
    # A group the sentence sends through a named exit leaves through it, whatever is nearer.
    asked = {g.index: g.exit_asked for g in groups if g.exit_asked in doors}
    choice = [asked.get(a.group_index, name) for a, name in zip(evacuees, choice)]
    for g in groups:
        allowed = {n: d.position for n, d in doors.items() if n not in g.exits_shunned}
        rows = [k for k, a in enumerate(evacuees) if a.group_index == g.index and choice[k] in g.exits_shunned]
        if rows and allowed:
            # "..., not the main doors": the nearest of the others
            try:
                others = nearest_exits(planner, allowed, [evacuees[k].start for k in rows])
            except PlanningError as exc:
                raise GenerationError(f"group '{g.label}' cannot reach an exit but {', '.join(g.exits_shunned)}: "
                                      f"{exc}") from None
            for k, name in zip(rows, others):
                choice[k] = name
    # A social party (family, friends) leaves together: through its first member's nearest exit.
    party_exit: dict[int, str] = {}
    for agent, name in zip(evacuees, choice):
        if agent.sfm_group >= 0:
            party_exit.setdefault(agent.sfm_group, name)
    used: dict[str, int] = {}
    for agent, name in zip(evacuees, choice):
        name = party_exit.get(agent.sfm_group, name)
        agent.exit = name
        used[name] = used.get(name, 0) + 1
    for g in groups:
        members = [a for a in evacuees if a.group_index == g.index]
        if len({a.exit for a in members}) > 1:
            for a in members:
                a.field_id = f"group_{g.index + 1}_{a.exit}"
            g.field_id = members[0].field_id  # the report's field for the group: its first member's
    notes.append("exits in use: " + ", ".join(f"{name} ({used[name]} people)" for name in sorted(used)))
