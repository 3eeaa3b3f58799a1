"""Operational layer: collision-free geometry for the post-processed trees, and the robot's task.

Normal and queuing presets plan every leg between consecutive navigation goals with Theta* and
inject the waypoints into the trees; the emergency preset plans each group's centroid to its exit
(per person the nearest allowed one; a group split over exits plans one field per exit) and turns
that path into the velocity field. The robot gets a start and a goal
(the user's, or chosen across the scene so that its path runs through where people are) and a
planned path.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace

import numpy as np
import shapely

from grove_tui.bt.format.document import TreeDocument, TreeFiles
from grove_tui.bt.format.manifest import NODES
from grove_tui.bt.format.ports import parse_point_list
from grove_tui.errors import Cancelled, GenerationError, PlanningError, WorldError
from grove_tui.navigation.theta_star import PlanCache, ThetaStarPlanner
from grove_tui.generation import approach_at_place
from grove_tui.generation.beside_queue import beside
from grove_tui.generation.past_queue import beside_points
from grove_tui.generation.goes_on_past import ends_off, goes_on
from grove_tui.generation.led_exit import nearest_exit
from grove_tui.generation.block_at_place import posts_for_blockers, rooms_to_pass, set_post
from grove_tui.generation.routine_rooms import rooms_of_routines
from grove_tui.generation.passed_spot import ends_off_the_spot
from grove_tui.generation.crossing import crossing_goal, crossing_start
from grove_tui.generation.formations import (
    PASSING_MARGIN,
    block_formations,
    formations_at,
    nearest_formation_gap,
    predict_formations,
)
from grove_tui.generation.passing_place import nearest_first, off_the_route, passing_points
from grove_tui.generation.queue_pass import along_their_queues
from grove_tui.generation.passing_reactors import PASS_NEAR, reacting_points, unplaced_note, widest_gap
from grove_tui.generation.guided import GUIDING_VEL, guided_exit, guided_index, guided_seconds
from grove_tui.generation.draft import DraftNode
from grove_tui.generation.waits_for_watchers import held_for_watchers
from grove_tui.generation.passing_look import react_once_there
from grove_tui.generation.postprocess import AgentPlan, FreeSpace, GroupPlan, PostProcessed
from grove_tui.generation.presets import Preset
from grove_tui.generation.requests import Point, RobotRequest
from grove_tui.generation.robot_errand import errand_robot
from grove_tui.language.robot_errands import robot_errand
from grove_tui.generation.spots_to_pass import spots_to_pass
from grove_tui.generation.robot_passing import people_stay_in, through_formations, zone_before
from grove_tui.scenario.model import AgentSpec, RobotSpec
from grove_tui.navigation.velocity_field import VelocityField
from grove_tui.generation.keep_out import keep_out_planner
from grove_tui.generation.robot_keep_out import keep_out_notes, kept_out_zones, robot_kept_out
from grove_tui.generation.waypoints import plan_waypoints
from grove_tui.world.model import Door, Entity, World
from grove_tui.navigation.grid import OccupancyGrid
from grove_tui.language.model import PromptReading
from grove_tui.language.tokens import lemma, words

ROBOT_CLEARANCE = 2.0  # metres between the robot's start/goal and anybody's spawn
ENTRY_DEPTH = 3.0  # metres into a room the robot goes to be seen by the people in it who react to it
VIA_SPOT_NEAR = 0.75  # metres: a path this close to a thing's or door's point passes by it (the report allows 1.5)
ROBOT_CANDIDATES = 48


@dataclass
class OperationalPlan:
    agents: list[AgentSpec]
    trees: TreeFiles  # relative path -> the agent's tree, waypoints injected
    fields: dict[str, VelocityField]  # field id -> field
    robot: RobotSpec | None
    notes: list[str] = field(default_factory=list)


class CachedPlanner:
    """Theta* behind a PlanCache: legs shared by many agents (same goal slot) are planned once."""

    def __init__(self, world_name: str, planner: ThetaStarPlanner, cache: PlanCache | None = None) -> None:
        self.world_name = world_name
        self.planner = planner
        self.cache = cache or PlanCache()

    def plan(self, start: Point, goal: Point, start_label: str = "start", goal_label: str = "goal") -> np.ndarray:
        path: np.ndarray = self.cache.plan(self.world_name, self.planner, start, goal, start_label=start_label,
                                           goal_label=goal_label)
        return path


def goals_from_tree(document: TreeDocument) -> list[Point]:
    """Every point the agent is sent to, in tick order: injected waypoints then the node's target."""
    goals: list[Point] = []
    for element in document.nodes():
        spec = NODES.get(element.id)
        x, y = element.get("x"), element.get("y")
        if spec is None or x is None or y is None:
            continue
        waypoints = element.get("waypoints")
        if waypoints:
            try:
                goals.extend(parse_point_list(waypoints))
            except ValueError as exc:
                raise PlanningError(f"{element.describe()}: waypoints: {exc}") from None
        goals.append((float(x), float(y)))
    return goals


