"""HuNavSim 2.0 nodes (hunav_agent_manager, BT_manual_generation) on the GROVE crowd, in simulation time.

Port names and defaults are HuNavSim's (see manifest.py). Differences, all deliberate:
- every duration is simulation time (HuNavSim 2.0 mixes in the wall clock);
- the reactions (Surprised/Curious/Scared/ThreateningNav) run as stateful actions: RUNNING for
  `beh_duration` seconds, then SUCCESS with the replaced intents restored; with only_once they FAIL
  on later activations, so the usual Fallback/ReactiveFallback falls through to the routine;
- `duration` = 0 means "until halted" for the stateful agent/robot interactions, as in HuNavSim.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Literal

from grove_tui.crowd.context import Point, SimContext, Snapshot
from grove_tui.crowd.coordination import Conversation
from grove_tui.crowd.led_slots import SLOT_EASE, slot_behind
from grove_tui.crowd.keep_in_place import clear_of_parked_robot, home_zone, in_zone, target_in_place
from grove_tui.crowd.leaves.base import (
    FAILURE, RUNNING, SUCCESS, AgentCondition, AgentStatefulAction, AgentSyncAction, QuietSpec, angle_diff,
)
from grove_tui.errors import BTError
from grove_tui.crowd.sfm import (
    MODE_FACE, MODE_GOALS, MODE_STOP, ROBOT_AS_AGENT, ROBOT_AS_OBSTACLE, ROBOT_FEARED, ROBOT_IGNORED,
)

# What an agent turns to (Crowd.set_face_target): a point, another agent's row, or the robot.
FaceTarget = Point | int | Literal["robot"]

VISIBLE_HALF_ANGLE = math.pi / 2 + 0.17  # HuNavSim IsRobotVisible field of view (each side)
FACING_TOLERANCE = 0.3  # rad, IsRobotFacingAgent
MIN_YAW_TOLERANCE = 0.02  # rad; the crowd turns at most 2*pi rad/s, 0.01 can be overshot by rounding


# ---- conditions ---------------------------------------------------------------------------------

class IsGoalReached(AgentCondition):
    __slots__ = ()
    PURE = True  # reads positions only: usable as a guard of quiescent ticks

    def tick(self) -> int:
        return SUCCESS if self.sim.crowd.goal_reached(self.row) else FAILURE


class IsRobotVisible(AgentCondition):
    __slots__ = ("distance",)
    distance: float | None  # its literal range; None when read from the blackboard
    PURE = True

    def robot_guard_distance(self) -> float | None:
        """Its literal range, so the simulation can check many agents' guards at once."""
        return self.distance

    def setup(self) -> None:
        super().setup()
        self.distance = self.get_input("distance") if self.is_literal("distance") else None

    def tick(self) -> int:
        sim = self.sim
        robot = sim.robot
        if robot is None:
            return FAILURE
        row = self.row
        dx = robot[0] - sim.px[row]
        dy = robot[1] - sim.py[row]
        distance = self.distance if self.distance is not None else self.get_input("distance")
        if dx * dx + dy * dy > distance * distance:
            return FAILURE
        if abs(angle_diff(math.atan2(dy, dx), sim.yaw[self.row])) <= VISIBLE_HALF_ANGLE:
            return SUCCESS
        return FAILURE


class IsRobotClose(AgentCondition):
    __slots__ = ()
    PURE = True  # reads positions only: usable as a guard of quiescent ticks

    def tick(self) -> int:
        robot = self.sim.robot
        if robot is None:
            return FAILURE
        p = self.sim.pos[self.row]
        threshold = self.get_input("threshold")
        return SUCCESS if math.hypot(robot[0] - p[0], robot[1] - p[1]) <= threshold else FAILURE


class IsRobotFacingAgent(AgentCondition):
    __slots__ = ()
    PURE = True  # reads positions only: usable as a guard of quiescent ticks

    def tick(self) -> int:
        robot = self.sim.robot
        if robot is None:
            return FAILURE
        p = self.sim.pos[self.row]
        bearing = math.atan2(p[1] - robot[1], p[0] - robot[0])
        return SUCCESS if abs(angle_diff(bearing, robot[2])) <= FACING_TOLERANCE else FAILURE


