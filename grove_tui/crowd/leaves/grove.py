"""GROVE nodes: the wrapped, id-free behaviors the model writes (paper, "Node Wrapping Strategy").

They act only through crowd intents. Multi-agent behaviors meet in the shared registries of
coordination.py (a queue owns its order, a conversation owns its spots).
"""

from __future__ import annotations

import math

import shapely

from collections.abc import Sequence

from grove_tui.crowd.context import Point, SimContext
from grove_tui.crowd.coordination import ARRIVAL_TOLERANCE, Conversation, FreeSpace, ServiceQueue
from grove_tui.crowd.leaves.base import RUNNING, SUCCESS, AgentStatefulAction, AgentSyncAction, QuietSpec
from grove_tui.crowd.sfm import MODE_FACE, MODE_FIELD, MODE_GOALS, MODE_STOP
from grove_tui.errors import BTError
from grove_tui.world.model import Door, World, Zone

EXIT_RADIUS = 0.6  # metres from the exit point at which an evacuee turns to walk out through the door
DOOR_PASS = 1.5  # metres beyond the door line an evacuee walks to; it is counted out on crossing the line
HUNAV_GOAL_TOLERANCE = 0.1  # IsGoalReached: goal radius + 0.1
STEP_ASIDE = 1.2  # metres a served person steps sideways out of the line
ASIDE_SPACING = 0.8  # metres between the spots served people step to
STUCK_AFTER = 5.0  # seconds without STUCK_HEADWAY metres of progress before a walker replans from where it stands
STUCK_AFTER_MAX = 40.0
STUCK_HEADWAY = 0.5
CIRCLE_APPROACH = 2.0  # metres outside a conversation circle's rim at which its members leave their walking group
GROUP_ID_BASE = 100000  # SFM group ids derived from agent ids, far from the scenario's own


def _go(sim: SimContext, row: int, route: Sequence[Point], goal_radius: float) -> None:
    crowd = sim.crowd
    crowd.set_goals(row, route, goal_radius=goal_radius)
    if crowd.mode[row] != MODE_GOALS:
        crowd.set_mode(row, MODE_GOALS)


def _stand(sim: SimContext, row: int) -> None:
    crowd = sim.crowd
    crowd.set_goals(row, [])
    if crowd.mode[row] != MODE_GOALS:
        crowd.set_mode(row, MODE_GOALS)


def _face(sim: SimContext, row: int, point: Sequence[float]) -> None:
    sim.crowd.set_face_target(row, (float(point[0]), float(point[1])))
    sim.crowd.set_mode(row, MODE_FACE)