def plan_operational(world: World, grid: OccupancyGrid, preset: Preset, post: PostProcessed, seed: int,
                     robot: RobotRequest | None = None, planner: ThetaStarPlanner | None = None,
                     cache: PlanCache | None = None, cancel: threading.Event | None = None,
                     reading: PromptReading | None = None) -> OperationalPlan:
    """Waypoints, fields and the robot. `reading`: the sentence's reading, whose robot clause sets the
    robot's task and places (a user's --robot-start/--robot-goal win over it)."""
    planner = planner or ThetaStarPlanner(grid)
    cached = CachedPlanner(world.name, planner, cache)
    notes: list[str] = []
    robot_spec = None
    if robot is None or robot.enabled:
        # The robot first: people whose whole activity is reacting to it start where it passes.
        request = robot or RobotRequest()
        robot_notes: list[str] = []
        robot_spec = plan_robot(world, grid, cached, post, request, seed, robot_notes, reading=reading)
        robot_spec = _at_a_guiding_pace(post, preset, robot_spec, robot_notes)
        reactor_notes: list[str] = []
        unseen = place_robot_reactors(world, grid, post, robot_spec, seed, reactor_notes, passing_points(
                reading, post.groups, lambda p: _place_point(world, grid, p)))
        route = list(robot_spec.path) or [robot_spec.start, robot_spec.goal]
        rooms = list(dict.fromkeys([g.reactor_zone for g in unseen if g.reactor_zone] + rooms_to_pass(
            world, post.groups, route) + approach_at_place.rooms_to_pass(world, post.groups, route)
            + rooms_of_routines(world, reading, route)))
        spots = spots_to_pass(world, grid, post.groups, route)  # a door or thing they react at, in a room passed
        if (rooms or spots) and robot_spec.task in ("cross", "patrol"):
            # People the sentence puts in a room to react to the robot ("people in the waiting area look
            # at it") react only if it comes by: a route fixed elsewhere passes through their room too.
            robot_notes = []
            robot_spec = plan_robot(world, grid, cached, post, request, seed, robot_notes, reading=reading,
                                    through=rooms, past=spots)
            robot_spec = _at_a_guiding_pace(post, preset, robot_spec, robot_notes)
            robot_notes.append(f"the robot passes {'through ' + ', '.join(rooms) if rooms else 'by the places'} on "
                               f"its way, where people react to it")
            reactor_notes = []
            unseen = place_robot_reactors(world, grid, post, robot_spec, seed, reactor_notes, passing_points(
                reading, post.groups, lambda p: _place_point(world, grid, p)))
        notes.extend(robot_notes)
        notes.extend(reactor_notes)
        _at_a_pace_the_robot_keeps(post, robot_spec)
        robot_spec = held_for_watchers(post, robot_spec, reading)  # "... look at the robot as it passes": once in place
        for g in unseen:
            notes.append(unplaced_note(world, g.label, g.spawn, g.reactor_zone, robot_spec.task,  # what kept them
                                       list(robot_spec.path) or [robot_spec.start, robot_spec.goal]))
    guided_for = _behind_the_guide_while_it_drives(post, robot_spec)
    # "two guards block the robot in the doorway": each holds a post where the robot passes the place
    blocker_posts = posts_for_blockers(world, grid, post.groups, post.agents, (
        list(robot_spec.path) or [robot_spec.start, robot_spec.goal]) if robot_spec is not None else None, notes)
    # "children in the playground approach the robot": each waits beside where the robot passes the place
    approach_posts = approach_at_place.posts_for_approachers(world, grid, post.groups, post.agents, (
        list(robot_spec.path) or [robot_spec.start, robot_spec.goal]) if robot_spec is not None else None, notes)
    fields: dict[str, VelocityField] = {}
    group_paths: dict[str, np.ndarray] = {}
    if preset.velocity == "field":
        if post.exit is None:
            raise GenerationError("the preset follows velocity fields to an exit, but the world has no exit")
        # One field per group and exit: a group whose members' nearest exits differ gets one per exit.
        followers: dict[str, list[AgentPlan]] = {}
        for a in post.agents:
            if a.field_id is not None:
                followers.setdefault(a.field_id, []).append(a)
        labels = {g.index: g for g in post.groups}
        for field_id, members in followers.items():
            _check_cancel(cancel)
            g = labels[members[0].group_index]
            exit_name = members[0].exit or post.exit
            exit_door = world.find(exit_name)
            assert isinstance(exit_door, Door), exit_name  # fields lead to exits, which are doors
            centroid = _free_centroid(grid, [a.start for a in members], g.spawn)
            try:
                built = cached.cache.field(world.name, planner, centroid, exit_door.position,
                                           start_label=f"group '{g.label}' in {g.spawn}", exit_label=exit_name)
            except PlanningError as exc:
                raise GenerationError(f"group '{g.label}' cannot reach exit {exit_name}: {exc}") from None
            fields[field_id] = built
            group_paths[field_id] = built.path

    agents: list[AgentSpec] = []
    trees: TreeFiles = {}
    keeping_out = _keep_out_planners(world, grid, post, cache, cached)
    groups_by_index = {g.index: g for g in post.groups}
    for a in post.agents:
        _check_cancel(cancel)
        assert a.document is not None  # post-processing gives every agent its tree document
        document = a.document.copy()  # planning edits its own copy: a re-plan starts from the same trees
        if a.group_index in guided_for:
            _set_guided_seconds(document, guided_for[a.group_index])
        set_post(document, blocker_posts.get(a.id))
        approach_at_place.set_post(document, approach_posts.get(a.id))
        react_once_there(document)  # a look as the robot passes, once they are there
        if preset.velocity == "waypoints" and preset.planner.enabled:
            around = keeping_out.get(a.group_index)
            try:
                if around is not None:
                    try:
                        # "..., avoiding the lifts": round them, when there is a way round
                        plan_waypoints(document, a.start, around, start_label=f"agent {a.id} in {a.spawn_zone}")
                    except PlanningError:
                        document = a.document.copy()
                        shunned = ", ".join(groups_by_index[a.group_index].places_shunned)
                        note = f"group '{a.label}': no way round {shunned}; it goes through"
                        notes.extend([] if note in notes else [note])
                        around = None
                if around is None:
                    plan_waypoints(document, a.start, cached, start_label=f"agent {a.id} in {a.spawn_zone}")
            except PlanningError as exc:
                raise GenerationError(f"agent {a.id} ({a.label}) cannot reach its goal: {exc}") from None
        goals = goals_from_tree(document)
        if a.field_id is not None and a.field_id in group_paths:
            # Field followers head along their group's path: record it as their goals.
            goals = [(float(p[0]), float(p[1])) for p in group_paths[a.field_id][1:]]
        rel = f"trees/agent_{a.id}.xml"
        document.source = rel  # what messages about it name
        trees[rel] = document
        agents.append(AgentSpec(
            id=a.id, group=a.sfm_group, start=a.start, goals=tuple((round(x, 3), round(y, 3)) for x, y in goals),
            zone=a.zone, tree=rel, radius=preset.agent_radius, max_vel=a.max_vel, label=a.label,
            behavior=a.behavior))
    return OperationalPlan(agents, trees, fields, robot_spec, notes)


def _keep_out_planners(world: World, grid: OccupancyGrid, post: PostProcessed, cache: PlanCache | None,
                       cached: CachedPlanner) -> dict[int, CachedPlanner]:
    """Per group index, a planner that goes round the places its sentence rules out (groups that rule
    out none plan with the shared one)."""
    planners: dict[int, CachedPlanner] = {}
    for g in post.groups:
        if not g.places_shunned:
            continue
        planner = keep_out_planner(world, grid, g.places_shunned)
        if planner is not None:
            name = f"{world.name}~{'~'.join(sorted(g.places_shunned))}"  # its own cache entries
            planners[g.index] = CachedPlanner(name, planner, cache or cached.cache)
    return planners


def _check_cancel(cancel: threading.Event | None) -> None:
    if cancel is not None and cancel.is_set():
        raise Cancelled("generation cancelled during planning")


def _free_centroid(grid: OccupancyGrid, points: Sequence[Point], zone: str) -> Point:
    if not points:
        # A group with no members has no centre; the prompt checks refuse "zero people" before this.
        raise GenerationError(f"a group in {zone} has no people to lead to the exit")
    cx = sum(p[0] for p in points) / len(points)
    cy = sum(p[1] for p in points) / len(points)
    q = grid.nearest_free(cx, cy)
    if q is None:
        raise GenerationError(f"no free floor near the centre of the group in {zone}")
    # Snap to the nearest spawn when the centroid's free cell lies in another room (an L-shaped group).
    nearest = min(points, key=lambda p: math.dist(p, (cx, cy)))
    return (float(q[0]), float(q[1])) if math.dist(q, (cx, cy)) < 1.0 else nearest


