"""The runnable scenario: the SFM crowd, one behavior tree per agent, the robot and the recorder.

Each physics step advances the crowd by dt; every 1/bt_rate seconds (simulation time) first every
agent's tree is ticked once (BT.CPP tickExactlyOnce) with blackboard {id, dt}. Trees change only
intents on the crowd; the numba step moves everyone.

Tree lifetime: a GROVE tree runs once. When its root returns SUCCESS or FAILURE the agent's
behavior is done and it stays where it is. A tree that reacts to the robot around its routine
(ReactiveFallback[robot cue branch, routine], as generation and with_robot_reaction write it) keeps
reacting after the routine: the routine runs once and then holds inside the reaction, as the HuNavSim
export does (bt/format/after_task.py); the agent counts as done when its routine is. HuNavSim-style trees (those using RegularNav, whose root
completes every tick by design) are ticked for the whole run, as HuNavSim does.

Robot reactions: an agent whose scenario `behavior` is Surprised, Scared, Curious or Threatening and
whose tree has no reaction node gets HuNavSim's reaction pattern around its tree:
    ReactiveFallback[ Sequence[IsRobotVisible(distance), ForceFailure(<Reaction>Nav(beh_duration, only_once))],
                      SubTree(original tree, _autoremap) ]
(the reaction halts the routine while it runs; the routine then resumes: GoTo replans from where the
agent stands, a queued agent gets its place back)
with HuNavSim 1.0's values (Surprised 4 m/30 s/once, Scared 3 m/40 s/repeat, Curious 10 m/30 s/once,
Threatening 4 m/40 s/once). Impassive agents treat the robot as an obstacle.
"""

from __future__ import annotations

import math
import os
import threading
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import shapely
from shapely.geometry.base import BaseGeometry

from grove_tui.crowd.context import AgentContext, SimContext
from grove_tui.crowd.leaves.registry import tree_factory
from grove_tui.crowd.leaves.hunav import ROBOT_ACTIVITIES, ROBOT_REACTION_DEFAULTS, ROBOT_REACTIONS, VISIBLE_HALF_ANGLE
from grove_tui.bt.runtime.blackboard import Blackboard
from grove_tui.simulation.after_task import AFTER_TASK_HOLD_SECONDS, holding_node, with_hold_after_task
from grove_tui.bt.format.document import TreeDocument, node, subtree_call
from grove_tui.bt.runtime.factory import BehaviorTree
from grove_tui.bt.runtime.tree_node import FAILURE, SUCCESS, SimClock
from grove_tui.errors import BTError
from grove_tui.bt.format.xml import parse_tree_text
from grove_tui.crowd.crowd import MODE_FIELD, MODE_STOP, ROBOT_AS_OBSTACLE, Crowd
from grove_tui.crowd.recording import TrajectoryRecorder
from grove_tui.crowd.sfm import SFMParams
from grove_tui.navigation.grid import OccupancyGrid
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.navigation.velocity_field import VelocityField
from grove_tui.scenario.events import SimEvent
from grove_tui.scenario.model import AgentSpec, RobotSpec, Scenario
from grove_tui.simulation.keep_inside import back_inside, may_leave
from grove_tui.simulation.robot import RobotDriver
from grove_tui.world.model import World

# behavior -> (reaction node, trigger distance m, duration s, only once): HuNavSim 1.0 values
REACTION_DEFAULTS = ROBOT_REACTION_DEFAULTS
HUNAV_LOOPING_NODES = frozenset({"RegularNav", "UpdateGoal"})
ROBOT_CONTACT_GAP = 0.02  # HuNavSim evaluator: a gap below this is a collision
# A contact ends only once the two have moved this far apart: bodies brushing against each other in a
# dense spot flicker in and out of touch every step, and each flicker is not a new collision.
CONTACT_RELEASE = 0.1


@dataclass(frozen=True)
class CounterSnapshot:
    reached_goals: int
    in_queue: int
    served: int
    evacuated: int
    collisions: int
    robot_collisions: int
    closest_robot_approach: float
    finished: int