class GoTo(AgentStatefulAction):
    """Walks [waypoints..., target]; SUCCESS within tolerance + 0.1 m of the target (HuNavSim's rule).

    The injected waypoints were planned from where the previous navigation ended; after an
    interruption (halt) the agent is somewhere else, so it replans from where it stands. So does an
    agent that has made no headway for a while: pushed off its line by a crowd or its walking
    group, it can stand against a wall with its next waypoint straight behind it (social forces have
    local minima); the checks back off (STUCK_AFTER, doubling) so a jam costs few replans. A member of
    a walking group that makes no headway walks on alone until it arrives: the group's coherence pulls
    it straight at the others, through the wall it is stuck behind, and holds them back for it.
    """

    __slots__ = ("target_point", "interrupted", "reach2", "check_at", "check_pos", "patience", "left_group")
    target_point: Point  # set by on_start
    interrupted: bool
    reach2: float
    check_at: float  # when on_running next checks its headway
    check_pos: Point  # where it stood at the last check
    patience: float
    left_group: int  # the SFM group it walked in before it got stuck and walked on alone, else -1

    def setup(self) -> None:
        super().setup()
        self.interrupted = False
        self.reach2 = 0.0
        self.check_at = math.inf
        self.check_pos = (0.0, 0.0)
        self.patience = STUCK_AFTER
        self.left_group = -1

    def on_start(self) -> int:
        sim = self.sim
        target = self.get_input("target")
        # x/y as GROVE writes them, else target_x/target_y as older HuNavSim 2.0 GoTo trees do
        x = self.get_input("x", self.get_input("target_x"))
        y = self.get_input("y", self.get_input("target_y"))
        point = sim.resolve_target(target, x, y, self.get_input("goal_id"))
        self.target_point = point
        tolerance = self.get_input("tolerance")
        self.reach2 = (tolerance + HUNAV_GOAL_TOLERANCE) ** 2
        p = sim.pos[self.row]
        sim.status[self.row] = f"going to {target or 'goal'}"
        if (p[0] - point[0]) ** 2 + (p[1] - point[1]) ** 2 <= self.reach2:
            sim.counters.reached_goals += 1
            sim.event("goal_reached", self.row, str(target or ""))
            return SUCCESS
        waypoints = self.get_input("waypoints") or ()
        if waypoints and not self.interrupted:
            route = [*waypoints, point]
        else:
            route = sim.rejoin(p, waypoints, point)
        _go(sim, self.row, route, tolerance)
        self.patience = STUCK_AFTER
        self._watch(p)
        return RUNNING

    def _watch(self, p: Sequence[float]) -> None:
        self.check_pos = (float(p[0]), float(p[1]))
        self.check_at = self.sim.clock.now + self.patience

    def on_running(self) -> int:
        sim = self.sim
        p = sim.pos[self.row]
        t = self.target_point
        if (p[0] - t[0]) ** 2 + (p[1] - t[1]) ** 2 <= self.reach2:
            self.interrupted = False
            self._rejoin_group()
            sim.counters.reached_goals += 1
            sim.event("goal_reached", self.row, str(self.get_input("target") or ""))
            return SUCCESS
        if sim.clock.now + 1e-9 >= self.check_at:
            if math.dist(p, self.check_pos) < STUCK_HEADWAY:
                # no headway: walk on from where it stands, back onto the route it can see, else a new plan
                group = int(sim.crowd.group[self.row])
                if group >= 0:
                    self.left_group = group
                    sim.crowd.set_group(self.row, -1)
                goals = sim.crowd.goals(self.row)
                _go(sim, self.row, sim.rejoin(p, goals[:-1], t), self.get_input("tolerance"))
                self.patience = min(2.0 * self.patience, STUCK_AFTER_MAX)
            else:
                self.patience = STUCK_AFTER
            self._watch(p)
        return RUNNING

    def _rejoin_group(self) -> None:
        if self.left_group >= 0:
            self.sim.crowd.set_group(self.row, self.left_group)
            self.left_group = -1

    def on_halted(self) -> None:
        self.interrupted = True
        self._rejoin_group()
        _stand(self.sim, self.row)

    def quiet_spec(self) -> QuietSpec | None:
        """(x, y, r2, t_end): poll() holds while the agent is farther than sqrt(r2) from (x, y) and
        the clock is before t_end; lets the simulation check all quiet agents at once in numpy."""
        return (self.target_point[0], self.target_point[1], self.reach2, self.check_at)

    def poll(self) -> bool:
        """Side-effect-free: would on_running return RUNNING and change nothing (not arrived, no check due)?"""
        sim, row, t = self.sim, self.row, self.target_point
        dx = sim.px[row] - t[0]
        dy = sim.py[row] - t[1]
        return dx * dx + dy * dy > self.reach2 and sim.clock.now + 1e-9 < self.check_at


class Wait(AgentStatefulAction):
    __slots__ = ()

    def poll(self) -> bool:
        return self.on_running() == RUNNING  # on_running only reads the clock

    def quiet_spec(self) -> QuietSpec | None:
        return (0.0, 0.0, -1.0, self.started_at + self.get_input("duration") - 1e-9)

    def on_start(self) -> int:
        sim = self.sim
        self.started_at = sim.clock.now
        sim.crowd.set_goals(self.row, [])
        sim.crowd.set_mode(self.row, MODE_STOP)
        sim.status[self.row] = "waiting"
        return self.on_running()

    def on_running(self) -> int:
        return SUCCESS if self.elapsed() + 1e-9 >= self.get_input("duration") else RUNNING