def _resolve_point(world: World, grid: OccupancyGrid, value: Point | str, what: str) -> Point:
    if isinstance(value, str):
        try:
            obj = world.find(value)
        except Exception as exc:
            raise GenerationError(f"robot {what} {value!r}: {exc}") from None
        if isinstance(obj, Entity):
            p = obj.interaction_point
        elif isinstance(obj, Door):
            p = obj.inward_point(0.8)
        else:
            p = obj.anchor
    else:
        p = (float(value[0]), float(value[1]))
    q = grid.nearest_free(p[0], p[1], max_dist=1.0)
    if q is None:
        raise GenerationError(f"robot {what} ({p[0]:.2f}, {p[1]:.2f}) is not on free floor")
    return (round(float(q[0]), 3), round(float(q[1]), 3))


def plan_robot(world: World, grid: OccupancyGrid, planner: CachedPlanner, post: PostProcessed, request: RobotRequest,
               seed: int, notes: list[str], reading: PromptReading | None = None,
               through: Sequence[str] = (), past: Sequence[Point] = ()) -> RobotSpec:
    """The robot's start, goal, path and task; a crossing or patrolling robot also passes through the
    zones `through` (where people who react to it are and its route did not come by) and by the points
    `past` (the doors and things they react at, spots_to_pass.py).

    The user's --robot-start/--robot-goal come first, then the sentence's robot clause (its start,
    destination, the places it passes, where it waits, whom it follows); what neither fixes is chosen
    so the robot crosses the scene: from one side of the crowd to the other, through where people are
    (or past the people who react to it). Every start is on free floor at least ROBOT_CLEARANCE from
    every person and outside the zones being evacuated, unless the user or the sentence puts it there.
    Queues and conversation circles the trees will form are obstacles for the robot's planner
    (`formations.py`): it passes them with PASSING_MARGIN to spare, or through them only when there
    is no other way (a note says so).
    """
    asked = reading.robot if reading is not None else None
    task = asked.task if asked is not None else "cross"
    reactors = _reactor_ids(post)
    people = [a.start for a in post.agents if a.id not in reactors]
    robot_radius = RobotSpec((0.0, 0.0), (0.0, 0.0)).radius
    clearance = robot_radius + PASSING_MARGIN
    formations = predict_formations(world, grid, [a.document for a in post.agents if a.document is not None],
                                    post.goals)
    named = [p for p in (request.start, request.goal) if p is not None]
    fixed = [_resolve_point(world, grid, p, what) for p, what in ((request.start, "start"), (request.goal, "goal"))
             if p is not None and not isinstance(p, str)]
    # A start or goal the user put inside a formation (the robot delivers to the counter): that one is not an obstacle.
    formations = [f for f in formations if not any(f in formations_at(formations, q, clearance) for q in fixed)]
    named_places = {world.zone_of_place(p) for p in named if isinstance(p, str)}
    if asked is not None:
        named_places |= {world.zone_of_place(p) for p in (asked.start, asked.location, asked.destination) if p}
    for place in [p for p in named if isinstance(p, str)] + ([asked.destination, asked.location] if asked else []):
        if place:
            point = _place_point(world, grid, place)
            if point is not None:
                formations = [f for f in formations if f not in formations_at(formations, point, clearance)]
    # "drives through the queue": the queue the robot is sent through is no obstacle; it passes by its gap
    formations, gaps = through_formations(reading, world, grid, formations)
    # "..., avoiding the cafeteria": its path goes round the places its clause keeps out of (robot_keep_out.py)
    kept_out = robot_kept_out(world, asked)
    around = keep_out_planner(world, grid, kept_out) if kept_out else None
    robot_planner = ThetaStarPlanner(block_formations(around.grid if around is not None else grid, formations,
                                                      clearance)) if formations else None
    space = FreeSpace(world, grid)
    guided_zone = _guided_zone(world, reading, post) if task == "cross" else None
    evacuated = _evacuated_zones(post) - named_places - {guided_zone}
    picker = _StartPicker(world, grid, space, people, robot_planner, evacuated | (kept_out_zones(world, kept_out)
                                                                                  - named_places), notes)
    through = [r for r in through if r not in kept_out]  # people who react there: not where it may not go

    def plan_path(a: Point, b: Point, may_cross: bool = True) -> np.ndarray:
        if robot_planner is not None:
            try:
                return robot_planner.plan(a, b, start_label="robot start", goal_label="robot goal")
            except PlanningError:
                if not may_cross:
                    raise
        if around is not None:
            try:
                found: np.ndarray = around.plan(a, b, start_label="robot start", goal_label="robot goal")
                return found
            except PlanningError:
                pass  # no way round: the plain path, and keep_out_notes say so once the path is set
        path: np.ndarray = planner.plan(a, b, start_label="robot start", goal_label="robot goal")
        if robot_planner is not None:
            crossed = [f.describe() for f in formations
                       if nearest_formation_gap([f], [tuple(p) for p in path]) < clearance]
            note = f"the robot's path passes close to {', '.join(crossed)}: there is no way around"
            if crossed and note not in notes:
                notes.append(note)
        return path

    # "carries books from the returns desk to the reading room": to the desk first, a stop, then on
    errand = robot_errand(asked) if request.start is None and request.goal is None else None
    errand_spec = errand_robot(world, picker, lambda p: _place_point(world, grid, p), plan_path, errand, notes,
                               lambda path, a, b: _through(world, path, (), through, picker, plan_path, a, b)) \
        if errand is not None else None
    if errand_spec is not None:
        return _kept_out_noted(world, kept_out, errand_spec, notes)
    follows: tuple[int, ...] = ()
    if task == "follow":
        follows = _followed(reading, post)
    guided_out = guided_exit(reading, post.groups, post.agents) if reading is not None and task == "cross" else None
    # Where the sentence or the user puts the robot's goal.
    goal: Point | None = None
    if request.goal is not None:
        goal = _request_point(world, grid, request.goal, "goal", picker)
    elif asked is not None and task in ("cross", "patrol") and (asked.destination or guided_out is not None):
        # a robot that guides people goes to the exit they take, not one picked for its words alone
        guided = guided_out
        if guided is not None and asked.destination and guided != asked.destination:
            notes.append(f"the robot goes to {guided}, the exit of the people it guides (its clause read "
                         f"{asked.destination})")
        goal = _place_point(world, grid, guided or asked.destination or "")
    elif asked is not None and task == "patrol" and asked.location and asked.via:
        # "patrols between the entrance and the reading tables": its round runs from one to the other
        goal = _place_point(world, grid, asked.location)
    led = _followers_way(reading) if task == "cross" and guided_out is None and \
        (asked is None or not (asked.start or asked.destination)) else None
    if goal is None and led is not None and led[1] is not None:
        # "three students follow the robot from the foyer to the computer lab": the robot leads them there
        goal = _place_point(world, grid, led[1])
    start: Point | None = None
    if request.start is not None:
        start = _request_point(world, grid, request.start, "start", picker)
        picker.check(start, "the start you gave")
    elif asked is not None and asked.start:
        start = picker.pick(asked.start, towards=None, away_from=goal)
    elif led is not None and led[0] is not None:
        start = picker.pick(led[0], towards=None, away_from=goal)
    elif asked is not None and task == "wait" and (asked.location or asked.destination):
        start = picker.pick(asked.location or asked.destination or "", towards=None)
    elif guided_zone is not None:
        # "the staff in the kitchen evacuate while the robot guides them out": it sets off from among them
        start = picker.pick(guided_zone, towards=None, away_from=goal)
    elif asked is not None and asked.via and task in ("cross", "patrol"):
        # "crosses the ticket hall to the platforms": from the far side of the hall; "drives through the
        # queue": from the next room, so it passes the people there (robot_passing.py)
        if goal is None and task == "cross" and not _is_spot(world, asked.via[0]) and world.zone_of_place(asked.via[0]):
            # nowhere named to go: out by the door across the room, so it sets off from the far wall
            zone = world.zone_of_place(asked.via[0]) or ""
            goal = crossing_goal(world, picker, zone, picker.space.cells(zone))
        before = zone_before(world, asked.via[0], goal) if people_stay_in(reading, world, asked.via[0]) else None
        start = picker.pick(before or asked.via[0], towards=None, away_from=goal)
        if before is None and task == "cross" and goal is not None and not _is_spot(world, asked.via[0]):
            start = crossing_start(world, picker, world.zone_of_place(asked.via[0]) or "", goal) or start
        if _is_spot(world, asked.via[0]) and before is None:
            # "passes the desk": it sets off away from the desk and ends on its far side (passed_spot.py)
            start, goal = ends_off_the_spot(world, picker, _place_point(world, grid, asked.via[0]), start, goal)
            assert start is not None
    elif task == "follow" and follows:
        rows = [a.start for a in post.agents if a.id in follows]
        centre = (sum(p[0] for p in rows) / len(rows), sum(p[1] for p in rows) / len(rows))
        start = picker.nearest(centre)
    elif asked is not None and task == "patrol" and asked.location:
        start = picker.pick(asked.location, towards=None)
        goal = goal or picker.pick(asked.location, towards=None, away_from=start)

    if request.goal is None and task == "cross":  # "leads a family to the exit": the nearest of those that fit
        # its start as it would set off for the exit the reader picked (a pair across the scene for no exit
        # set off from a restroom, and twenty followers stood ahead of it on its way out)
        start, goal = nearest_exit(world, reading, start, goal, lambda: _chosen_pair(
            world, grid, post, people, seed, picker, reactors, plan_path, None, goal)[0],
            lambda p: _place_point(world, grid, p), plan_path, notes)
    if task in ("wait", "follow"):
        if start is None:
            start = _chosen_pair(world, grid, post, people, seed, picker, reactors, plan_path, None, None)[0]
        return _kept_out_noted(world, kept_out, RobotSpec(start=start, goal=start, path=(start,), task=task,
                                                          follows=follows), notes)

    via = asked.via if asked is not None else ()
    via_zones = [z for z in (world.zone_of_place(v) for v in via if not _is_spot(world, v)) if z]
    # "via the fountain": a thing or a door is passed by its own point (where the report checks it), not
    # anywhere in the zone it stands in
    via_spots = [p for p in (_place_point(world, grid, v) for v in via if _is_spot(world, v)) if p is not None]
    via_spots += beside_points(reading, world, formations, robot_planner.grid if robot_planner else grid)  # "drives past them": by the line's first and last places
    via_spots = beside(via_spots, formations, clearance, robot_planner.grid if robot_planner else None)  # not into a queue
    via_spots += gaps
    via_spots += [p for p in past if p not in via_spots]
    if start is None or goal is None:
        start, goal, path = _chosen_pair(world, grid, post, people, seed, picker, reactors, plan_path, start, goal)
        if not via_zones and not via_spots and not through:
            return _kept_out_noted(world, kept_out, RobotSpec(start=start, goal=goal, path=_rounded(path), task=task),
                                   notes)
    try:
        path = plan_path(start, goal)
        path = _through(world, path, via_zones, through, picker, plan_path, start, goal, via_spots)
    except PlanningError as exc:
        raise GenerationError(f"the robot cannot reach its goal: {exc}") from None
    return _kept_out_noted(world, kept_out, RobotSpec(start=start, goal=goal, path=_rounded(path), task=task), notes)


