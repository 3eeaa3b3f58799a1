"""RiMEA verification tests (RiMEA e.V., Guideline for Microscopic Evacuation Analysis, v3) on GROVE's crowd.

Each test builds its geometry and people with `grove_tui.crowd.crowd.Crowd` (the kernel every scenario
runs on) at the product's step (dt 0.05 s) and returns a RimeaResult with the measured value and
whether it meets RiMEA's criterion. Tests 1, 4, 5, 6 and 7 drive the crowd directly; 9, 10, 11 and
12 need whole buildings and run the evacuation path end to end (world YAML, grid, velocity fields,
behavior trees, Simulation.build). Run them with `grove validate rimea`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from grove_tui.crowd.crowd import Crowd
from grove_tui.crowd.sfm import MODE_STOP, SFMParams
from grove_tui.scenario.model import DEFAULT_AGENT_RADIUS

DT = 0.05
RADIUS = 0.25


@dataclass(frozen=True)
class RimeaResult:
    test: int
    name: str
    measured: str
    criterion: str
    passed: bool


def _corridor(length: float, width: float, params: SFMParams) -> Crowd:
    walls = np.array([[-1.0, 0.0, length + 5.0, 0.0], [-1.0, width, length + 5.0, width],
                      [-1.0, 0.0, -1.0, width]])
    return Crowd(walls, params=params, dt=DT)


def test_1_corridor(params: SFMParams) -> RimeaResult:
    """One person, 1.33 m/s, walks 40 m of a 2 m corridor: 26-34 s."""
    crowd = _corridor(40.0, 2.0, params)
    i = crowd.add_agent((0.0, 1.0), radius=RADIUS, desired_speed=1.33, goals=[(60.0, 1.0)])
    while crowd.pos[i, 0] < 40.0 and crowd.time < 60.0:
        crowd.step(1)
    t = crowd.time
    return RimeaResult(1, "corridor 40 m at 1.33 m/s", f"{t:.1f} s", "26-34 s", 26.0 <= t <= 34.0)


def block_speed(density: float, params: SFMParams) -> float:
    """Mean speed of the middle of a block walking down a 4 m corridor at `density` persons/m^2."""
    width = 4.0
    walls = np.array([[-50.0, 0.0, 500.0, 0.0], [-50.0, width, 500.0, width]])
    crowd = Crowd(walls, params=params, dt=DT)
    spacing = 1.0 / math.sqrt(density)
    rows = max(int(width / spacing), 1)
    for c in range(int(30.0 / spacing)):
        for r in range(rows):
            y = (r + 0.5) * width / rows
            crowd.add_agent((c * spacing, y), radius=0.2, desired_speed=1.34, goals=[(1000.0, y)])
    crowd.step(int(2.0 / DT))
    start = crowd.pos[:, 0].copy()
    crowd.step(int(3.0 / DT))
    middle = (start > 10.0) & (start < 20.0)
    return float(np.mean(crowd.pos[middle, 0] - start[middle]) / 3.0)


def test_4_fundamental_diagram(params: SFMParams) -> RimeaResult:
    """Speed falls with density like Weidmann's curve; criterion of issue 19: v(3) <= 0.5 v(0.5)."""
    speeds = [block_speed(rho, params) for rho in (0.5, 1.0, 2.0, 3.0)]
    falling = all(a >= b for a, b in zip(speeds, speeds[1:]))
    return RimeaResult(4, "fundamental diagram 0.5/1/2/3 per m2", " / ".join(f"{v:.2f}" for v in speeds) + " m/s",
                       "falls; v(3) <= 0.5 v(0.5) (Weidmann 1.30/1.06/0.61/0.33)",
                       falling and speeds[3] <= 0.5 * speeds[0])