@dataclass(frozen=True)
class Frame:
    """Immutable snapshot of the active agents (evacuated ones are gone) and the robot."""

    t: float
    step: int
    ids: np.ndarray  # (n,) int agent ids
    pos: np.ndarray  # (n, 2)
    vel: np.ndarray  # (n, 2)
    yaw: np.ndarray  # (n,)
    group: np.ndarray  # (n,) SFM group, -1 for none
    status: tuple[str, ...]  # short text per agent
    robot: tuple[float, float, float] | None  # x, y, yaw
    counters: CounterSnapshot


@dataclass(frozen=True)
class RunState:
    """Where the people of a run stand: how many it has, how many have left it (evacuated, out of the
    building) and how many are out or have finished their tree. Nothing is left to happen to the
    people once `over` (a HuNavSim looping tree never finishes: its agent keeps a run going)."""

    agents: int
    out: int
    done: int

    @property
    def over(self) -> bool:
        return self.agents > 0 and self.done == self.agents


def _frozen(a: np.ndarray) -> np.ndarray:
    a = np.array(a, copy=True)
    a.setflags(write=False)
    return a


class Simulation:
    def __init__(self, crowd: Crowd, context: SimContext, trees: list[BehaviorTree], *, dt: float,
                 bt_rate: float, loops: list[bool] | None = None, scenario: Scenario | None = None,
                 world: World | None = None,
                 recorder: TrajectoryRecorder | None = None):
        self.crowd = crowd
        self.context = context
        self.clock = context.clock
        self.trees = trees
        self.dt = float(dt)
        self.bt_rate = float(bt_rate)
        self.bt_every = max(1, int(round(1.0 / (self.bt_rate * self.dt))))
        self.bt_dt = self.bt_every * self.dt
        self.loops = loops if loops is not None else [False] * len(trees)
        self.finished = [False] * len(trees)
        self._finished_mask = np.array(self.finished, dtype=bool)
        n = len(trees)
        # quiescence specs (see tick_behaviors): far from (x, y) by more than sqrt(r2), before t,
        # robot unseen within guard distance (< 0: no guard)
        self._q_on = np.zeros(n, dtype=bool)
        self._q_x = np.zeros(n)
        self._q_y = np.zeros(n)
        self._q_r2 = np.zeros(n)
        self._q_t = np.zeros(n)
        self._q_guard = np.full(n, -1.0)
        self.tree_result = ["" for _ in trees]
        # rows whose routine holds inside a reaction to the robot: ticked on after their routine is done
        self._after_task = [holding_node(tree) if tree is not None else None for tree in trees]
        self._reacting = np.zeros(n, dtype=bool)
        self.tree_errors: dict[int, str] = {}  # agent id -> why its tree stopped (e.g. an unset blackboard entry)
        self._building: BaseGeometry | None = None  # the zones' union, prepared on first use (see _count_people_outside)
        self._exits: list[tuple[str, tuple[float, float]]] = []
        self.scenario = scenario
        self.world = world
        self.recorder = recorder if recorder is not None else _make_recorder(dt, context.ids)
        self.step_count = 0
        self._robot_contacts: set[int] = set()
        self._agent_contacts: set[tuple[int, int]] = set()
        self._lock = threading.Lock()
        self.robot_driver: RobotDriver | None = None  # the scripted robot's task and collision monitor
        self._kept_in: set[int] = set()
        self.may_leave: np.ndarray | None = None  # rows whose task is to leave (None: everyone may; see keep_inside)
        for row in range(len(trees)):
            tree = trees[row]
            if tree is not None:
                tree.blackboard.set("dt", self.bt_dt)

    # ---- construction -------------------------------------------------------------------------

    @classmethod
    def from_scenario(cls, scenario: Scenario, bundle_dir: str | Path, world: World | None = None, dt: float = 0.05,
                      bt_rate: float = 10.0, runtime_planning: bool = True,
                      params: SFMParams | None = None) -> Simulation:
        """`runtime_planning=False` walks every dynamic goal straight (HuNavSim's behavior, the
        no-planner baseline); by default goals set while running are planned with Theta*.
        `params`: the pedestrian model's SFMParams (default: the "grove" model)."""
        from grove_tui.navigation.grid import build_grid
        from grove_tui.navigation.theta_star import ThetaStarPlanner
        from grove_tui.scenario.bundle import load_bundle_world, load_field, load_grid, read_bundle_text

        bundle_dir = Path(bundle_dir)
        if world is None:
            world = load_bundle_world(bundle_dir, scenario)
        grid_path = bundle_dir / "grid.npz"
        # a bundle without its grid: inflate by the people's largest radius, as generation did
        grid = (load_grid(bundle_dir) if os.path.lexists(grid_path)
                else build_grid(world, resolution=scenario.resolution, inflation=scenario.grid_inflation))
        # Every file is checked to be a regular file inside the bundle before it is read.
        fields = {field_id: load_field(bundle_dir, field_id, rel) for field_id, rel in scenario.fields.items()}
        documents = []
        for agent in sorted(scenario.agents, key=lambda a: a.id):
            text = read_bundle_text(bundle_dir, agent.tree, f"agent {agent.id}'s tree")
            documents.append(parse_tree_text(text, str(bundle_dir / agent.tree)))
        planner = ThetaStarPlanner(grid) if runtime_planning else None
        return cls.build(scenario.agents, documents, world=world, grid=grid, planner=planner,
                         walls=world.walls(), robot=scenario.robot, fields=fields, seed=scenario.seed, dt=dt,
                         bt_rate=bt_rate, scenario=scenario, params=params)

    @classmethod
    def build(cls, agents: Sequence[AgentSpec], documents: list[TreeDocument], *, world: World | None = None,
              grid: OccupancyGrid | None = None, planner: ThetaStarPlanner | None = None,
              walls: np.ndarray | None = None, robot: RobotSpec | None = None,
              fields: Mapping[str, VelocityField] | None = None, seed: int = 0, dt: float = 0.05,
              bt_rate: float = 10.0, scenario: Scenario | None = None, params: SFMParams | None = None) -> Simulation:
        """Build from agent specs (sorted by id, as in Scenario.agents) and their parsed trees."""
        agents = sorted(agents, key=lambda a: a.id)
        if len(documents) != len(agents):
            raise BTError(f"{len(agents)} agents but {len(documents)} behavior trees")
        crowd = Crowd(walls, params=params, dt=dt, seed=seed, grid=grid)
        for agent in agents:
            crowd.add_agent(agent.start, radius=agent.radius, desired_speed=agent.max_vel, group=agent.group,
                            goal_radius=agent.goal_radius, yaw=agent.initial_heading(),
                            robot_interaction=ROBOT_AS_OBSTACLE if agent.behavior == "Impassive" else 0)
        if robot is not None:
            path = list(robot.path) if robot.path else [robot.start, robot.goal]
            heading = next((math.atan2(q[1] - robot.start[1], q[0] - robot.start[0]) for q in path
                            if math.dist(q, robot.start) > 1e-6), 0.0)
            crowd.set_robot(robot.start, radius=robot.radius, max_speed=robot.max_vel, path=np.asarray(path, float),
                            yaw=heading)
        ids = [a.id for a in agents]
        groups = _draft_groups(agents)
        clock = SimClock(0.0)
        context = SimContext(crowd, clock, ids=ids, seed=seed, world=world, grid=grid, planner=planner, walls=walls,
                             goal_table=_goal_table(documents) | dict(getattr(scenario, "global_goals", None) or {}),
                             groups=groups,
                             base_speed=[a.max_vel for a in agents])
        for field_id, field in (fields or {}).items():
            context.fields[field_id] = crowd.register_field(field)
            context.field_exits[field_id] = (float(field.exit[0]), float(field.exit[1]))
        factory = tree_factory()
        bt_dt = max(1, int(round(1.0 / (bt_rate * dt)))) * dt
        trees: list[BehaviorTree] = []
        loops: list[bool] = []
        for row, (agent, document) in enumerate(zip(agents, documents)):
            document = with_robot_reaction(document, agent.behavior)
            hunav_style = any(e.id in HUNAV_LOOPING_NODES for e in document.nodes())
            if not hunav_style:
                document = with_hold_after_task(document, AFTER_TASK_HOLD_SECONDS)
            blackboard = Blackboard(values={"id": agent.id, "dt": bt_dt})
            trees.append(factory.create(document, blackboard, AgentContext(context, row), clock))
            loops.append(hunav_style)
            if hunav_style and agent.goals:
                # HuNavSim trees walk the agent's own goal list (agents YAML `goals` and `cyclic_goals`)
                crowd.set_goals(row, agent.goals, cyclic=agent.cyclic_goals)
        recorder = _make_recorder(dt, ids)
        simulation = cls(crowd, context, trees, dt=dt, bt_rate=bt_rate, loops=loops, scenario=scenario, world=world,
                         recorder=recorder)
        simulation.may_leave = may_leave(documents, [door.name for door in world.exits()] if world is not None else ())
        if robot is not None:
            simulation.robot_driver = RobotDriver(robot, crowd, context)
            crowd.set_robot_path(simulation.robot_driver.initial_path())
        return simulation

    # ---- running --------------------------------------------------------------------------------

    @property
    def time(self) -> float:
        return self.crowd.time

    @property
    def ids(self) -> list[int]:
        return self.context.ids

    @property
    def events(self) -> list[SimEvent]:
        return [SimEvent(t, agent_id, kind, detail) for t, agent_id, kind, detail in self.context.events]

    def step(self) -> None:
        with self._lock:
            if self.step_count % self.bt_every == 0:
                self.tick_trees()
            self.crowd.step(1)
            self.step_count += 1
            self.clock.now = self.crowd.time
            # Every step, not every tick: whoever stepped over the building's outline (an exit's door
            # line) leaves before the frame is recorded, so trajectories end at the door line and stay
            # inside the walkable area PedPy checks them against (30 us for 200 people).
            self._count_people_outside()
            self._record()

    def tick_trees(self) -> None:
        """What step() does every 1/bt_rate seconds: tick every tree, then update the contact counters."""
        self.tick_behaviors()
        # After the ticks, so an evacuee's tree has already set its field mode on the first tick.
        self._count_people_outside()
        self._measure_contacts()
        if self.robot_driver is not None:
            self.robot_driver.update()

    def _count_people_outside(self) -> None:
        """Anyone the crowd pushed out of the building (through an exit: walls hold everywhere else)
        has left it. An evacuee is counted as evacuated through the nearest exit; anyone else gets a
        `left_building` event. Either way the agent stops taking part, so nobody wanders outside
        uncounted, and is not recorded outside. (An evacuee's tree is quiescent until it is near its
        own exit point, so without this check one pushed past that point was never ticked again.)"""
        world = self.world
        if world is None or not hasattr(world, "outline"):
            return
        n = len(self.trees)
        active = np.flatnonzero(np.asarray(self.crowd.active[:n], dtype=bool))
        if active.size == 0:
            return
        if self._building is None:
            self._building = world.outline()
            shapely.prepare(self._building)
            self._exits = [(door.name, door.position) for door in world.exits()]
        pos = self.crowd.pos[active]
        # strictly inside, as PedPy's walkable-area check (shapely.within) counts it
        outside = active[~shapely.contains_xy(self._building, pos[:, 0], pos[:, 1])]
        ctx = self.context
        for row in outside.tolist():
            x, y = float(self.crowd.pos[row, 0]), float(self.crowd.pos[row, 1])
            exit_name = min(self._exits, key=lambda e: math.dist(e[1], (x, y)))[0] if self._exits else ""
            evacuating = int(self.crowd.mode[row]) == MODE_FIELD or ctx.status[row].startswith("evacuating")
            if not evacuating and self.may_leave is not None and not self.may_leave[row]:
                # not their task to leave: held back in at the door (keep_inside)
                self.crowd.pos[row] = back_inside(self._building, (x, y), float(self.crowd.radius[row]))
                self.crowd.vel[row] = 0.0
                if row not in self._kept_in:  # said once: the crowd may press them at the door again and again
                    self._kept_in.add(row)
                    ctx.event("kept_in", row, exit_name)
                continue
            self.crowd.set_active(row, False)
            if evacuating:
                ctx.counters.evacuated += 1
                ctx.event("evacuated", row, exit_name)
                ctx.status[row] = "evacuated"
            else:
                ctx.event("left_building", row, exit_name)
                ctx.status[row] = f"left through {exit_name}" if exit_name else "left the building"
            if not self.finished[row]:
                self.finished[row] = True
                self._finished_mask[row] = True
                self._q_on[row] = False
                ctx.counters.finished_trees += 1
                self.tree_result[row] = "done"

    def tick_behaviors(self) -> None:
        """Tick every unfinished tree once with the current positions, then order new queue arrivals.

        Trees waiting in a quiescent state (BehaviorTree.quiet) whose leaf condition is a distance or
        a deadline (`quiet_spec`) are checked together in numpy, with margins so that only cases
        certain to be quiet are skipped; everything else goes through BehaviorTree.tick, which
        decides exactly.
        """
        ctx = self.context
        ctx.refresh()
        trees, finished, loops = self.trees, self.finished, self.loops
        quiet_rows = self._quiet_rows()
        alive = np.asarray(self.crowd.active[: len(trees)], dtype=bool) & (~self._finished_mask | self._reacting)
        for row in np.flatnonzero(alive & ~quiet_rows).tolist():
            tree = trees[row]
            quiet = tree.quiet
            # BehaviorTree.tick's quiescent check, inlined for the common guard-free case
            if quiet is not None and not quiet[1] and quiet[0].poll():
                continue
            try:
                status = tree.tick()
            except BTError as exc:
                # One agent's broken tree (say a port reading a blackboard entry nobody sets) stops
                # that agent, with the reason in its status and the event log, not the whole run.
                self._fail_tree(row, str(exc))
                continue
            self._update_quiet_spec(row)
            holding = self._after_task[row]
            if holding is not None and not finished[row] and holding.current > 0:
                # the routine is over; the agent stands there and keeps reacting to the robot
                self._finish(row, "done")
                self._reacting[row] = True
                continue
            if (status == SUCCESS or status == FAILURE) and not loops[row]:
                finished[row] = True
                self._finished_mask[row] = True
                self._q_on[row] = False
                ctx.counters.finished_trees += 1
                self.tree_result[row] = "done" if status == SUCCESS else "failed"
                if ctx.status[row] != "evacuated":
                    ctx.status[row] = f"{ctx.status[row]} · {self.tree_result[row]}" if ctx.status[row] else self.tree_result[row]
        ctx.queues.commit()

    def _finish(self, row: int, result: str) -> None:
        ctx = self.context
        self.finished[row] = True
        self._finished_mask[row] = True
        ctx.counters.finished_trees += 1
        self.tree_result[row] = result
        if ctx.status[row] != "evacuated":
            ctx.status[row] = f"{ctx.status[row]} · {result}" if ctx.status[row] else result

    def _fail_tree(self, row: int, message: str) -> None:
        ctx = self.context
        self._reacting[row] = False
        self.finished[row] = True
        self._finished_mask[row] = True
        self._q_on[row] = False
        ctx.counters.finished_trees += 1
        self.tree_result[row] = "failed"
        self.tree_errors[int(ctx.ids[row])] = message
        self.crowd.set_mode(row, MODE_STOP)
        ctx.status[row] = f"tree error: {message}"
        ctx.event("tree_error", row, message)

    def _update_quiet_spec(self, row: int) -> None:
        tree = self.trees[row]
        self._q_on[row] = False
        quiet = tree.quiet
        if quiet is None:
            return
        leaf, guards = quiet
        spec_of = getattr(leaf, "quiet_spec", None)
        if spec_of is None:
            return
        guard_distance = -1.0
        if guards:
            if len(guards) != 1 or guards[0][1] != FAILURE:
                return
            distance_of = getattr(guards[0][0], "robot_guard_distance", None)
            distance = distance_of() if distance_of is not None else None
            if distance is None:
                return
            guard_distance = float(distance)
        spec = spec_of()
        if spec is None:
            return
        self._q_x[row], self._q_y[row], self._q_r2[row], self._q_t[row] = spec
        self._q_guard[row] = guard_distance
        self._q_on[row] = True

    def _quiet_rows(self) -> np.ndarray:
        """Rows certain to be quiescent this tick (conservative margins; the rest are ticked exactly)."""
        on = self._q_on
        if not on.any():
            return on.copy()
        pos = self.crowd.pos[: len(self.trees)]
        x, y = pos[:, 0], pos[:, 1]
        d2 = (x - self._q_x) ** 2 + (y - self._q_y) ** 2
        ok = on & (d2 > self._q_r2 + 1e-9) & (self.clock.now < self._q_t - 1e-6)
        guarded = np.flatnonzero(ok & (self._q_guard >= 0))
        robot = self.context.robot
        if len(guarded) and robot is not None:
            dx, dy = robot[0] - x[guarded], robot[1] - y[guarded]
            far = dx * dx + dy * dy > self._q_guard[guarded] ** 2 + 1e-6
            turn = (np.arctan2(dy, dx) - self.crowd.yaw[guarded] + np.pi) % (2 * np.pi) - np.pi
            ok[guarded] = far | (np.abs(turn) > VISIBLE_HALF_ANGLE + 1e-6)
        return ok

    def run(self, seconds: float, on_frame: Callable[[Frame], object] | None = None,
            cancel: threading.Event | Callable[[], bool] | None = None) -> Frame:
        """Advance `seconds` of simulation time; on_frame gets a Frame after every BT period."""
        steps = int(round(seconds / self.dt))
        for k in range(steps):
            if cancel is not None and (cancel.is_set() if hasattr(cancel, "is_set") else cancel()):
                break
            self.step()
            if on_frame is not None and (k + 1) % self.bt_every == 0:
                on_frame(self.frame())
        return self.frame()

    # ---- observation ----------------------------------------------------------------------------

    def counters(self) -> CounterSnapshot:
        c = self.context.counters
        return CounterSnapshot(c.reached_goals, self.context.queues.in_queue(), c.served, c.evacuated, c.collisions,
                               c.robot_collisions, c.closest_robot_approach, c.finished_trees)

    def run_state(self) -> RunState:
        n = len(self.trees)
        active = np.asarray(self.crowd.active[:n], dtype=bool)
        # people who keep reacting to a robot after their task still have something to happen to them
        waiting = self._reacting if self.crowd.robot_pos is not None else np.zeros(n, dtype=bool)
        return RunState(n, int(n - active.sum()), int(((self._finished_mask & ~waiting) | ~active).sum()))

    def frame(self) -> Frame:
        crowd = self.crowd
        n = len(self.context.ids)
        active = np.asarray(crowd.active[:n], dtype=bool)
        idx = np.flatnonzero(active)
        ids = np.asarray(self.context.ids, dtype=np.int64)[idx]
        robot = None
        rp, yaw = crowd.robot_pos, crowd.robot_yaw  # None without a robot
        if rp is not None and yaw is not None:
            robot = (float(rp[0]), float(rp[1]), yaw)
        status = tuple(self.context.status[i] for i in idx)
        return Frame(float(crowd.time), self.step_count, _frozen(ids), _frozen(crowd.pos[idx]), _frozen(crowd.vel[idx]),
                     _frozen(crowd.yaw[idx]), _frozen(crowd.group[idx]), status, robot, self.counters())

    def tree_status(self, agent_id: int) -> list[tuple[str, str, str]]:
        row = self.context.row(agent_id)
        return self.trees[row].status_list()

    def agent_status(self, agent_id: int) -> str:
        return self.context.status[self.context.row(agent_id)]

    # ---- bookkeeping ----------------------------------------------------------------------------

    def _measure_contacts(self) -> None:
        crowd, ctx = self.crowd, self.context
        n = len(ctx.ids)
        if n == 0:
            return
        active = np.asarray(crowd.active[:n], dtype=bool)
        pos = crowd.pos[:n]
        radius = crowd.radius[:n]
        c = ctx.counters
        rp, robot_radius = crowd.robot_pos, crowd.robot_radius  # None without a robot
        if rp is not None and robot_radius is not None:
            gap = np.hypot(pos[:, 0] - rp[0], pos[:, 1] - rp[1]) - radius - robot_radius
            gap[~active] = np.inf
            if np.any(active):
                c.closest_robot_approach = min(c.closest_robot_approach, max(0.0, float(gap.min())))
            touching = set(np.flatnonzero(gap < ROBOT_CONTACT_GAP).tolist())
            c.robot_collisions += len(touching - self._robot_contacts)
            still = set(np.flatnonzero(gap < ROBOT_CONTACT_GAP + CONTACT_RELEASE).tolist())
            self._robot_contacts = touching | (self._robot_contacts & still)
        # Only people who were near someone at the start of the last step can touch now: bodies close
        # in by at most two steps, so a gap over CONTACT_RELEASE plus that rules a person out.
        reach = CONTACT_RELEASE + 2.0 * float(crowd.desired_speed[:n].max(initial=0.0)) * crowd.dt
        near_someone = crowd.min_gap[:n] < reach if crowd.step_count else np.ones(n, dtype=bool)
        rows = np.flatnonzero(active & near_someone)
        if len(rows) <= 1:
            self._agent_contacts = set()
        else:
            from scipy.spatial import cKDTree

            p = pos[rows]
            reach = 2.0 * float(radius[rows].max()) + CONTACT_RELEASE
            pairs = cKDTree(p).query_pairs(reach, output_type="ndarray")
            if len(pairs):
                i, j = rows[pairs[:, 0]], rows[pairs[:, 1]]
                # bodies touch at the shoulders (SFMParams.body_fraction of the radius), as in the forces
                body = crowd.params.body_fraction
                gap = np.hypot(pos[i, 0] - pos[j, 0], pos[i, 1] - pos[j, 1]) - body * (radius[i] + radius[j])
                now = set(zip(i[gap < 0.0].tolist(), j[gap < 0.0].tolist()))
                near = set(zip(i[gap < CONTACT_RELEASE].tolist(), j[gap < CONTACT_RELEASE].tolist()))
            else:
                now, near = set(), set()
            c.collisions += len(now - self._agent_contacts)
            self._agent_contacts = now | (self._agent_contacts & near)

    def _record(self) -> None:
        self.recorder.record(self.crowd)