class TimeExpiredCondition(AgentCondition):
    """Adds `ts` per tick; FAILURE until `seconds` accumulate, then SUCCESS (and restarts unless only_once)."""

    __slots__ = ("total",)
    total: float

    def setup(self) -> None:  # counts its own `ts`: bound to no agent
        self.row = -1
        self.total = 0.0

    def tick(self) -> int:
        self.total += float(self.get_input("ts"))
        if self.total + 1e-9 >= float(self.get_input("seconds")):
            if not self.get_input("only_once"):
                self.total = 0.0
            return SUCCESS
        return FAILURE


class RandomChanceCondition(AgentCondition):
    __slots__ = ()

    def tick(self) -> int:
        return SUCCESS if self.sim.rng.random() < self.get_input("probability") else FAILURE


def _other_row(node: AgentCondition | AgentSyncAction | AgentStatefulAction, port: str) -> int | None:
    value = node.get_input(port)
    if value is None:
        return node.sim.partner_of(node.row)
    return node.sim.row(value, f"{node.node_id}.{port}")


class IsAgentVisible(AgentCondition):
    __slots__ = ()
    PURE = True  # reads positions only: usable as a guard of quiescent ticks
    AGENT_PORT = "observer_id"

    def tick(self) -> int:
        other = _other_row(self, "agent_id")
        if other is None or not self.sim.active[other]:
            return FAILURE
        p, q = self.sim.pos[self.row], self.sim.pos[other]
        dx, dy = q[0] - p[0], q[1] - p[1]
        if math.hypot(dx, dy) > self.get_input("distance"):
            return FAILURE
        fov = self.get_input("field_of_view")
        return SUCCESS if abs(angle_diff(math.atan2(dy, dx), self.sim.yaw[self.row])) <= fov else FAILURE


class IsAgentClose(AgentCondition):
    __slots__ = ()
    PURE = True  # reads positions only: usable as a guard of quiescent ticks
    AGENT_PORT = "observer_id"

    def tick(self) -> int:
        other = _other_row(self, "target_agent_id")
        if other is None or not self.sim.active[other]:
            return FAILURE
        p, q = self.sim.pos[self.row], self.sim.pos[other]
        return SUCCESS if math.hypot(q[0] - p[0], q[1] - p[1]) <= self.get_input("threshold") else FAILURE


class IsAtPosition(AgentCondition):
    __slots__ = ()
    PURE = True  # reads positions only: usable as a guard of quiescent ticks

    def tick(self) -> int:
        tx, ty = self.get_input("target_x"), self.get_input("target_y")
        if tx is None or ty is None:
            goal_id = self.get_input("goal_id")
            if goal_id is None or goal_id not in self.sim.goal_table:
                return FAILURE
            tx, ty = self.sim.goal_table[goal_id]
        p = self.sim.pos[self.row]
        return SUCCESS if math.hypot(tx - p[0], ty - p[1]) <= self.get_input("tolerance") else FAILURE


class _Watch(AgentStatefulAction):
    """Stateful condition: RUNNING while watching, SUCCESS when seen, FAILURE after `duration`."""

    __slots__ = ()

    def on_start(self) -> int:
        self.started_at = self.sim.clock.now
        return self.on_running()

    def on_running(self) -> int:
        found = self.look()
        if found is not None:
            return SUCCESS
        duration = self.get_input("duration")
        if duration > 0 and self.elapsed() + 1e-9 >= duration:
            return FAILURE
        return RUNNING

    def look(self) -> int | None:
        """Who the watching condition looks for (an agent row, or None); each subclass says."""
        raise NotImplementedError(f"{type(self).__name__} must define look()")


class IsAnyoneSpeaking(_Watch):
    __slots__ = ()

    def look(self) -> int | None:
        sim = self.sim
        p = sim.pos[self.row]
        limit = self.get_input("distance_threshold")
        for _, speaker, _ in sim.speech.since(self.started_at - 1.0):
            if speaker != self.row:
                q = sim.pos[speaker]
                if math.hypot(q[0] - p[0], q[1] - p[1]) <= limit:
                    self.set_output("speaker_id", sim.ids[speaker])
                    return speaker
        return None


class IsSpeaking(_Watch):
    __slots__ = ()

    def look(self) -> int | None:
        sim = self.sim
        target = _other_row(self, "target_id")
        if target is None:
            return None
        p, q = sim.pos[self.row], sim.pos[target]
        if math.hypot(q[0] - p[0], q[1] - p[1]) > self.get_input("distance_threshold"):
            return None
        for _, speaker, _ in sim.speech.since(self.started_at - 1.0):
            if speaker == target:
                return speaker
        return None