def _kept_out_noted(world: World, kept_out: Sequence[str], spec: RobotSpec, notes: list[str]) -> RobotSpec:
    """The robot's plan, with a note for each place it is to keep out of that it starts in, ends in or goes
    through (no way round): said, never hidden."""
    route = [(float(p[0]), float(p[1])) for p in spec.path] or [spec.start, spec.goal]
    notes.extend(n for n in keep_out_notes(world, kept_out, route) if n not in notes)
    return spec


def _followers_way(reading: PromptReading | None) -> tuple[str | None, str | None] | None:
    """Where people who follow the robot say it leads them: (from, to) of the first follower group that
    names a place to go, None when none does."""
    for group in reading.groups if reading is not None else ():
        if group.robot_interaction == "follow" and group.destination:
            return group.start, group.destination
    return None


def _is_spot(world: World, name: str) -> bool:
    """Whether a place is a thing or a door (a point to pass by), not a zone."""
    try:
        return isinstance(world.find(name), (Entity, Door))
    except WorldError:  # an unknown name, or an alias several places share: no point to pass by
        return False


def _through(world: World, path: np.ndarray, via: Sequence[str], rooms: Sequence[str], picker: _StartPicker,
             plan_path: Callable[[Point, Point, bool], np.ndarray], start: Point, goal: Point,
             spots: Sequence[Point] = ()) -> np.ndarray:
    """The path, made to pass through every zone of `via` it misses (by the zone's free point nearest to
    the way from start to goal), by every point of `spots` it does not come within VIA_SPOT_NEAR of,
    and into every room of `rooms` it misses (a few metres in by the door nearest to it, and out again),
    the stops in their order along the path."""
    stops = [picker.via_point(z, start, goal) for z in via if not _passes(world, path, z)]
    samples, _ = _along(np.asarray(path, dtype=float).reshape(-1, 2), 0.5)
    stops += [p for p in spots if float(np.min(np.hypot(samples[:, 0] - p[0], samples[:, 1] - p[1]))) > VIA_SPOT_NEAR]
    stops += [picker.entry_point(z, path) for z in rooms if not _passes(world, path, z)]
    if not stops:
        return path
    samples, arcs = _along(np.asarray(path, dtype=float).reshape(-1, 2), 0.5)
    stops.sort(key=lambda p: float(arcs[int(np.argmin(np.hypot(samples[:, 0] - p[0], samples[:, 1] - p[1])))]))
    legs = [plan_path(a, b, True) for a, b in zip([start, *stops], [*stops, goal])]
    return np.concatenate([legs[0], *(leg[1:] for leg in legs[1:])])