def test_5_premovement(params: SFMParams) -> RimeaResult:
    """Ten people in an 8 x 5 m room wait 10-100 s, then leave: each starts at its time, standing still before."""
    walls = np.array([[0, 0, 8, 0], [8, 0, 8, 2], [8, 3, 8, 5], [8, 5, 0, 5], [0, 5, 0, 0]], dtype=np.float64)
    crowd = Crowd(walls, params=params, dt=DT)
    times = np.linspace(10.0, 100.0, 10)
    starts = [(1.0 + 1.4 * (k % 5), 1.5 + 2.0 * (k // 5)) for k in range(10)]
    for p in starts:
        i = crowd.add_agent(p, radius=RADIUS, desired_speed=1.2)
        crowd.set_mode(i, MODE_STOP)
    moved_early = 0.0
    late = 0.0
    begun = [False] * 10
    while crowd.time < 105.0:
        for k in range(10):
            if not begun[k] and crowd.time + 1e-9 >= times[k]:
                begun[k] = True
                crowd.set_goals(k, [(9.0, 2.5), (12.0, 2.5)], goal_radius=0.3)
                crowd.set_mode(k, 0)
        crowd.step(1)
        for k in range(10):
            drift = math.dist(crowd.pos[k], starts[k])
            if not begun[k]:
                moved_early = max(moved_early, drift)
            elif crowd.time - times[k] > 2.0 and drift < 0.5:
                late = max(late, crowd.time - times[k])
    passed = moved_early <= 0.3 and late == 0.0
    return RimeaResult(5, "premovement 10-100 s", f"drift before start {100 * moved_early:.1f} cm",
                       "nobody leaves early (drift <= 0.3 m), everyone moves within 2 s", passed)


def test_6_corner(params: SFMParams) -> RimeaResult:
    """20 people walk round a left corner (2 m wide corridor): nobody passes through a wall."""
    # corridor east along y 0..2 to x 12, then north along x 10..12; measured to y 10.5 (RiMEA's
    # 10 m legs), the walls run on so that nobody crowds a dead end
    walls = np.array([[0, 0, 12, 0], [12, 0, 12, 40], [0, 2, 10, 2], [10, 2, 10, 40], [0, 0, 0, 2]],
                     dtype=np.float64)
    crowd = Crowd(walls, params=params, dt=DT)
    for k in range(20):
        crowd.add_agent((0.6 + 0.7 * (k // 2), 0.6 + 0.8 * (k % 2)), radius=RADIUS, desired_speed=1.2,
                        goals=[(11.0, 1.0), (11.0, 38.0)], goal_radius=0.5)
    inside = True
    while crowd.time < 60.0:
        crowd.step(1)
        x, y = crowd.pos[:, 0], crowd.pos[:, 1]
        legal = ((x > 0) & (x < 12) & (y > 0) & (y < 2)) | ((x > 10) & (x < 12) & (y > 0) & (y < 40))
        inside &= bool(legal.all())
        if (y > 10.5).all():
            break
    arrived = int((crowd.pos[:, 1] > 10.5).sum())
    return RimeaResult(6, "corner, 20 persons", f"{arrived}/20 round the corner in {crowd.time:.0f} s",
                       "all round, none through a wall", inside and arrived == 20)


def test_7_speed_distribution(params: SFMParams) -> RimeaResult:
    """50 people with desired speeds spread over 0.58-1.61 m/s (adults) walk at those speeds (+-5 %)."""
    rng = np.random.default_rng(7)
    speeds = rng.uniform(0.58, 1.61, 50)
    crowd = _corridor(1000.0, 2.0, params)
    for v in speeds:
        crowd.add_agent((0.0, 1.0), radius=RADIUS, desired_speed=float(v), goals=[(2000.0, 1.0)])
    measured = []
    for k in range(len(speeds)):
        # one at a time, alone in the corridor: the others are inactive and take no part
        for j in range(len(speeds)):
            crowd.set_active(j, j == k)
        crowd.step(int(2.0 / DT))
        x0 = float(crowd.pos[k, 0])
        crowd.step(int(5.0 / DT))
        measured.append((float(crowd.pos[k, 0]) - x0) / 5.0)
    error = float(np.max(np.abs(np.array(measured) / speeds - 1.0)))
    return RimeaResult(7, "speed distribution 0.58-1.61 m/s", f"worst {100 * error:.1f} % off",
                       "each walks its desired speed within 5 %", error <= 0.05)


# --------------------------------------------------------------------------- whole buildings (9-12)
#
# These run the product's evacuation path end to end: a world YAML, the occupancy grid inflated by
# the people's radius, Theta* and one velocity field per exit, a FollowVelocityField tree per person,
# and Simulation.build, which counts a person out only once it crossed its door line.

PRODUCT_RADIUS = DEFAULT_AGENT_RADIUS  # every generated person's body radius
PRODUCT_SPEED = 1.34                   # Weidmann's mean free walking speed, m/s


@dataclass
class EvacuationRun:
    """Who left through which exit and when; `crossings` holds the times a measuring line was crossed."""

    exit_of: dict[int, str]
    time_of: dict[int, float]
    crossings: list[float]
    inside: int
    duration: float
    worst_overlap: float
    aborted: str = ""  # why the simulator stopped early (JuPedSim ends a run it cannot continue)

    def unfinished(self) -> str:
        """'' when everyone got out, else what stopped them, for the measured column."""
        if self.aborted:
            return f"aborted at {self.duration:.0f} s: {self.aborted}"
        return f"{self.inside} still inside after {self.duration:.0f} s" if self.inside else ""


# A door: name, centre, width, the zone it leads to ("outside" for an exit), whether it is an exit.
DoorSpec = tuple[str, tuple[float, float], float, str, bool]


def _room_yaml(name: str, zones: Sequence[tuple[str, Sequence[tuple[float, float]], Sequence[DoorSpec]]]) -> str:
    lines = [f"name: {name}", f"description: RiMEA verification geometry {name}.", "zones:"]
    for zone, boundary, doors in zones:
        lines += [f"  - name: {zone}", "    type: room", f"    description: {zone}.",
                  f"    boundary: {[[float(x), float(y)] for x, y in boundary]}"]
        if doors:
            lines.append("    doors:")
            for door, (x, y), width, leads_to, is_exit in doors:
                lines.append(f"      - {{name: {door}, position: [{x}, {y}], width: {width}, leads_to: {leads_to}, "
                             f"exit: {'true' if is_exit else 'false'}}}")
    return "\n".join(lines) + "\n"


def _load(text: str, source: str):
    from grove_tui.world import parse_world

    world, problems = parse_world(text, source)
    if world is None:
        raise AssertionError(f"RiMEA geometry {source} is broken: {problems[0]}")
    return world


def evacuate(world, starts: list[tuple[float, float]], exit_of: list[str], params: SFMParams | JuPedSimModel, *,
             radius: float = PRODUCT_RADIUS, speed: float = PRODUCT_SPEED, limit: float = 900.0,
             line_x: float | None = None) -> EvacuationRun:
    """Everyone follows the velocity field of their own exit and leaves through its door.

    `line_x`: also record the times people's centres first cross x = line_x going +x (a bottleneck).
    With `params` JUPEDSIM the same people leave the same world in JuPedSim instead.
    """
    if isinstance(params, JuPedSimModel):
        return _evacuate_jupedsim(world, starts, exit_of, radius=radius, speed=speed, limit=limit, line_x=line_x)
    from grove_tui.bt.format.document import TreeDocument, node
    from grove_tui.bt.format.xml import validate_document
    from grove_tui.navigation.grid import build_grid
    from grove_tui.navigation.theta_star import ThetaStarPlanner
    from grove_tui.navigation.velocity_field import build_velocity_field
    from grove_tui.scenario.model import AgentSpec
    from grove_tui.simulation.simulation import Simulation

    grid = build_grid(world, resolution=0.1, inflation=radius)
    planner = ThetaStarPlanner(grid)
    fields = {}
    for name in sorted(set(exit_of)):
        door = world.find(name)
        members = [p for p, e in zip(starts, exit_of) if e == name]
        centre = grid.nearest_free(sum(p[0] for p in members) / len(members), sum(p[1] for p in members) / len(members))
        if centre is None:
            centre = members[0]
        fields[f"to_{name}"] = build_velocity_field(grid, planner.plan(centre, door.position), door.position,
                                                    exit_label=name, planner=planner)
    agents, documents = [], []
    for k, (start, name) in enumerate(zip(starts, exit_of)):
        zone = world.zone_at(*start)
        agents.append(AgentSpec(id=k + 1, group=-1, start=start, goals=(), zone=zone.name if zone else "",
                                tree=f"trees/agent_{k + 1}.xml", radius=radius, max_vel=speed))
        tree = TreeDocument.single("T", node("FollowVelocityField", exit=name, field=f"to_{name}"), f"agent_{k + 1}.xml")
        documents.append(validate_document(tree))
    sim = Simulation.build(agents, documents, world=world, grid=grid, planner=planner, walls=world.walls(),
                           fields=fields, seed=0, dt=DT, params=params)
    n = len(agents)
    crossed = np.zeros(n, dtype=bool)
    crossings: list[float] = []
    worst = 0.0
    while sim.time < limit and sim.crowd.active[:n].any():
        before = sim.crowd.pos[:n, 0].copy()
        sim.step()
        if line_x is not None:
            now = sim.crowd.pos[:n, 0]
            new = ~crossed & (before < line_x) & (now >= line_x)
            crossed |= new
            crossings += [sim.time] * int(new.sum())
        if sim.step_count % 20 == 0:
            worst = max(worst, _worst_overlap(sim.crowd, n))
    exit_of_id: dict[int, str] = {}
    time_of: dict[int, float] = {}
    for event in sim.events:
        if event.kind == "evacuated":
            exit_of_id[event.agent_id] = event.detail
            time_of[event.agent_id] = event.t
    return EvacuationRun(exit_of_id, time_of, crossings, int(sim.crowd.active[:n].sum()), sim.time, worst)


def _worst_overlap(crowd: Crowd, n: int) -> float:
    """Deepest body overlap among the active people (metres)."""
    from scipy.spatial import cKDTree

    rows = np.flatnonzero(crowd.active[:n])
    if len(rows) < 2:
        return 0.0
    pos = crowd.pos[rows]
    radius = crowd.radius[rows]
    pairs = cKDTree(pos).query_pairs(2.0 * float(radius.max()), output_type="ndarray")
    if len(pairs) == 0:
        return 0.0
    d = np.hypot(*(pos[pairs[:, 0]] - pos[pairs[:, 1]]).T)
    return float(max(0.0, np.max(radius[pairs[:, 0]] + radius[pairs[:, 1]] - d)))


def _grid_of_people(x0: float, x1: float, y0: float, y1: float, count: int, spacing: float) -> list[tuple[float, float]]:
    """`count` people on a regular grid at least `spacing` apart inside the box, row by row."""
    cols = int((x1 - x0) / spacing) + 1
    rows = int((y1 - y0) / spacing) + 1
    sx = (x1 - x0) / max(cols - 1, 1)
    sy = (y1 - y0) / max(rows - 1, 1)
    points = [(x0 + c * sx, y0 + r * sy) for r in range(rows) for c in range(cols)]
    if count > len(points):
        raise ValueError(f"{count} people do not fit {spacing} m apart in the box")
    # spread the chosen ones over the whole box, not the first rows
    chosen = np.linspace(0, len(points) - 1, count).round().astype(int)
    return [(round(points[k][0], 3), round(points[k][1], 3)) for k in chosen]


def _nearest_exit(world, starts: list[tuple[float, float]], names: list[str], radius: float) -> list[str]:
    from grove_tui.navigation.grid import build_grid
    from grove_tui.navigation.theta_star import ThetaStarPlanner
    from grove_tui.navigation.velocity_field import nearest_exits

    grid = build_grid(world, resolution=0.1, inflation=radius)
    return nearest_exits(ThetaStarPlanner(grid, landmarks=0), {n: world.find(n).position for n in names}, starts)


def room_with_exits(exits: tuple[str, ...]) -> str:
    """RiMEA 9's room, 30 m x 20 m, with 1 m exits near the four corners (those named stay open)."""
    doors = {"exit_nw": ((4.5, 20.0), 1.0), "exit_ne": ((25.5, 20.0), 1.0),
             "exit_sw": ((4.5, 0.0), 1.0), "exit_se": ((25.5, 0.0), 1.0)}
    return _room_yaml("rimea_9_" + "_".join(exits), [
        ("room", [(0, 0), (30, 0), (30, 20), (0, 20)],
         [(name, doors[name][0], doors[name][1], "outside", True) for name in exits])])


def test_9_exits(params: SFMParams | JuPedSimModel, people: int = 1000, runs: int = 3) -> RimeaResult:
    """A 30 x 20 m room of `people` leaves through 4 exits, then through 2: the time about doubles.

    A crowd draining through 1 m doors is chaotic: a millimetre more or less at the start decides
    whether an arch jams a door for seconds (one run's 4-exit time ranged 37.7-43.6 s over such
    starts). So, as RiMEA asks of evacuation times, each configuration runs `runs` times from
    starts shifted by under a millimetre, and the median time counts.
    """
    base = _grid_of_people(0.6, 29.4, 0.6, 19.4, people, 2.0 * PRODUCT_RADIUS + 0.02)
    times = []
    for exits in (("exit_nw", "exit_ne", "exit_se", "exit_sw"), ("exit_nw", "exit_sw")):
        world = _load(room_with_exits(exits), f"rimea_9_{len(exits)}_exits.yaml")
        choice = _nearest_exit(world, base, list(exits), PRODUCT_RADIUS)
        finished = []
        for run_index in range(max(runs, 1)):
            rng = np.random.default_rng(run_index)
            shift = 0.0 if run_index == 0 else 0.001
            starts = [(x + shift * rng.uniform(-1, 1), y + shift * rng.uniform(-1, 1)) for x, y in base]
            run = evacuate(world, starts, choice, params, limit=60.0 + 1.5 * people)
            if run.unfinished():
                return RimeaResult(9, f"room of {people}, 4 exits then 2", f"{run.unfinished()} ({len(exits)} exits)",
                                   "T(2)/T(4) about 2 (1.7-2.3)", False)
            finished.append(max(run.time_of.values()))
        times.append(float(np.median(finished)))
    ratio = times[1] / times[0]
    return RimeaResult(9, f"room of {people}, 4 exits then 2",
                       f"{times[0]:.1f} s / {times[1]:.1f} s, ratio {ratio:.2f} (median of {max(runs, 1)})",
                       "T(2)/T(4) about 2 (1.7-2.3)", 1.7 <= ratio <= 2.3)


def building_of_rooms() -> str:
    """RiMEA 10's building: twelve 4 x 4 m rooms on both sides of a 2 m corridor, an exit at each end."""
    zones: list[tuple[str, Sequence[tuple[float, float]], Sequence[DoorSpec]]] = []
    # each exit spans the whole end of the corridor: its jambs are the corridor's corners
    corridor_doors = [("west_exit", (0.0, 5.0), 2.0, "outside", True), ("east_exit", (24.0, 5.0), 2.0, "outside", True)]
    zones.append(("corridor", [(0.0, 4.0), (24.0, 4.0), (24.0, 6.0), (0.0, 6.0)], corridor_doors))
    for k in range(6):
        x0 = 4.0 * k
        zones.append((f"room_s{k + 1}", [(x0, 0), (x0 + 4, 0), (x0 + 4, 4), (x0, 4)],
                      [(f"door_s{k + 1}", (x0 + 2.0, 4.0), 1.0, "corridor", False)]))
        zones.append((f"room_n{k + 1}", [(x0, 6), (x0 + 4, 6), (x0 + 4, 10), (x0, 10)],
                      [(f"door_n{k + 1}", (x0 + 2.0, 6.0), 1.0, "corridor", False)]))
    return _room_yaml("rimea_10_rooms", zones)


def test_10_assigned_routes(params: SFMParams | JuPedSimModel) -> RimeaResult:
    """23 people in 12 rooms, each with an assigned exit (some the farther one): all use their own."""
    world = _load(building_of_rooms(), "rimea_10.yaml")
    starts, exits = [], []
    for k in range(23):
        room = k % 12
        side = "s" if room % 2 == 0 else "n"
        column = room // 2
        x = 4.0 * column + (1.2 if k < 12 else 2.8)
        y = 1.8 if side == "s" else 8.2
        starts.append((x, y))
        # RiMEA: the assignment, not the distance, decides; every third person gets the farther exit
        nearer = "west_exit" if x < 12.0 else "east_exit"
        farther = "east_exit" if nearer == "west_exit" else "west_exit"
        exits.append(farther if k % 3 == 0 else nearer)
    run = evacuate(world, starts, exits, params, limit=120.0)
    right = sum(1 for i, name in enumerate(exits) if run.exit_of.get(i + 1) == name)
    return RimeaResult(10, "assigned escape routes, 23 in 12 rooms", f"{right}/23 through their exit",
                       "everyone through the assigned exit", right == 23)


def room_with_two_exits() -> str:
    """RiMEA 11's room, 30 m x 20 m, two 1 m exits in the north wall at x 21.5 and 27.5."""
    return _room_yaml("rimea_11", [("room", [(0, 0), (30, 0), (30, 20), (0, 20)],
                                    [("exit_1", (21.5, 20.0), 1.0, "outside", True),
                                     ("exit_2", (27.5, 20.0), 1.0, "outside", True)])])


def exit_choice(world, starts, names, radius: float, speed: float, how: str) -> list[str]:
    """Each person's exit: the nearest by walking distance, or the least congested (RiMEA 11)."""
    from grove_tui.navigation.grid import build_grid
    from grove_tui.navigation.theta_star import ThetaStarPlanner
    from grove_tui.navigation.velocity_field import least_congested_exits, nearest_exits

    planner = ThetaStarPlanner(build_grid(world, resolution=0.1, inflation=radius), landmarks=0)
    doors = {n: world.find(n) for n in names}
    if how == "nearest":
        return nearest_exits(planner, {n: d.position for n, d in doors.items()}, starts)
    return least_congested_exits(planner, {n: (d.position, d.width) for n, d in doors.items()}, starts,
                                 [speed] * len(starts))


def test_11_exit_choice(params: SFMParams | JuPedSimModel, people: int = 1000) -> RimeaResult:
    """People in the west two thirds of the room, exit 1 nearer for all: the least-congested choice sends
    some of them to exit 2 (the nearest-exit choice, shown beside it, sends nobody)."""
    world = _load(room_with_two_exits(), "rimea_11.yaml")
    starts = _grid_of_people(0.6, 19.4, 0.6, 19.4, people, 2.0 * PRODUCT_RADIUS + 0.02)
    nearest = exit_choice(world, starts, ["exit_1", "exit_2"], PRODUCT_RADIUS, PRODUCT_SPEED, "nearest")
    chosen = exit_choice(world, starts, ["exit_1", "exit_2"], PRODUCT_RADIUS, PRODUCT_SPEED, "least_congested")
    run = evacuate(world, starts, chosen, params, limit=60.0 + 1.5 * people)
    used = [sum(1 for e in run.exit_of.values() if e == name) for name in ("exit_1", "exit_2")]
    # Two doors of one width drain at one rate: once queues set the time, the expected-time choice
    # splits the crowd about evenly, the nearer door taking those who reach it before a queue forms.
    passed = not run.unfinished() and used[0] >= used[1] > 0
    return RimeaResult(11, f"exit choice, {people} people, 2 exits",
                       (run.unfinished() or f"least congested {used[0]}/{used[1]} in {run.duration:.0f} s")
                       + f"; nearest {nearest.count('exit_1')}/{nearest.count('exit_2')}",
                       "exit 1 (nearer for all) takes at least half, exit 2 is used", passed)


def bottleneck_building() -> str:
    """RiMEA 12's geometry: a 10 x 10 m room, a 1 m wide 5 m long corridor, a second room, a 1 m exit."""
    return _room_yaml("rimea_12", [
        ("room_a", [(0, 0), (10, 0), (10, 10), (0, 10)], [("bottleneck_in", (10.0, 5.0), 1.0, "corridor", False)]),
        ("corridor", [(10, 4.5), (15, 4.5), (15, 5.5), (10, 5.5)], [("bottleneck_out", (15.0, 5.0), 1.0, "room_b", False)]),
        ("room_b", [(15, 0), (25, 0), (25, 10), (15, 10)], [("exit", (25.0, 5.0), 1.0, "outside", True)]),
    ])


def bottleneck_flow(params: SFMParams | JuPedSimModel, people: int = 150,
                    radius: float = PRODUCT_RADIUS) -> tuple[float, float, str]:
    """(specific flow into the 1 m bottleneck /s/m, flow out of the last exit /s, '' or what stopped people)."""
    world = _load(bottleneck_building(), "rimea_12.yaml")
    starts = _grid_of_people(0.6, 9.0, 0.6, 9.4, people, 2.0 * radius + 0.02)
    run = evacuate(world, starts, ["exit"] * people, params, radius=radius, limit=60.0 + 2.0 * people, line_x=10.0)
    return _steady_flow(run.crossings) / 1.0, _steady_flow(sorted(run.time_of.values())), run.unfinished()


def _steady_flow(times: list[float]) -> float:
    """Persons per second between the 10th and the 90th percentile crossing (start-up and tail left out)."""
    if len(times) < 10:
        return 0.0
    times = sorted(times)
    a, b = int(0.1 * len(times)), int(0.9 * len(times))
    return (b - a) / max(times[b] - times[a], 1e-9)


def test_12_bottleneck(params: SFMParams | JuPedSimModel, people: int = 150) -> RimeaResult:
    """150 people through a 1 m, 5 m long corridor: specific flow 1.3-1.9 /s/m, no jam at the exit after it."""
    specific, last, unfinished = bottleneck_flow(params, people)
    # no jam after the bottleneck: the last exit, as wide, passes people as fast as they arrive
    passed = not unfinished and 1.3 <= specific <= 1.9 and last >= 0.9 * specific
    return RimeaResult(12, f"bottleneck, {people} people, 1 m corridor",
                       f"{specific:.2f} /s/m in, {last:.2f} /s out" + (f"; {unfinished}" if unfinished else ""),
                       "specific flow 1.3-1.9 /s/m; exit after it >= 0.9 of it", passed)


TESTS: dict[int, Callable[..., RimeaResult]] = {
    1: test_1_corridor, 4: test_4_fundamental_diagram, 5: test_5_premovement, 6: test_6_corner,
    7: test_7_speed_distribution, 9: test_9_exits, 10: test_10_assigned_routes, 11: test_11_exit_choice,
    12: test_12_bottleneck,
}


# --------------------------------------------------------------------------- JuPedSim beside GROVE


class JuPedSimModel:
    """Stands in for SFMParams in the building tests: `evacuate` then runs JuPedSim's SocialForceModel
    on the same world (its walkable area plus a strip outside each exit), people, radius and speed, at
    JuPedSim's own dt of 0.01 s. People leave at an exit stage 1-2 m beyond their door line."""

    dt = 0.01


JUPEDSIM = JuPedSimModel()
# The tests JuPedSim runs beside GROVE: those on whole buildings, built from a world file.
JUPEDSIM_TESTS = (9, 10, 11, 12)


def jupedsim_version() -> str | None:
    """JuPedSim's version when it can be imported (`./install.sh bench`), else None."""
    import importlib.util

    if importlib.util.find_spec("jupedsim") is None:
        return None
    try:
        import jupedsim
    except ImportError:
        return None
    return str(getattr(jupedsim, "__version__", "?"))


def _evacuate_jupedsim(world, starts: list[tuple[float, float]], exit_of: list[str], *, radius: float, speed: float,
                       limit: float, line_x: float | None) -> EvacuationRun:
    import jupedsim as jps
    import shapely as sh

    pieces = [world.walkable()]
    stages = {}
    for name in sorted(set(exit_of)):
        door = world.find(name)
        (ax, ay), (bx, by) = door.opening
        ox, oy = -door.normal[0], -door.normal[1]  # out of the building
        pieces.append(sh.Polygon([(ax - 0.06 * ox, ay - 0.06 * oy), (bx - 0.06 * ox, by - 0.06 * oy),
                                  (bx + 3.0 * ox, by + 3.0 * oy), (ax + 3.0 * ox, ay + 3.0 * oy)]))
        stages[name] = sh.Polygon([(ax + 1.0 * ox, ay + 1.0 * oy), (bx + 1.0 * ox, by + 1.0 * oy),
                                   (bx + 2.0 * ox, by + 2.0 * oy), (ax + 2.0 * ox, ay + 2.0 * oy)])
    geometry = sh.union_all(pieces)
    if geometry.geom_type != "Polygon":
        geometry = max(geometry.geoms, key=lambda g: g.area)
    sim = jps.Simulation(model=jps.SocialForceModel(), geometry=geometry, dt=JUPEDSIM.dt)
    journeys = {}
    for name, polygon in stages.items():
        stage = sim.add_exit_stage(polygon)
        journeys[name] = (sim.add_journey(jps.JourneyDescription([stage])), stage)
    agent_exit = {}
    for k, (start, name) in enumerate(zip(starts, exit_of)):
        journey, stage = journeys[name]
        agent = sim.add_agent(jps.SocialForceModelAgentParameters(journey_id=journey, stage_id=stage,
                                                                  position=start, desired_speed=speed, radius=radius))
        agent_exit[agent] = (k + 1, name)
    every = 10  # positions read every 0.1 s
    last = {a.id: a.position for a in sim.agents()}
    exit_of_id: dict[int, str] = {}
    time_of: dict[int, float] = {}
    crossings: list[float] = []
    crossed: set[int] = set()
    t = 0.0
    aborted = ""
    while sim.agent_count() and t < limit:
        try:
            sim.iterate(every)
        except RuntimeError as error:
            # JuPedSim stops when its SFM pushes someone out of the walkable area (issue 19)
            message = str(error).splitlines()[0] if str(error) else "RuntimeError"
            aborted = "it pushed someone out of the walkable area" if "is outside" in message else message[:60]
            break
        t = sim.iteration_count() * JUPEDSIM.dt
        now = {a.id: a.position for a in sim.agents()}
        for agent in set(last) - set(now):
            person, name = agent_exit[agent]
            exit_of_id[person] = name
            time_of[person] = t
        if line_x is not None:
            for agent, (x, _y) in now.items():
                if agent not in crossed and x >= line_x and last.get(agent, (x, 0))[0] < line_x:
                    crossed.add(agent)
                    crossings.append(t)
        last = now
    return EvacuationRun(exit_of_id, time_of, crossings, sim.agent_count(), t, float("nan"), aborted)


def run_rimea(model: str = "grove", tests: tuple[int, ...] = tuple(TESTS),
              jupedsim: bool = False) -> list[tuple[RimeaResult, RimeaResult | None]]:
    """Each test on the model's crowd, with JuPedSim's result beside the building tests when asked."""
    params = SFMParams.named(model)
    return [(TESTS[t](params), TESTS[t](JUPEDSIM) if jupedsim and t in JUPEDSIM_TESTS else None)
            for t in tests]