def _looks_at(sim: SimContext, observer: int, row: int, angle_threshold: float, distance: float) -> bool:
    if not sim.active[observer]:
        return False
    p, q = sim.pos[row], sim.pos[observer]
    dx, dy = p[0] - q[0], p[1] - q[1]
    if math.hypot(dx, dy) > distance:
        return False
    return abs(angle_diff(math.atan2(dy, dx), sim.yaw[observer])) <= angle_threshold


class IsAnyoneLookingAtMe(_Watch):
    __slots__ = ()

    def look(self) -> int | None:
        sim = self.sim
        angle, distance = self.get_input("angle_threshold"), self.get_input("distance_threshold")
        for other in range(len(sim.ids)):
            if other != self.row and _looks_at(sim, other, self.row, angle, distance):
                self.set_output("observer_id", sim.ids[other])
                return other
        return None


class IsLookingAtMe(_Watch):
    __slots__ = ()

    def look(self) -> int | None:
        target = _other_row(self, "target_id")
        if target is None:
            return None
        ok = _looks_at(self.sim, target, self.row, self.get_input("angle_threshold"),
                       self.get_input("distance_threshold"))
        return target if ok else None


# ---- simple actions -----------------------------------------------------------------------------

class UpdateGoal(AgentSyncAction):
    __slots__ = ()

    def tick(self) -> int:
        self.sim.crowd.advance_goal(self.row)
        return SUCCESS


class RegularNav(AgentSyncAction):
    """The agent walks its goal list (HuNavSim's regular SFM step happens in the crowd step)."""

    __slots__ = ()

    def tick(self) -> int:
        crowd = self.sim.crowd
        if crowd.mode[self.row] != MODE_GOALS:
            crowd.set_mode(self.row, MODE_GOALS)
        self.sim.status[self.row] = "walking"
        return SUCCESS


class FindNearestAgent(AgentSyncAction):
    __slots__ = ()

    def tick(self) -> int:
        other = self.sim.nearest_agent(self.row)
        if other is None:
            return FAILURE
        self.set_output("target_agent_id", self.sim.ids[other])
        return SUCCESS


class SaySomething(AgentSyncAction):
    __slots__ = ()

    def tick(self) -> int:
        message = str(self.get_input("message"))
        self.sim.speech.say(self.sim.clock.now, self.row, message)
        self.sim.status[self.row] = f'says "{message[:40]}"'
        return SUCCESS


class SetGroupId(AgentSyncAction):
    __slots__ = ()

    def tick(self) -> int:
        group_id = self.get_input("group_id")
        if group_id is None:
            return FAILURE
        self.sim.crowd.set_group(self.row, int(group_id))
        return SUCCESS


def goal_point(node: AgentSyncAction | AgentStatefulAction, x_port: str = "target_x",
               y_port: str = "target_y") -> Point | None:
    """A node's point: its global goal (goal_id), else the literal x/y ports older HuNavSim 2.0 trees
    wrote (manifest._legacy_point); None when it names neither."""
    goal_id = node.get_input("goal_id")
    if goal_id is not None and goal_id in node.sim.goal_table:
        return node.sim.goal_table[goal_id]
    x, y = node.get_input(x_port), node.get_input(y_port)
    return (float(x), float(y)) if x is not None and y is not None else None


class SetGoal(AgentSyncAction):
    __slots__ = ()

    def tick(self) -> int:
        point = goal_point(self)
        if point is None:
            return FAILURE
        crowd = self.sim.crowd
        crowd.append_goal(self.row, point)
        return SUCCESS


class StopMovement(AgentSyncAction):
    __slots__ = ()

    def tick(self) -> int:
        self.sim.crowd.set_speed(self.row, 0.0)
        self.sim.status[self.row] = "stopped"
        return SUCCESS


class ResumeMovement(AgentSyncAction):
    __slots__ = ()

    def tick(self) -> int:
        self.sim.crowd.set_speed(self.row, self.sim.base_speed[self.row])
        return SUCCESS


# ---- stateful actions ---------------------------------------------------------------------------