class Queue(AgentStatefulAction):
    """Joins the line at a service point, advances slot by slot, is served at the head, steps aside."""

    __slots__ = ("queue", "slot", "arrived", "slot_point")
    queue: ServiceQueue  # joined by on_start
    slot: int
    arrived: bool
    slot_point: Point

    def setup(self) -> None:
        super().setup()
        self.slot = -1
        self.arrived = False
        self.slot_point = (0.0, 0.0)

    def on_start(self) -> int:
        sim = self.sim
        name = self.get_input("service_point")
        point = sim.resolve_target(name, self.get_input("x"), self.get_input("y"))
        self.queue = sim.queues.join(name, point, self.get_input("spacing"), self.get_input("service_time"), self.row)
        self.slot = -1
        self.arrived = False
        sim.status[self.row] = f"joining the queue at {name}"
        sim.event("queue_join", self.row, name)
        return RUNNING

    def on_running(self) -> int:
        sim, queue, row = self.sim, self.queue, self.row
        k = queue.position_of(row)
        if k is None:
            return RUNNING  # joined this tick; the registry orders same-tick arrivals at the end of the tick
        p = sim.pos[row]
        if k != self.slot:
            if 0 <= k < self.slot:
                sim.event("queue_advance", row, queue.name)  # moved up the line: the queue advances
            self.slot = k
            self.arrived = False
            self.slot_point = queue.slot_point(k)
            far = math.dist(p, self.slot_point) > 2.0
            _go(sim, row, sim.plan(p, self.slot_point) if far else [self.slot_point], 0.1)
            sim.status[row] = f"in the queue at {queue.name}, place {k + 1}"
        if not self.arrived and math.dist(p, self.slot_point) <= ARRIVAL_TOLERANCE:
            # the slot stays the agent's goal: standing agents are pushed by their neighbours and
            # the goal force pulls them back, so the line keeps its spacing
            self.arrived = True
        if k == 0 and self.arrived:
            now = sim.clock.now
            if queue.head_since is None:
                queue.head_since = now
                sim.status[row] = f"being served at {queue.name}"
            elif now - queue.head_since + 1e-9 >= queue.service_time:
                queue.leave(row)
                queue.served += 1
                sim.counters.served += 1
                sim.event("queue_served", row, queue.name)
                sim.status[row] = f"served at {queue.name}"
                _go(sim, row, [aside_spot(sim, queue)], 0.3)
                return SUCCESS
        return RUNNING

    def on_halted(self) -> None:
        self.queue.step_out(self.row, self.sim.clock.now)  # halted while RUNNING: on_start joined it
        _stand(self.sim, self.row)

    def poll(self) -> bool:
        """RUNNING with nothing to do: same place in line, not arriving now, not at the head."""
        k = self.queue.position_of(self.row)
        if k is None:
            return True
        if k != self.slot or k == 0:
            return False
        sim, row, slot = self.sim, self.row, self.slot_point
        return self.arrived or math.hypot(sim.px[row] - slot[0], sim.py[row] - slot[1]) > ARRIVAL_TOLERANCE


def aside_spot(sim: FreeSpace, queue: ServiceQueue) -> Point:
    """A free spot beside the line, away from where earlier served people stand: everyone stepping
    to one spot would pile up next to the head of the line for the rest of the run.

    `sim` needs only is_free and nearest_free, so generation can predict the spots on its grid."""
    sx, sy = queue.service_point
    dx, dy = queue.direction
    first: Point | None = None
    for ring in range(6):
        out = STEP_ASIDE + ASIDE_SPACING * ring
        for back in (0.0, ASIDE_SPACING):  # beside the head, or half a step back along the line
            for sign in (1.0, -1.0):
                x = sx - sign * dy * out + dx * back
                y = sy + sign * dx * out + dy * back
                if not sim.is_free(x, y):
                    continue
                first = first or (x, y)
                if all(math.dist((x, y), q) >= ASIDE_SPACING for q in queue.aside):
                    queue.aside.append((x, y))
                    return (x, y)
    spot = first or sim.nearest_free(sx - dy * STEP_ASIDE, sy + dx * STEP_ASIDE)
    queue.aside.append(spot)
    return spot