def _make_recorder(dt: float, ids: list[int]) -> TrajectoryRecorder:
    return TrajectoryRecorder(fps=1.0 / dt, id_map=ids)


def _draft_groups(agents: Sequence[AgentSpec]) -> dict[int, tuple[int, ...]]:
    """agent id -> ids of its social group (same SFM group id >= 0); alone otherwise."""
    by_group: dict[int, list[int]] = {}
    for a in agents:
        if a.group >= 0:
            by_group.setdefault(a.group, []).append(a.id)
    return {a.id: tuple(sorted(by_group[a.group])) if a.group >= 0 else (a.id,) for a in agents}


def _goal_table(documents: list[TreeDocument]) -> dict[int, tuple[float, float]]:
    """HuNavSim global goals: every node with a literal goal_id and x/y (as post-processing writes them)."""
    table: dict[int, tuple[float, float]] = {}
    for document in documents:
        for element in document.nodes():
            ports = element.ports
            if "goal_id" in ports and "x" in ports and "y" in ports:
                try:
                    table.setdefault(int(ports["goal_id"]), (float(ports["x"]), float(ports["y"])))
                except ValueError:
                    continue
    return table


def with_robot_reaction(document: TreeDocument, behavior: str) -> TreeDocument:
    """Wrap a tree in HuNavSim's reaction pattern for its scenario behavior (see the module docstring)."""
    spec = REACTION_DEFAULTS.get(behavior)
    if spec is None:
        return document
    if any(e.id in ROBOT_REACTIONS or e.id in ROBOT_ACTIVITIES for e in document.nodes()):
        return document
    reaction_node, distance, duration, once = spec
    wrapper_id = "GroveRobotReaction"
    while wrapper_id in document.trees:
        wrapper_id += "_"
    routine = subtree_call(document.main_tree_id, autoremap=True)
    # ForceFailure: a finished reaction falls through to the routine instead of ending the tree
    reaction = node("Sequence", [
        node("IsRobotVisible", distance=f"{distance:g}"),
        node("ForceFailure", [node(reaction_node, beh_duration=f"{duration:g}",
                                   only_once="true" if once else "false")]),
    ])
    wrapped = TreeDocument(wrapper_id, dict(document.trees), document.source, list(document.models))
    wrapped.add_tree(wrapper_id, node("ReactiveFallback", [reaction, routine], name=f"{behavior} reaction"))
    return wrapped