class _Timed(AgentStatefulAction):
    """Save intents, run `step()` each tick for `duration` seconds (0 = until halted), restore."""

    __slots__ = ("last_goal", "last_speed", "facing", "routed_to")
    last_goal: Point | None
    last_speed: float | None
    facing: FaceTarget | None
    routed_to: Point | None
    DURATION_PORT = "duration"
    LABEL = ""
    REGOAL = 0.2  # metres a moving target must shift before the goal intent is rewritten
    REROUTE = 2.0  # metres a target out of sight must shift before the route to it is planned again
    ROBOT_EVENT = False  # log a "robot_reaction" event when it starts (reactions to the robot)

    def setup(self) -> None:
        super().setup()
        self.last_goal = None
        self.last_speed = None
        self.facing = None
        self.routed_to = None

    def on_start(self) -> int:
        self.started_at = self.sim.clock.now
        self.last_goal = self.last_speed = self.facing = self.routed_to = None
        self.save_intents()
        self.begin()
        if self.LABEL:
            self.sim.status[self.row] = self.LABEL
        if self.ROBOT_EVENT:
            self.sim.event("robot_reaction", self.row, type(self).__name__)
        return self.on_running()

    def on_running(self) -> int:
        duration = self.get_input(self.DURATION_PORT)
        if duration > 0 and self.elapsed() + 1e-9 >= duration:
            self.restore_intents()
            return SUCCESS
        self.step()
        return RUNNING

    def on_halted(self) -> None:
        self.restore_intents()

    def poll(self) -> bool:
        """True when on_running would only return RUNNING: no per-tick step and time left."""
        if type(self).step is not _Timed.step:
            return False
        duration = self.get_input(self.DURATION_PORT)
        return duration <= 0 or self.elapsed() + 1e-9 < duration

    def quiet_spec(self) -> QuietSpec | None:
        if type(self).step is not _Timed.step:
            return None
        duration = self.get_input(self.DURATION_PORT)
        return (0.0, 0.0, -1.0, self.started_at + duration - 1e-9 if duration > 0 else math.inf)

    def begin(self) -> None:
        """Set the intents the behavior starts with."""

    def step(self) -> None:
        """Update intents from the current positions."""

    # shared moves
    def walk_to(self, point: Point, speed: float | None = None, goal_radius: float = 0.15,
                beyond: Point | None = None) -> None:
        """Walk to `point`; out of sight of it, the planned way to `beyond` when given (the robot a
        point short of it is approached: that point may lie in the wall beside a door, which the
        planner moves to the near side of the wall, and the agent walks along it instead of through)."""
        # the target (robot, another agent) moves a few centimetres per tick: rewriting the intents
        # only when it shifted REGOAL or the speed changed by 5 % keeps the behaviour and the cost low
        crowd = self.sim.crowd
        last = self.last_goal
        if self.facing is not None or last is None or math.dist(last, point) > self.REGOAL:
            sim = self.sim
            here = sim.pos[self.row]
            if sim.sees(here, point):
                crowd.set_goals(self.row, [point], goal_radius=goal_radius)
                self.routed_to = None
            elif self.routed_to is None or math.dist(self.routed_to, point) > self.REROUTE or self.facing is not None:
                # out of sight (another room): walk the planned way there, not into the wall between
                crowd.set_goals(self.row, sim.plan(here, beyond if beyond is not None else point),
                                goal_radius=goal_radius)
                self.routed_to = (float(point[0]), float(point[1]))
            self.last_goal = (float(point[0]), float(point[1]))
            if crowd.mode[self.row] != MODE_GOALS:
                crowd.set_mode(self.row, MODE_GOALS)
            self.facing = None
        if speed is not None:
            speed = max(0.0, speed)
            if self.last_speed is None or abs(speed - self.last_speed) > 0.05 * max(self.last_speed, 0.1):
                crowd.set_speed(self.row, speed)
                self.last_speed = speed

    def face(self, target: FaceTarget) -> None:
        if self.facing == target:
            return
        crowd = self.sim.crowd
        crowd.set_face_target(self.row, target)
        if crowd.mode[self.row] != MODE_FACE:
            crowd.set_mode(self.row, MODE_FACE)
        self.facing = target


class StopAndWaitTimerAction(_Timed):
    __slots__ = ()
    DURATION_PORT = "wait_duration"
    LABEL = "waiting"

    def begin(self) -> None:
        self.sim.crowd.set_mode(self.row, MODE_STOP)