class FollowVelocityField(AgentStatefulAction):
    """Follows the group's field to the exit door, then walks out through its opening.

    Near the door (EXIT_RADIUS of the exit point) the agent heads for a point DOOR_PASS beyond the
    door line, so it squeezes through the real opening like everyone else; the simulation deactivates
    and counts it only once its centre is outside the building (Simulation._count_people_outside).
    Removing people at the exit point, still inside, drained doors several times faster than real
    ones (issue 19). Without a world (no door line) the exit point itself is where the agent leaves.
    Without a field (a scenario planned with waypoints) it walks the planned path to the exit instead.
    """

    __slots__ = ("exit_point", "door", "passing")
    exit_point: Point
    door: Door | None  # None without a world: the exit point is where the agent leaves
    passing: bool

    def setup(self) -> None:
        super().setup()
        self.exit_point = (0.0, 0.0)
        self.door = None
        self.passing = False

    def on_start(self) -> int:
        sim, row = self.sim, self.row
        if not sim.crowd.active[row]:
            return SUCCESS  # already out of the building (a tree may say "leave" twice): counted once
        field_id = self.get_input("field")
        if field_id is None and len(sim.fields) == 1:
            field_id = next(iter(sim.fields))
        exit_name = self.get_input("exit")
        slot = sim.fields.get(field_id) if field_id is not None else None
        if field_id is not None and slot is None:
            raise BTError(f"{self.path} FollowVelocityField: field {field_id!r} is not in the scenario "
                          f"(fields: {', '.join(sim.fields) or 'none'})")
        if slot is not None:
            self.exit_point = sim.field_exits.get(field_id) or sim.resolve_target(exit_name, self.get_input("x"),
                                                                                   self.get_input("y"))
            sim.crowd.set_field(row, slot)
            sim.crowd.set_mode(row, MODE_FIELD)
        else:
            self.exit_point = sim.resolve_target(exit_name, self.get_input("x"), self.get_input("y"))
            _go(sim, row, sim.plan(sim.pos[row], self.exit_point), 0.3)
        self.door = exit_door_near(sim.world, self.exit_point)
        self.passing = False
        sim.status[row] = f"evacuating through {exit_name}"
        return self.on_running()

    def on_running(self) -> int:
        sim, row = self.sim, self.row
        if not sim.crowd.active[row]:
            return SUCCESS  # counted by the simulation when its centre crossed the door line
        if self.passing:
            return RUNNING
        if math.dist(sim.pos[row], self.exit_point) > EXIT_RADIUS:
            return RUNNING
        if self.door is not None:
            # Through the opening: the walls beside it hold, so the door's width sets the flow.
            _go(sim, row, [self.door.outward_point(DOOR_PASS)], 0.3)
            self.passing = True
            return RUNNING
        sim.crowd.set_active(row, False)
        sim.counters.evacuated += 1
        sim.event("evacuated", row, str(self.get_input("exit") or ""))
        sim.status[row] = "evacuated"
        return SUCCESS

    def on_halted(self) -> None:
        self.passing = False
        self.sim.crowd.set_mode(self.row, MODE_STOP)

    def quiet_spec(self) -> QuietSpec | None:
        if self.passing:
            return (0.0, 0.0, -1.0, math.inf)  # nothing left to decide: the outline check counts it
        return (self.exit_point[0], self.exit_point[1], EXIT_RADIUS * EXIT_RADIUS, math.inf)

    def poll(self) -> bool:
        sim, row, e = self.sim, self.row, self.exit_point
        if self.passing:
            return True
        return math.hypot(sim.px[row] - e[0], sim.py[row] - e[1]) > EXIT_RADIUS


def exit_door_near(world: World | None, point: Point) -> Door | None:
    """The exit door whose opening is within reach of `point` (the exit RoI may be its centre or just inside)."""
    if world is None:
        return None
    best: Door | None = None
    best_distance = math.inf
    for door in world.exits():
        distance = math.dist(door.position, point)
        if distance <= door.width / 2.0 + EXIT_RADIUS + 0.5 and distance < best_distance:
            best, best_distance = door, distance
    return best