def _passes(world: World, path: np.ndarray, zone: str) -> bool:
    """Whether a path goes through a zone (its vertices, or points every half metre along it)."""
    points, _ = _along(np.asarray(path, dtype=float).reshape(-1, 2), 0.5)
    polygon = world.zone(zone).polygon
    return bool(shapely.contains_xy(polygon, points[:, 0], points[:, 1]).any())


def _rounded(path: np.ndarray) -> tuple[Point, ...]:
    return tuple((round(float(x), 3), round(float(y), 3)) for x, y in path)


def _chosen_pair(world: World, grid: OccupancyGrid, post: PostProcessed, people: Sequence[Point], seed: int, picker: _StartPicker,
                 reactors: set[int], plan_path: Callable[[Point, Point, bool], np.ndarray], fixed_start: Point | None,
                 fixed_goal: Point | None) -> tuple[Point, Point, np.ndarray]:
    """A start/goal pair across the scene: longest (up to 20 m) and passing closest to the crowd's
    centre, or to the people who react to the robot when some do."""
    candidates = [c for c in _robot_candidates(world, grid, post, people, seed) if picker.acceptable(c)]
    if not candidates:
        candidates = [c for c in _robot_candidates(world, grid, post, people, seed, evacuated=set()) if
                      picker.free(c)] or _robot_candidates(world, grid, post, people, seed, evacuated=set())
    # past the people who react to it where the sentence puts them, else through the crowd
    placed = {g.index for g in post.groups if getattr(g, "reactor_zone", None)}
    staying = reacting_points(post.agents, skip=reactors)  # people reacting around a routine: where they stay
    staying = along_their_queues(staying, predict_formations(  # a queue's people along it, not all at its head
        world, grid, [a.document for a in post.agents if a.document is not None], post.goals))
    focus = [a.start for a in post.agents if a.id in reactors and a.group_index in placed] + staying or \
        list(people) or [a.start for a in post.agents]
    centre = (sum(p[0] for p in focus) / len(focus), sum(p[1] for p in focus) / len(focus))
    pairs = []
    firsts = [fixed_start] if fixed_start else candidates
    seconds = [fixed_goal] if fixed_goal else candidates
    for a in firsts:
        for b in seconds:
            if a == b:
                continue
            length = math.dist(a, b)
            if length < 4.0:
                continue
            # Crossing the crowd matters more than length; beyond 20 m a longer walk adds nothing.
            pairs.append((min(length, 20.0) - 3.0 * _point_segment_distance(centre, a, b), a, b))
    pairs.sort(key=lambda t: (-t[0], t[1], t[2]))
    if not pairs:
        raise GenerationError("no room for the robot: no two free points 4 m apart near the scene")
    # Every pair around the formations first; through one only when no pair can go around.
    for may_cross in (False, True):
        # a pair that passes them and goes on first, one that ends beside them after (goes_on_past.py)
        for tried, settle in ends_off(pairs, staying) if fixed_start is None and fixed_goal is None else [(pairs, True)]:
            best: tuple[float, Point, Point, np.ndarray] | None = None
            for _, a, b in tried[:20]:
                try:
                    path = plan_path(a, b, may_cross)
                except PlanningError:
                    continue
                gap = widest_gap(path, staying)  # past everyone who reacts to it, the first pair that does
                if gap <= PASS_NEAR:
                    return goes_on(a, b, path, staying, candidates, plan_path, may_cross) if settle else (a, b, path)
                best = best if best is not None and best[0] <= gap else (gap, a, b, path)
            if best is not None and settle:
                return goes_on(best[1], best[2], best[3], staying, candidates, plan_path, may_cross)
    raise GenerationError("no reachable start/goal pair for the robot near the scene")