def _toward(p: Sequence[float], q: Sequence[float], keep: float) -> tuple[Point, float]:
    """The point `keep` metres short of q on the way from p."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    d = math.hypot(dx, dy)
    if d <= keep or d < 1e-9:
        return (p[0], p[1]), d
    f = (d - keep) / d
    return (p[0] + dx * f, p[1] + dy * f), d


class _Reaction(_Timed):
    """HuNavSim reaction to the robot, see agent_manager.cpp (2.0 behaviours, section 3 of the reference)."""

    __slots__ = ("used",)
    used: bool
    DURATION_PORT = "beh_duration"
    INTERACTION = ROBOT_IGNORED
    ROBOT_EVENT = True

    def setup(self) -> None:
        super().setup()
        self.used = False

    def on_start(self) -> int:
        if self.used and self.get_input("only_once"):
            return FAILURE
        if self.sim.robot is None:
            return FAILURE
        self.used = True
        return super().on_start()

    def begin(self) -> None:
        # HuNavSim 2.0: while a reaction is active the robot leaves the agent's social forces
        self.sim.crowd.set_robot_interaction(self.row, self.INTERACTION)


class SurprisedNav(_Reaction):
    __slots__ = ()
    LABEL = "surprised by the robot"

    def begin(self) -> None:
        super().begin()
        self.face("robot")

    def step(self) -> None:
        # Started in a ReactiveFallback, it halts the routine after it (a Queue, a GoTo), and the halt stands
        # the person still (MODE_STOP) after begin() turned them to the robot: turn to it again.
        if self.sim.crowd.mode[self.row] != MODE_FACE:
            self.facing = None
            self.face("robot")


class CuriousNav(_Reaction):
    __slots__ = ()
    LABEL = "curious about the robot"

    def step(self) -> None:
        robot = self.sim.robot
        if robot is None:
            return  # the robot left; the reaction ends with its duration
        p = self.sim.pos[self.row]
        stop = self.get_input("stop_distance")
        bodies = (self.sim.crowd.robot_radius or 0.3) + float(self.sim.crowd.radius[self.row])
        goal, d = _toward(p, robot, stop + bodies)
        if d - bodies <= stop + 0.1:
            self.face("robot")
        else:
            # HuNavSim 2.0: slow down on the way, speed = max_vel * d / (d + closest)
            self.walk_to(goal, self.get_input("agent_vel") * d / (d + max(stop, 0.1)))


class ScaredNav(_Reaction):
    __slots__ = ()
    LABEL = "scared of the robot"
    INTERACTION = ROBOT_FEARED
    SAFE_DISTANCE = 3.0  # HuNavSim's newest ScaredNav flees to robot + safe_distance along the escape line

    def begin(self) -> None:
        super().begin()
        base_other = float(self.sim.crowd.factors[self.row, 3])
        self.sim.crowd.set_factors(self.row, other=base_other * self.get_input("scary_force_factor"))

    def step(self) -> None:
        _flee(self, self.SAFE_DISTANCE, self.get_input("runaway_vel"))


def _flee(node: _Timed, safe_distance: float, speed: float) -> None:
    sim = node.sim
    robot = sim.robot
    if robot is None:
        return  # the robot left; the reaction ends with its duration
    p = sim.pos[node.row]
    dx, dy = p[0] - robot[0], p[1] - robot[1]
    d = math.hypot(dx, dy)
    if d >= safe_distance:
        node.face("robot")
        return
    ux, uy = (dx / d, dy / d) if d > 1e-6 else (math.cos(sim.yaw[node.row]), math.sin(sim.yaw[node.row]))
    target = sim.nearest_free(robot[0] + ux * (safe_distance + 0.3), robot[1] + uy * (safe_distance + 0.3))
    node.walk_to(target, speed)


class ThreateningNav(_Reaction):
    __slots__ = ()
    LABEL = "confronting the robot"
    SPEED = 2.5

    def step(self) -> None:
        sim = self.sim
        if sim.robot is None:
            return  # the robot left; the reaction ends with its duration
        rx, ry, ryaw = sim.robot
        g = self.get_input("goal_dist")
        g = g if g > 0.5 else 1.5
        target = sim.nearest_free(rx + g * math.cos(ryaw), ry + g * math.sin(ryaw))
        p = sim.pos[self.row]
        if math.dist(target, p) <= 0.8 and sim.robot_speed <= 0.1:
            self.face("robot")
        else:
            self.walk_to(target, self.SPEED)


class ApproachRobot(_Timed):
    __slots__ = ()
    ROBOT_EVENT = True
    LABEL = "approaching the robot"

    def begin(self) -> None:
        self.sim.crowd.set_robot_interaction(self.row, ROBOT_IGNORED)

    def step(self) -> None:
        robot = self.sim.robot
        if robot is None:
            return
        p = self.sim.pos[self.row]
        closest = self.get_input("closest_dist")
        behind = self.get_input("behind")
        spot = slot_behind(self.sim, self.row, robot, behind) if behind is not None and behind > 0 else None
        if spot is not None:
            # people the robot leads walk to their place behind it, not at it (crowd/led_slots.py)
            goal, d = spot, math.dist(p, spot)
            if d <= 0.3:
                self.face("robot")
            else:
                self.walk_to(goal, self.get_input("max_vel") * d / (d + SLOT_EASE),
                             beyond=(float(robot[0]), float(robot[1])))
            return
        goal, d = _toward(p, robot, closest)
        if d <= closest + 0.1:
            self.face("robot")
        else:
            self.walk_to(goal, self.get_input("max_vel") * d / (d + max(closest, 0.1)),
                         beyond=(float(robot[0]), float(robot[1])))


class ApproachAgent(_Timed):
    __slots__ = ()
    LABEL = "approaching someone"

    def step(self) -> None:
        other = _other_row(self, "target_agent_id")
        if other is None:
            return
        p, q = self.sim.pos[self.row], self.sim.pos[other]
        closest = self.get_input("closest_dist")
        goal, d = _toward(p, q, closest)
        if d <= closest + 0.1:
            self.face(other)
        else:
            self.walk_to(goal, self.get_input("max_vel"), beyond=(float(q[0]), float(q[1])))


class BlockRobot(_Timed):
    __slots__ = ()
    ROBOT_EVENT = True
    LABEL = "blocking the robot"

    def begin(self) -> None:
        self.sim.crowd.set_robot_interaction(self.row, ROBOT_AS_OBSTACLE)

    def step(self) -> None:
        robot = self.sim.robot
        if robot is None:
            return
        front = self.get_input("front_dist")
        target = self.sim.nearest_free(robot[0] + front * math.cos(robot[2]), robot[1] + front * math.sin(robot[2]))
        if math.dist(target, self.sim.pos[self.row]) <= 0.3:
            self.face("robot")
        else:
            self.walk_to(target, 1.5)


class BlockAgent(_Timed):
    __slots__ = ()
    LABEL = "blocking someone"

    def step(self) -> None:
        other = _other_row(self, "target_agent_id")
        if other is None:
            return
        q, yaw = self.sim.pos[other], self.sim.yaw[other]
        front = self.get_input("front_dist")
        target = self.sim.nearest_free(q[0] + front * math.cos(yaw), q[1] + front * math.sin(yaw))
        if math.dist(target, self.sim.pos[self.row]) <= 0.3:
            self.face(other)
        else:
            self.walk_to(target, 1.5)


class AvoidRobot(_Timed):
    """Keeps away inside the zone it stood in when the robot came, and lets the routine go on once the
    robot stands at the end of its drive a personal distance off (crowd/keep_in_place.py)."""

    __slots__ = ("home",)
    home: str | None
    ROBOT_EVENT = True
    LABEL = "keeping away from the robot"

    def on_start(self) -> int:
        if clear_of_parked_robot(self.sim, self.sim.pos[self.row], self.get_input("safe_distance")):
            return FAILURE  # the robot has gone: the routine goes on
        return super().on_start()

    def on_running(self) -> int:
        if clear_of_parked_robot(self.sim, self.sim.pos[self.row], self.get_input("safe_distance")):
            self.restore_intents()
            return SUCCESS
        return super().on_running()

    def setup(self) -> None:
        super().setup()
        self.home = None

    def begin(self) -> None:
        self.home = home_zone(self.sim, self.sim.pos[self.row])
        self.sim.crowd.set_robot_interaction(self.row, ROBOT_FEARED)

    def step(self) -> None:
        robot = self.sim.robot
        if robot is None:
            return
        safe, speed = self.get_input("safe_distance"), self.get_input("runaway_vel")
        here = self.sim.pos[self.row]
        if math.hypot(here[0] - robot[0], here[1] - robot[1]) >= safe and \
                (self.home is None or in_zone(self.sim, self.home, here)):
            self.face("robot")
            return
        # too near, or pushed out of their place while standing clear of it: to a clear point of the place
        target = target_in_place(self.sim, self.home, here, (robot[0], robot[1]), safe)
        if target is None:
            _flee(self, safe, speed)
        else:
            self.walk_to(target, speed)


class FollowAgent(_Timed):
    __slots__ = ()
    LABEL = "following"

    def step(self) -> None:
        other = _other_row(self, "target_agent_id")
        if other is None:
            return
        p, q = self.sim.pos[self.row], self.sim.pos[other]
        closest = max(self.get_input("closest_dist"), 0.1)
        d = math.hypot(q[0] - p[0], q[1] - p[1])
        vmax = self.get_input("max_vel")
        speed = vmax if d > closest else vmax * (d / closest) ** 2
        self.walk_to((q[0], q[1]), speed, goal_radius=0.2)


class SetGroupWalk(_Timed):
    """The main agent's group id and goals are given to the listed agents for `duration`."""

    __slots__ = ("followers",)
    followers: list[tuple[int, Snapshot, int]]  # (row, intents, group) of each follower, to give back
    AGENT_PORT = "main_agent_id"
    LABEL = "leading a group"

    def setup(self) -> None:
        super().setup()
        self.followers = []

    def begin(self) -> None:
        sim = self.sim
        ids = self.get_input("non_main_agent_ids") or ()
        if not ids:
            ids = tuple(i for i in sim.members_of(sim.ids[self.row]) if i != sim.ids[self.row])
        rows = [sim.row(i, "non_main_agent_ids") for i in ids]
        crowd = sim.crowd
        group = int(crowd.group[self.row])
        if group < 0:
            group = 100000 + sim.ids[self.row]
            crowd.set_group(self.row, group)
        goals = crowd.goals(self.row)
        saved: list[tuple[int, Snapshot, int]] = []
        for row in rows:
            saved.append((row, sim.snapshot(row), int(crowd.group[row])))
            crowd.set_group(row, group)
            crowd.set_goals(row, goals)
            crowd.set_mode(row, MODE_GOALS)
        self.followers = saved

    def on_running(self) -> int:
        status = super().on_running()
        if status == SUCCESS:
            self._release()
        return status

    def on_halted(self) -> None:
        self._release()
        super().on_halted()

    def _release(self) -> None:
        for row, snap, group in self.followers:
            self.sim.restore(row, snap)
            self.sim.crowd.set_group(row, group)
        self.followers = []