class Wander(AgentStatefulAction):
    """Random reachable spots inside a zone, one after another with short pauses, for `duration`."""

    __slots__ = ("zone", "goal", "pause_until")
    zone: Zone  # set by on_start
    goal: Point  # set by on_start (_next_goal)
    pause_until: float

    def setup(self) -> None:
        super().setup()
        self.pause_until = -1.0

    def on_start(self) -> int:
        sim = self.sim
        name = self.get_input("zone")
        if sim.world is None:
            raise BTError(f"{self.path} Wander: needs the world to know zone {name!r}")
        try:
            found = sim.world.find(name)
        except Exception as exc:
            raise BTError(f"{self.path} Wander: {exc}") from None
        if isinstance(found, Zone):
            zone = found
        elif found.zone is not None:
            zone = sim.world.zone(found.zone)
        else:
            raise BTError(f"{self.path} Wander: {name!r} is in no zone to wander in")
        self.zone = zone
        self.started_at = sim.clock.now
        self.pause_until = -1.0
        sim.status[self.row] = f"wandering in {zone.name}"
        self._next_goal()
        return RUNNING

    def _next_goal(self) -> None:
        sim = self.sim
        polygon = self.zone.polygon
        xmin, ymin, xmax, ymax = polygon.bounds
        p = sim.pos[self.row]
        hidden: Point | None = None  # a reachable spot out of sight, used only if no spot in sight turns up
        for _ in range(8):
            xs = sim.rng.uniform(xmin, xmax, 32)
            ys = sim.rng.uniform(ymin, ymax, 32)
            inside = shapely.contains_xy(polygon, xs, ys)
            for x, y in zip(xs[inside], ys[inside]):
                if sim.is_free(x, y) and math.dist(p, (x, y)) > 1.0:
                    if sim.sees(p, (x, y)):
                        self.goal = (float(x), float(y))
                        _go(sim, self.row, [self.goal], 0.3)
                        return
                    hidden = hidden or (float(x), float(y))
        self.goal = hidden or self.zone.anchor
        _go(sim, self.row, sim.plan(p, self.goal), 0.3)

    def on_running(self) -> int:
        sim = self.sim
        duration = self.get_input("duration")
        now = sim.clock.now
        if duration > 0 and now - self.started_at + 1e-9 >= duration:
            _stand(sim, self.row)
            return SUCCESS
        if self.pause_until >= 0:
            if now >= self.pause_until:
                self.pause_until = -1.0
                self._next_goal()
            return RUNNING
        if math.dist(sim.pos[self.row], self.goal) <= 0.4:
            sim.counters.reached_goals += 1
            self.pause_until = now + float(sim.rng.uniform(1.0, 4.0))
            _stand(sim, self.row)
        return RUNNING

    def on_halted(self) -> None:
        _stand(self.sim, self.row)

    def quiet_spec(self) -> QuietSpec | None:
        duration = self.get_input("duration")
        end = self.started_at + duration - 1e-9 if duration > 0 else math.inf
        if self.pause_until >= 0:
            return (0.0, 0.0, -1.0, min(self.pause_until, end))
        return (self.goal[0], self.goal[1], 0.16, end)

    def poll(self) -> bool:
        duration = self.get_input("duration")
        now = self.sim.clock.now
        if duration > 0 and now - self.started_at + 1e-9 >= duration:
            return False
        if self.pause_until >= 0:
            return now < self.pause_until
        sim, row, goal = self.sim, self.row, self.goal
        return math.hypot(sim.px[row] - goal[0], sim.py[row] - goal[1]) > 0.4


class JoinGroup(AgentSyncAction):
    """Same SFM group as the draft group's other members; everyone walks at the slowest member's pace."""

    __slots__ = ()

    def tick(self) -> int:
        sim, row = self.sim, self.row
        agent_id = sim.ids[row]
        members = self.get_input("members") or sim.members_of(agent_id)
        rows = [sim.row_of[m] for m in members if m in sim.row_of]
        group_id = self.get_input("group_id")
        if group_id is None:
            group_id = GROUP_ID_BASE + min(members, default=agent_id)
        sim.crowd.set_group(row, int(group_id))
        if rows:
            sim.crowd.set_speed(row, min(sim.base_speed[r] for r in rows))
        sim.status[row] = f"with a group of {len(rows)}"
        return SUCCESS