class _StartPicker:
    """Free points for the robot: on free floor, ROBOT_CLEARANCE from every person, off queues and
    circles, outside the zones being evacuated."""

    def __init__(self, world: World, grid: OccupancyGrid, space: FreeSpace, people: Sequence[Point],
                 robot_planner: ThetaStarPlanner | None, evacuated: set[str], notes: list[str]) -> None:
        self.world, self.grid, self.space, self.notes = world, grid, space, notes
        self.people = np.asarray(people, dtype=float).reshape(-1, 2)
        self.robot_planner = robot_planner
        self.evacuated = evacuated

    def clearance(self, points: np.ndarray) -> np.ndarray:
        if not len(self.people):
            return np.full(len(points), np.inf)
        nearest: np.ndarray = np.min(np.hypot(points[:, None, 0] - self.people[None, :, 0],
                                              points[:, None, 1] - self.people[None, :, 1]), axis=1)
        return nearest

    def free(self, p: Point) -> bool:
        return self.robot_planner is None or bool(self.robot_planner.grid.is_free(*p))

    def acceptable(self, p: Point) -> bool:
        zone = self.world.zone_at(p[0], p[1])
        if zone is not None and zone.name in self.evacuated:
            return False
        return self.free(p) and float(self.clearance(np.asarray([p]))[0]) >= ROBOT_CLEARANCE

    def pick(self, place: str, towards: Point | None, away_from: Point | None = None) -> Point:
        """A point of `place` (a zone, or the zone of a door or thing) for the robot to start at."""
        zone = self.world.zone_of_place(place)
        if zone is None:
            raise GenerationError(f"robot place {place!r} is not a place of world '{self.world.name}'")
        pts = self.space.cells(zone)
        if not len(pts):
            raise GenerationError(f"zone '{zone}' has no free floor for the robot")
        room = self.clearance(pts)
        ok = room >= ROBOT_CLEARANCE
        if self.robot_planner is not None:
            ok &= np.array([self.robot_planner.grid.is_free(x, y) for x, y in pts], dtype=bool)
        if not ok.any():
            best = int(np.argmax(room))
            self.notes.append(f"the robot starts {room[best]:.1f} m from the nearest person: {zone} has no free floor "
                              f"{ROBOT_CLEARANCE:g} m from everyone")
            return (round(float(pts[best, 0]), 3), round(float(pts[best, 1]), 3))
        pts = pts[ok]
        if away_from is not None:
            # the far side of the place from `away_from`, but not wedged in a corner: of the points at
            # least 80 % as far as the farthest, the one nearest the place's anchor
            d = np.hypot(pts[:, 0] - away_from[0], pts[:, 1] - away_from[1])
            anchor = self.world.zone(zone).anchor
            far = np.flatnonzero(d >= 0.8 * d.max())
            k = int(far[np.argmin(np.hypot(pts[far, 0] - anchor[0], pts[far, 1] - anchor[1]))])
        else:
            anchor = towards or _place_point(self.world, self.grid, place) or self.world.zone(zone).anchor
            d = np.hypot(pts[:, 0] - anchor[0], pts[:, 1] - anchor[1])
            k = int(np.argmin(d))
        return (round(float(pts[k, 0]), 3), round(float(pts[k, 1]), 3))

    def _passable(self, zone: str) -> np.ndarray:
        """The zone's free floor the robot may drive over (off queues and circles when it can be)."""
        pts = self.space.cells(zone)
        if self.robot_planner is not None and len(pts):
            keep = np.array([self.robot_planner.grid.is_free(x, y) for x, y in pts], dtype=bool)
            pts = pts[keep] if keep.any() else pts
        if not len(pts):
            raise GenerationError(f"zone '{zone}' has no free floor for the robot to pass through")
        return pts

    def via_point(self, zone: str, a: Point, b: Point) -> Point:
        """A free point of `zone` (off queues and circles) nearest to the segment a-b."""
        pts = self._passable(zone)
        d = [_point_segment_distance((float(x), float(y)), a, b) for x, y in pts]
        k = int(np.argmin(d))
        return (round(float(pts[k, 0]), 3), round(float(pts[k, 1]), 3))

    def entry_point(self, zone: str, path: np.ndarray) -> Point:
        """A free point ENTRY_DEPTH metres into `zone` from its door nearest to `path`: where a robot
        passing by looks in."""
        doors = [d for d in self.world.doors_of(zone) if not d.exit] or self.world.doors_of(zone)
        if not doors:
            return self.via_point(zone, tuple(path[0]), tuple(path[-1]))
        samples, _ = _along(np.asarray(path, dtype=float).reshape(-1, 2), 0.5)
        door = min(doors, key=lambda d: float(np.min(np.hypot(samples[:, 0] - d.position[0],
                                                               samples[:, 1] - d.position[1]))))
        inside = door.inward_point(ENTRY_DEPTH) if door.zone == zone else door.outward_point(ENTRY_DEPTH)
        pts = self._passable(zone)
        k = int(np.argmin(np.hypot(pts[:, 0] - inside[0], pts[:, 1] - inside[1])))
        return (round(float(pts[k, 0]), 3), round(float(pts[k, 1]), 3))

    def nearest(self, centre: Point) -> Point:
        """The acceptable free point nearest to `centre` (the robot starts beside the people it follows)."""
        zone = self.world.zone_at(centre[0], centre[1])
        zones = [zone.name] if zone is not None else [z.name for z in self.world.zones]
        for name in zones + [z.name for z in self.world.zones if z.name not in zones]:
            pts = self.space.cells(name)
            if not len(pts):
                continue
            ok = self.clearance(pts) >= ROBOT_CLEARANCE
            if ok.any():
                pts = pts[ok]
                k = int(np.argmin(np.hypot(pts[:, 0] - centre[0], pts[:, 1] - centre[1])))
                return (round(float(pts[k, 0]), 3), round(float(pts[k, 1]), 3))
        raise GenerationError("no free floor for the robot 2 m from everyone")

    def check(self, p: Point, what: str) -> None:
        room = float(self.clearance(np.asarray([p]))[0])
        if room < ROBOT_CLEARANCE:
            self.notes.append(f"{what} for the robot is {room:.1f} m from the nearest person "
                              f"(a robot placed by GROVE keeps {ROBOT_CLEARANCE:g} m)")


def _request_point(world: World, grid: OccupancyGrid, value: Point | str, what: str, picker: _StartPicker) -> Point:
    """A user's --robot-start/--robot-goal: a point as given, a place name as a free point there."""
    if isinstance(value, str) and what == "start":
        try:
            obj = world.find(value)
        except Exception as exc:
            raise GenerationError(f"robot {what} {value!r}: {exc}") from None
        if not hasattr(obj, "interaction_point") and not hasattr(obj, "leads_to"):
            return picker.pick(value, towards=None)
    return _resolve_point(world, grid, value, what)


def _place_point(world: World, grid: OccupancyGrid, name: str) -> Point | None:
    """Where the robot goes for a place: a thing's interaction point, a point inside a door, a zone's anchor."""
    try:
        return _resolve_point(world, grid, name, "place")
    except GenerationError:
        return None


def _evacuated_zones(post: PostProcessed) -> set[str]:
    """Zones people are evacuated from: the robot does not start there."""
    zones: set[str] = set()
    for g in post.groups:
        if any(n.node == "FollowVelocityField" for n in g.tree.walk()):
            zones |= set(g.spawn_zones) or {g.spawn}
    return zones


def _reactor_ids(post: PostProcessed) -> set[int]:
    by_index = {g.index: g for g in post.groups}
    return {a.id for a in post.agents if getattr(by_index.get(a.group_index), "reacts_only", False)
            or getattr(by_index.get(a.group_index), "follows_robot", False)}


def _guided_groups(post: PostProcessed) -> list[GroupPlan]:
    """Groups the robot guides out before they walk out on their own (reconcile.py: not reacts_only)."""
    return [g for g in post.groups if g.follows_robot and not g.reacts_only]


def _guided_zone(world: World, reading: PromptReading | None, post: PostProcessed) -> str | None:
    """Where the people the robot guides are at first (their sentence's place, else their one spawn
    zone): the robot sets off from there, with them behind it."""
    index = guided_index(reading) if reading is not None else None
    group = next((g for g in _guided_groups(post) if g.reading_index == index), None)
    if group is None or reading is None:
        return None
    start = reading.groups[index].start if index is not None else None
    zone = world.zone_of_place(start) if start else None
    return zone or (group.spawn if not group.spawn_zones else None)


def _at_a_guiding_pace(post: PostProcessed, preset: Preset, robot: RobotSpec, notes: list[str]) -> RobotSpec:
    """A robot that leads an evacuation drives at GUIDING_VEL (a brisk walk, as far as the preset's
    people walk), not its service pace: evacuees kept behind a 0.8 m/s robot would leave slower than
    a guided evacuation needs to."""
    guided = [g for g in _guided_groups(post) if any(n.node == "FollowVelocityField" for n in g.tree.walk())
              or g.exit_asked or any(a.exit for a in post.agents if a.group_index == g.index)]
    pace = round(min(GUIDING_VEL, float(preset.max_vel)), 2)
    if robot.task != "cross" or not guided or pace <= robot.max_vel:
        return robot
    notes.append(f"the robot leads the evacuation at {pace:g} m/s (its usual top speed is {robot.max_vel:g} m/s)")
    return replace(robot, max_vel=pace)