class _LookAt(AgentStatefulAction):
    __slots__ = ()

    def poll(self) -> bool:
        return self.on_running() == RUNNING  # on_running only reads positions

    def target(self) -> FaceTarget | None:
        """Where the approach goes; each subclass says (the robot, an agent)."""
        raise NotImplementedError(f"{type(self).__name__} must define target()")

    def on_start(self) -> int:
        target = self.target()
        if target is None:
            return FAILURE
        self.sim.crowd.set_face_target(self.row, target)
        self.sim.crowd.set_mode(self.row, MODE_FACE)
        return self.on_running()

    def on_running(self) -> int:
        target = self.target()
        if target is None:
            return FAILURE
        point: Sequence[float]
        if isinstance(target, str):
            if self.sim.robot is None:
                return FAILURE
            point = self.sim.robot
        elif isinstance(target, int):
            point = self.sim.pos[target]
        else:
            point = target
        p = self.sim.pos[self.row]
        bearing = math.atan2(point[1] - p[1], point[0] - p[0])
        tolerance = max(self.get_input("yaw_tolerance"), MIN_YAW_TOLERANCE)
        return SUCCESS if abs(angle_diff(bearing, self.sim.yaw[self.row])) <= tolerance else RUNNING


class LookAtRobot(_LookAt):
    __slots__ = ()

    def target(self) -> FaceTarget | None:
        return "robot" if self.sim.robot is not None else None

    def on_start(self) -> int:
        if self.sim.robot is not None:
            self.sim.event("robot_reaction", self.row, "LookAtRobot")
        return super().on_start()