class Converse(AgentStatefulAction):
    """Conversation circle at the target: walk to the assigned spot, face the centre, talk once all arrived."""

    __slots__ = ("conv", "spot", "ready", "interrupted", "group", "near")
    conv: Conversation  # joined by on_start
    spot: Point
    ready: bool
    interrupted: bool
    group: int
    near: bool  # within CIRCLE_APPROACH of the circle's rim: out of its walking group, bound for its spot

    def setup(self) -> None:
        super().setup()
        self.spot = (0.0, 0.0)
        self.ready = False
        self.interrupted = False
        self.group = -1
        self.near = False

    def on_start(self) -> int:
        sim, row = self.sim, self.row
        centre = sim.resolve_target(self.get_input("target"), self.get_input("x"), self.get_input("y"))
        agent_id = sim.ids[row]
        members = tuple(self.get_input("members") or sim.members_of(agent_id))
        rows = {sim.row_of[m] for m in members if m in sim.row_of}
        rows.add(row)
        self.conv = sim.conversations.join(centre, tuple(sorted(rows)), row)
        self.spot = self.conv.spots[row]
        self.ready = False
        self.near = False
        self.group = int(sim.crowd.group[row])
        waypoints = self.get_input("waypoints") or ()
        p = sim.pos[row]
        route = [*waypoints, self.spot] if waypoints and not self.interrupted else sim.plan(p, self.spot)
        _go(sim, row, route, 0.1)
        sim.status[row] = f"meeting at {self.get_input('target')}"
        return self.on_running()

    def _approach(self) -> float:
        """Within this of the centre the circle is the formation: friends walk there as a group, then each
        takes their own spot (coherence would hold members bound for opposite sides of the circle back,
        each pulling the others, and the circle would never start)."""
        return self.conv.radius + CIRCLE_APPROACH

    def on_running(self) -> int:
        sim, row, conv = self.sim, self.row, self.conv
        if not self.near and math.dist(sim.pos[row], conv.centre) <= self._approach():
            # The waypoints lead to the circle, not to this member's spot: three friends each trying to
            # touch the same last waypoint jostle for it; from here each walks to their own spot.
            self.near = True
            sim.crowd.set_group(row, -1)
            if not self.ready:
                _go(sim, row, sim.plan(sim.pos[row], self.spot), 0.1)
        if not self.ready and math.dist(sim.pos[row], self.spot) <= ARRIVAL_TOLERANCE:
            self.ready = True
            # group coherence would pull a standing circle into its centre; the circle is the formation
            sim.crowd.set_group(row, -1)
            _face(sim, row, conv.centre)
            sim.conversations.mark_ready(conv, row)
        elif self.ready:
            # standing agents are nudged by their neighbours' social forces and facing has no goal
            # force: step back onto the spot when pushed off, then face the centre again
            off = math.dist(sim.pos[row], self.spot)
            mode = sim.crowd.mode[row]
            if off > 0.2 and mode == MODE_FACE:
                _go(sim, row, [self.spot], 0.05)
            elif off <= 0.1 and mode == MODE_GOALS:
                _face(sim, row, conv.centre)
            if conv.started_at is None:
                sim.conversations.mark_ready(conv, row)  # re-check: someone may have left meanwhile
        if conv.started_at is None:
            if self.ready:
                sim.status[row] = f"waiting for the others ({len(conv.ready)}/{len(conv.members)})"
            return RUNNING
        sim.status[row] = "talking"
        duration = self.get_input("duration")
        if duration > 0 and sim.clock.now - conv.started_at + 1e-9 >= duration:
            sim.conversations.leave(conv, row)
            sim.crowd.set_group(row, self.group)
            self.interrupted = False
            return SUCCESS
        return RUNNING

    def on_halted(self) -> None:
        self.interrupted = True
        self.sim.conversations.leave(self.conv, self.row)  # halted while RUNNING: on_start joined it
        self.sim.crowd.set_group(self.row, self.group)
        _stand(self.sim, self.row)

    def quiet_spec(self) -> QuietSpec | None:
        if self.ready:
            return None
        if not self.near:
            centre, reach = self.conv.centre, self._approach()
            return (centre[0], centre[1], reach * reach, math.inf)
        return (self.spot[0], self.spot[1], ARRIVAL_TOLERANCE * ARRIVAL_TOLERANCE, math.inf)

    def poll(self) -> bool:
        """Would on_running change nothing and return RUNNING? Walking to the spot, standing on it while
        waiting for a circle that cannot start yet, or talking with time left."""
        sim, row, spot = self.sim, self.row, self.spot
        off = math.hypot(sim.px[row] - spot[0], sim.py[row] - spot[1])
        if not self.ready:
            if not self.near:
                centre = self.conv.centre
                return math.hypot(sim.px[row] - centre[0], sim.py[row] - centre[1]) > self._approach()
            return off > ARRIVAL_TOLERANCE
        mode = sim.crowd.mode[row]
        if (off > 0.2 and mode == MODE_FACE) or (off <= 0.1 and mode == MODE_GOALS):
            return False
        conv = self.conv
        if conv.started_at is None:
            # only an arrival (that member's own tick), a departure or the patience limit can start it
            if conv.left or sim.clock.now - conv.created_at >= sim.conversations.PATIENCE:
                return False
            if len(conv.ready) >= len(conv.members) or not all(sim.active[m] for m in conv.members):
                return False
            return sim.status[row] == f"waiting for the others ({len(conv.ready)}/{len(conv.members)})"
        duration = self.get_input("duration")
        if duration > 0 and sim.clock.now - conv.started_at + 1e-9 >= duration:
            return False
        return sim.status[row] == "talking"


GROVE_LEAVES = {
    cls.__name__: cls for cls in (GoTo, Wait, Queue, FollowVelocityField, Wander, JoinGroup, Converse)
}