def _behind_the_guide_while_it_drives(post: PostProcessed, robot: RobotSpec | None) -> dict[int, float]:
    """Group index -> seconds the guided keep behind the robot: as long as it drives to their exit,
    then they walk out on their own; with no robot they walk out at once. Their group's tree says so."""
    out: dict[int, float] = {}
    for g in _guided_groups(post):
        seconds = guided_seconds(robot.path or (robot.start, robot.goal), robot.max_vel) \
            if robot is not None and robot.task == "cross" else 0.1
        g.tree = _with_duration(g.tree, seconds)
        out[g.index] = seconds
    return out


def _set_guided_seconds(document: TreeDocument, seconds: float) -> None:
    for element in document.nodes():
        if element.id == "ApproachRobot":
            element.set("duration", f"{seconds:g}")


def _with_duration(tree: DraftNode, seconds: float) -> DraftNode:
    if tree.node == "ApproachRobot":
        return replace(tree, ports={**tree.ports, "duration": seconds})
    return replace(tree, children=tuple(_with_duration(c, seconds) for c in tree.children)) if tree.children else tree


def _followed(reading: PromptReading | None, post: PostProcessed) -> tuple[int, ...]:
    """The agents the robot follows: the group its clause names ("the robot follows the nurse"), else
    the first group of the sentence."""
    if reading is None or reading.robot is None or not post.groups:
        return ()
    text = {lemma(w) for w in words(reading.robot.follows or reading.robot.text)}
    best = None
    for g in post.groups:
        if g.reading_index is None or g.reading_index >= len(reading.groups):
            continue
        r = reading.groups[g.reading_index]
        names = {lemma(w) for w in words(r.who)} | {r.label, lemma(r.label)}
        if names & text - {"the", "a", "robot"}:
            best = g
            break
    if best is None and reading.robot.follows:
        return ()  # whom it follows is no group of the sentence: nobody to follow (the report says so)
    best = best or post.groups[0]
    return tuple(best.member_ids)


# A person the robot follows walks at most this share of the robot's top speed, so it can keep up (a
# pedestrian's 1.0-1.3 m/s against a base's 0.8: it fell behind half the time).
ROBOT_FOLLOWED_PACE = 0.9


def _at_a_pace_the_robot_keeps(post: PostProcessed, robot: RobotSpec) -> None:
    """The people a following robot follows walk at a pace it can keep, unless their sentence says they
    hurry; their group lists it as added (the sentence did not ask it)."""
    if robot.task != "follow" or not robot.follows:
        return
    pace = round(ROBOT_FOLLOWED_PACE * float(robot.max_vel), 3)
    followed = set(robot.follows)
    for g in post.groups:
        members = [a for a in post.agents if a.id in followed and a.group_index == g.index]
        if not members or g.speed_factor > 1.0 or all(a.max_vel <= pace for a in members):
            continue
        for a in members:
            a.max_vel = min(a.max_vel, pace)
        g.added.append(f"walks at {pace:g} m/s, a pace the robot can follow (its top speed is {robot.max_vel:g} m/s)")


# ---- people who react to the robot start where it passes -----------------------------------------

# (closest, farthest) metres from the robot's route, per reaction node: close enough for the
# reaction to show (an avoider must be inside its safe distance), not in the robot's way.
REACTOR_BAND = {"ApproachRobot": (3.0, 6.0), "BlockRobot": (3.0, 6.0), "AvoidRobot": (1.5, 2.5),
                "LookAtRobot": (2.0, 5.0)}
# reactors who react from where they stand keep their band from the whole route (a guard stood 0.2 m from a
# later leg of it); those who go to the robot (approach, block) only from their anchor: kept 3 m off every leg,
# a receptionist started 6 m from the desk she holds and the robot was past it before she got there
_GO_TO_IT = ("ApproachRobot", "BlockRobot")


def place_robot_reactors(world: World, grid: OccupancyGrid, post: PostProcessed, robot: RobotSpec | None, seed: int,
                         notes: list[str], at: dict[int, Point] | None = None) -> list[GroupPlan]:
    """Groups whose whole activity is reacting to the robot, and whom the sentence places nowhere, start
    beside its route, a third of the way along (so the robot reaches them early in a run), in sight of
    it: a reaction gated on the robot showing up must not depend on where a model happened to spawn them.
    Returns the groups with no free floor beside the route (they keep their start)."""
    groups = [g for g in post.groups if g.reacts_only or g.follows_robot]
    if not groups or robot is None:
        return []
    unseen: list[GroupPlan] = []
    path = np.asarray(robot.path if robot.path else (robot.start, robot.goal), dtype=float).reshape(-1, 2)
    samples, arcs = _along(path, 0.5)
    total = float(arcs[-1]) if len(arcs) else 0.0
    rng = np.random.default_rng([int(seed) & 0xFFFFFFFF, 0x5BE0CD19])
    space = FreeSpace(world, grid)
    sight = ThetaStarPlanner(grid, landmarks=0)
    taken = [a.start for a in post.agents if a.group_index not in {g.index for g in groups}]
    for g in groups:
        if g.follows_robot:
            placed_behind = _behind_the_robot(world, space, sight, path, samples, arcs, g, taken, rng)
            if placed_behind is not None:
                _start_at(world, post, g, placed_behind)
                taken += placed_behind
                notes.append(f"group '{g.label}': starts in {g.spawn} behind the robot's start, to follow it")
                continue
            if not g.reacts_only:
                continue  # guided people with no room behind the robot keep their start
        node = next((n.node for n in g.tree.walk() if n.node in REACTOR_BAND), "ApproachRobot")
        near, far = REACTOR_BAND[node]
        goes_to_it = any(n.node in _GO_TO_IT for n in g.tree.walk())
        order = np.argsort(np.abs(arcs - min(max(0.3 * total, 4.0), total)), kind="stable") if total else np.arange(1)
        if g.reactor_zone is not None:
            # the sentence puts them in a zone: the route's points nearest to it first
            polygon = world.zone(g.reactor_zone).polygon
            gap = shapely.distance(polygon, shapely.points(samples))
            order = np.lexsort((np.abs(arcs - min(max(0.3 * total, 4.0), total)), np.round(gap, 0)))
        if at and g.index in at:  # "as the robot passes the ticket desk": where it passes the desk (passing_place.py)
            order = nearest_first(samples, at[g.index])
        placed = None
        # the band the reaction needs first; in the sentence's zone, further off when the route passes by
        for widen in (0.0, 4.0) if g.reactor_zone is not None else (0.0,):
            for k in order[:300]:
                anchor = samples[k]
                found = _spots(world, space, sight, anchor, near, far + widen, robot.start, taken, g.count, rng,
                               g.reactor_zone, route=None if goes_to_it else samples)
                if found is not None:
                    placed = (found, float(arcs[k]) if total else 0.0)
                    break
            if placed is not None:
                break
        if placed is None:
            unseen.append(g)
            continue
        spots, along = placed
        _start_at(world, post, g, spots)
        taken += spots
        notes.append(f"group '{g.label}': starts in {g.spawn} beside the robot's route ({along:.0f} m along it), "
                     f"where it sees the robot come")
    return unseen