class LookAtAgent(_LookAt):
    __slots__ = ()
    AGENT_PORT = "observer_id"

    def target(self) -> FaceTarget | None:
        return _other_row(self, "target_id")


class LookAtPoint(_LookAt):
    __slots__ = ()

    def target(self) -> FaceTarget | None:
        return goal_point(self)


class ConversationFormation(AgentStatefulAction):
    """HuNavSim's conversation: the main agent's node drives every participant (spots, facing, timer)."""

    __slots__ = ("conv", "rows", "snaps")
    conv: Conversation  # joined by on_start
    rows: list[int]
    snaps: list[tuple[int, Snapshot]]  # (row, intents to give back) of every participant
    AGENT_PORT = "main_agent_id"

    def setup(self) -> None:
        super().setup()
        self.rows = []
        self.snaps = []

    def on_start(self) -> int:
        sim = self.sim
        goal_id = self.get_input("goal_id")
        centre = goal_point(self, "center_x", "center_y")
        if centre is None:
            raise BTError(f"{self.path} ConversationFormation: goal_id={goal_id!r} is not a known global goal")
        others = self.get_input("non_main_agent_ids") or ()
        self.rows = [self.row] + [sim.row(i, "non_main_agent_ids") for i in others]
        self.snaps = [(r, sim.snapshot(r)) for r in self.rows]
        self.conv = sim.conversations.join(centre, tuple(self.rows), self.row)
        for r in self.rows:
            spot = self.conv.spots[r]
            sim.crowd.set_goals(r, sim.plan(sim.pos[r], spot), goal_radius=0.1)
            sim.crowd.set_mode(r, MODE_GOALS)
            sim.status[r] = "joining a conversation"
        return RUNNING

    def on_running(self) -> int:
        sim, conv = self.sim, self.conv
        for r in self.rows:
            spot = conv.spots[r]
            p = sim.pos[r]
            if r not in conv.ready and math.hypot(spot[0] - p[0], spot[1] - p[1]) <= 0.3:
                sim.crowd.set_face_target(r, conv.centre)
                sim.crowd.set_mode(r, MODE_FACE)
                sim.status[r] = "talking"
                sim.conversations.mark_ready(conv, r)
        if conv.started_at is not None:
            duration = self.get_input("conversation_duration")
            if duration > 0 and sim.clock.now - conv.started_at + 1e-9 >= duration:
                self._finish()
                return SUCCESS
        return RUNNING

    def on_halted(self) -> None:
        self._finish()

    def _finish(self) -> None:
        for r, snap in self.snaps:
            self.sim.restore(r, snap)
            self.sim.conversations.leave(self.conv, r)
        self.snaps = []


HUNAV_LEAVES = {
    cls.__name__: cls
    for cls in (
        IsGoalReached, IsRobotVisible, IsRobotClose, IsRobotFacingAgent, TimeExpiredCondition, RandomChanceCondition,
        IsAgentVisible, IsAgentClose, IsAtPosition, IsAnyoneSpeaking, IsSpeaking, IsAnyoneLookingAtMe, IsLookingAtMe,
        UpdateGoal, RegularNav, FindNearestAgent, SaySomething, SetGroupId, SetGoal, StopMovement, ResumeMovement,
        StopAndWaitTimerAction, SurprisedNav, CuriousNav, ScaredNav, ThreateningNav, ApproachRobot, ApproachAgent,
        BlockRobot, BlockAgent, AvoidRobot, FollowAgent, SetGroupWalk, LookAtRobot, LookAtAgent, LookAtPoint,
        ConversationFormation,
    )
}
ROBOT_REACTIONS = ("SurprisedNav", "CuriousNav", "ScaredNav", "ThreateningNav")
# Nodes through which a tree deals with the robot on purpose (not HuNavSim's cued reactions): a tree
# with one of them already reacts to the robot and is not wrapped in a reaction pattern.
ROBOT_ACTIVITIES = ("ApproachRobot", "BlockRobot", "AvoidRobot", "LookAtRobot")
# HuNavSim behavior type -> (reaction node, trigger distance m, duration s, only once): HuNavSim 1.0
# values. The simulation wraps a tree in this pattern at run time; generation writes it into the tree.
ROBOT_REACTION_DEFAULTS = {
    "Surprised": ("SurprisedNav", 4.0, 30.0, True),
    "Scared": ("ScaredNav", 3.0, 40.0, False),
    "Curious": ("CuriousNav", 10.0, 30.0, True),
    "Threatening": ("ThreateningNav", 4.0, 40.0, True),
}
__all__ = ["HUNAV_LEAVES", "ROBOT_ACTIVITIES", "ROBOT_REACTIONS", "ROBOT_REACTION_DEFAULTS", "ROBOT_AS_AGENT"]