def _start_at(world: World, post: PostProcessed, g: GroupPlan, spots: Sequence[Point]) -> None:
    members = [a for a in post.agents if a.group_index == g.index]
    for agent, spot in zip(members, spots):
        agent.start = spot
        zone = world.zone_at(spot[0], spot[1])
        agent.spawn_zone = agent.zone = zone.name if zone is not None else agent.spawn_zone
    g.spawn = members[0].spawn_zone if members else g.spawn


FOLLOWERS_BEHIND = 5.0  # metres from the robot's start within which its followers start (widened if full)


def _behind_the_robot(world: World, space: FreeSpace, sight: ThetaStarPlanner, path: np.ndarray,
                      samples: np.ndarray, arcs: np.ndarray, g: GroupPlan, taken: Sequence[Point],
                      rng: np.random.Generator) -> list[Point] | None:
    """Spots for people who follow the robot: around its start and not ahead of it on its way (a
    group placed on the route ahead blocks it, and the robot crawls behind its own followers). Behind
    first; beside the start when the floor behind is too small; None when neither has room."""
    start = path[0]
    ahead = samples[int(np.searchsorted(arcs, 2.0))] if len(arcs) and arcs[-1] >= 2.0 else samples[-1]
    heading = ahead - start
    norm = float(np.hypot(*heading))
    direction = heading / norm if norm > 1e-6 else None
    origin = (float(start[0]), float(start[1]))
    for behind_only in (True, False) if direction is not None else (False,):
        for widen in (0.0, 3.0, 6.0):
            found = _spots(world, space, sight, start, 0.0, FOLLOWERS_BEHIND + widen, origin, taken, g.count, rng,
                           g.reactor_zone, direction if behind_only else None)
            if found is not None:
                return found
    return None


def _along(path: np.ndarray, step: float) -> tuple[np.ndarray, np.ndarray]:
    """Points every `step` metres along a polyline, and their distance along it."""
    if len(path) < 2:
        return path[:1].copy(), np.zeros(1)
    points, arcs, s = [path[0]], [0.0], 0.0
    for a, b in zip(path, path[1:]):
        length = float(np.hypot(*(b - a)))
        n = max(1, int(length // step))
        for i in range(1, n + 1):
            points.append(a + (b - a) * i / n)
            arcs.append(s + length * i / n)
        s += length
    return np.asarray(points), np.asarray(arcs)


def _spots(world: World, space: FreeSpace, sight: ThetaStarPlanner, anchor: np.ndarray, near: float, far: float,
           robot_start: Point, taken: Sequence[Point], count: int, rng: np.random.Generator,
           zone_name: str | None = None, behind: np.ndarray | None = None,
           route: np.ndarray | None = None) -> list[Point] | None:
    """`count` free spots `near`..`far` from `anchor`, in sight of it, clear of the robot's start and of
    `taken`; with `behind` (a unit heading), none ahead of the anchor along it."""
    if zone_name is None:
        zone = world.zone_at(float(anchor[0]), float(anchor[1]))
        if zone is None:
            return None
        zone_name = zone.name
    pts = space.cells(zone_name)
    if not len(pts):
        return None
    d = np.hypot(pts[:, 0] - anchor[0], pts[:, 1] - anchor[1])
    robot = np.hypot(pts[:, 0] - robot_start[0], pts[:, 1] - robot_start[1])
    ok = (d >= near) & (d <= far) & (robot >= ROBOT_CLEARANCE + 0.5)
    if behind is not None:
        ok &= (pts[:, 0] - anchor[0]) * behind[0] + (pts[:, 1] - anchor[1]) * behind[1] <= 0.0
    if route is not None:  # `near` from the whole route, not only from the anchor (passing_place.py)
        ok &= off_the_route(pts, route, near)
    if len(taken):
        others = np.asarray(taken, dtype=float)
        ok &= np.min(np.hypot(pts[:, None, 0] - others[None, :, 0], pts[:, None, 1] - others[None, :, 1]),
                     axis=1) >= 0.7
    idx = np.flatnonzero(ok)
    if idx.size < count:
        return None
    idx = idx[np.argsort(d[idx] + rng.uniform(0.0, 0.2, idx.size), kind="stable")]
    chosen: list[Point] = []
    for i in idx:
        p = (round(float(pts[i, 0]), 3), round(float(pts[i, 1]), 3))
        if all(math.dist(p, q) >= 0.7 for q in chosen) and sight.segment_is_free(p[0], p[1], float(anchor[0]),
                                                                                  float(anchor[1])):
            chosen.append(p)
            if len(chosen) == count:
                return chosen
    return None


def _robot_candidates(world: World, grid: OccupancyGrid, post: PostProcessed, starts: Sequence[Point], seed: int,
                      evacuated: set[str] | None = None) -> list[Point]:
    zones: list[str] = []
    for a in post.agents:
        for z in (a.spawn_zone, a.zone):
            if z and z not in zones:
                zones.append(z)
    for z in list(zones):
        for d in world.doors_of(z):
            other = d.leads_to if d.zone == z else d.zone
            if other in [zz.name for zz in world.zones] and other not in zones:
                zones.append(other)
    if evacuated is None:
        evacuated = _evacuated_zones(post)
    zones = [z for z in zones if z not in evacuated] or zones
    rng = np.random.default_rng([int(seed) & 0xFFFFFFFF, 0x3C6EF372])
    space = FreeSpace(world, grid)
    found: list[Point] = []
    per_zone = max(4, ROBOT_CANDIDATES // max(len(zones), 1))
    spawn_arr = np.asarray(starts, dtype=float).reshape(-1, 2)
    for z in zones:
        pts = space.cells(z)
        if len(pts) == 0:
            continue
        if len(spawn_arr):
            d = np.min(np.hypot(pts[:, None, 0] - spawn_arr[None, :, 0], pts[:, None, 1] - spawn_arr[None, :, 1]),
                       axis=1)
            pts = pts[d >= ROBOT_CLEARANCE]
        if len(pts) == 0:
            continue
        pick = rng.choice(len(pts), size=min(per_zone, len(pts)), replace=False)
        found += [(round(float(pts[i, 0]), 3), round(float(pts[i, 1]), 3)) for i in sorted(pick)]
    return found


def _point_segment_distance(p: Point, a: Point, b: Point) -> float:
    ax, ay = a
    dx, dy = b[0] - ax, b[1] - ay
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / length2))
    return math.hypot(p[0] - ax - t * dx, p[1] - ay - t * dy)
