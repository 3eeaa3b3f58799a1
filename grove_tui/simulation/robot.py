"""The scripted robot: what it does with its planned path, and how it stops for people in its way.

The crowd moves the robot along a path at its top speed (crowd/sfm.py); this driver decides the
path and the speed limit once per behavior-tree tick, as a simple navigation stack would:

- task "cross" drives the path once, "wait" stays at the start, "patrol" drives it there and back
  again, "follow" keeps a short distance behind the people it follows (replanned every second);
- a person standing in the corridor just ahead of the robot stops it (a collision monitor, as Nav2's
  stops a real base): it holds still for HOLD_SECONDS, then creeps on at CREEP_SPEED so people can
  make way, and drives at full speed again once the corridor is clear. Someone who keeps stepping in
  front of it (blocking the robot) therefore slows it, as a researcher expects.

A robot driven by a velocity command (the app's arrow keys, a Gymnasium policy) is left alone.
Stops and resumes are logged as events (agent id 0, the robot): "robot_stopped" with the ids in the
way, "robot_resumed".
"""

from __future__ import annotations

import math

import numpy as np

from grove_tui.crowd.context import SimContext
from grove_tui.crowd.crowd import Crowd
from grove_tui.scenario.model import RobotSpec

STOP_GAP = 0.6  # metres between bodies ahead of the robot at which it stops
SIDE_MARGIN = 0.05  # metres added to both bodies' radii for the corridor's half width
HOLD_SECONDS = 2.0  # standing still before creeping on
CREEP_SPEED = 0.15  # m/s while someone stays in the way
FOLLOW_BEHIND = 1.2  # metres the following robot keeps from the person it follows
FOLLOW_REPLAN = 1.0  # seconds between the follower's new paths
ROBOT_ID = 0


class RobotDriver:
    def __init__(self, spec: RobotSpec, crowd: Crowd, context: SimContext) -> None:
        self.spec = spec
        self.crowd = crowd
        self.context = context
        self.task = getattr(spec, "task", "cross")
        self.path = np.asarray(spec.path if spec.path else [spec.start, spec.goal], dtype=np.float64).reshape(-1, 2)
        self.max_vel = float(spec.max_vel)
        self.blocked_since: float | None = None
        self.follows = tuple(getattr(spec, "follows", ()) or ())
        self._next_follow = 0.0
        self._outbound = True
        # a "cross" that stops on the way (a pick-up): its path in legs, each but the last ending at a stop
        self.legs, self.holds = split_at_stops(self.path, getattr(spec, "stops", ()) or ()) \
            if self.task == "cross" else ([self.path], [])
        self._held_until: float | None = None

    def initial_path(self) -> np.ndarray:
        if self.task == "wait" or self.task == "follow":
            return self.path[:1]
        return self.legs[0] if self.holds else self.path

    def update(self) -> None:
        crowd = self.crowd
        if not crowd.has_robot:
            return
        if crowd.robot_commanded:
            # Someone else drives: its full speed is theirs to use.
            self.blocked_since = None
            if crowd.robot_speed_limit != self.max_vel:
                crowd.set_robot_speed_limit(self.max_vel)
            return
        now = self.context.clock.now
        if self.task == "patrol" and crowd.robot_path_done and len(self.path) > 1:
            self._outbound = not self._outbound
            crowd.set_robot_path(self.path if self._outbound else self.path[::-1])
        elif self.task == "follow" and now >= self._next_follow:
            self._next_follow = now + FOLLOW_REPLAN
            self._follow()
        elif self.holds and crowd.robot_path_done:
            self._stop_on_the_way(now)
        self._collision_monitor(now)

    def _stop_on_the_way(self, now: float) -> None:
        """At the end of a leg that ends at a stop: stand there its seconds, then drive the next leg."""
        if self._held_until is None:
            self._held_until = now + self.holds[0]
            self.context.events.append((now, ROBOT_ID, "robot_stop", f"{self.holds[0]:g}"))
        if now + 1e-9 < self._held_until:
            return
        self._held_until = None
        self.holds.pop(0)
        self.legs.pop(0)
        self.context.events.append((now, ROBOT_ID, "robot_stop_done", ""))
        self.crowd.set_robot_path(self.legs[0])

    def _follow(self) -> None:
        ctx, crowd = self.context, self.crowd
        rows = [ctx.row_of[i] for i in self.follows if i in ctx.row_of and crowd.active[ctx.row_of[i]]]
        robot_pos = crowd.robot_pos
        if not rows or robot_pos is None:
            crowd.set_robot_path([(float(robot_pos[0]), float(robot_pos[1]))] if robot_pos is not None else None)
            return
        robot = (float(robot_pos[0]), float(robot_pos[1]))
        target = min(((float(crowd.pos[r, 0]), float(crowd.pos[r, 1])) for r in rows),
                     key=lambda p: math.dist(p, robot))
        d = math.dist(target, robot)
        if d <= FOLLOW_BEHIND:
            crowd.set_robot_path([robot])
            return
        f = (d - FOLLOW_BEHIND) / d
        goal = (robot[0] + (target[0] - robot[0]) * f, robot[1] + (target[1] - robot[1]) * f)
        route = [goal] if ctx.sees(robot, goal) else ctx.plan(robot, goal)
        crowd.set_robot_path([robot, *route])

    def _collision_monitor(self, now: float) -> None:
        crowd, ctx = self.crowd, self.context
        n = len(ctx.ids)
        robot = crowd.robot_pos
        blockers: list[int] = []
        if n and robot is not None:
            yaw = float(crowd.robot_yaw or 0.0)
            hx, hy = math.cos(yaw), math.sin(yaw)
            pos = crowd.pos[:n]
            radius = crowd.radius[:n]
            rr = float(crowd.robot_radius or 0.3)
            dx, dy = pos[:, 0] - robot[0], pos[:, 1] - robot[1]
            ahead = dx * hx + dy * hy
            side = np.abs(-dx * hy + dy * hx)
            reach = rr + radius + STOP_GAP
            way = (np.asarray(crowd.active[:n], dtype=bool) & (ahead > 0.0) & (ahead <= reach)
                   & (side <= rr + radius + SIDE_MARGIN))
            blockers = np.flatnonzero(way).tolist() if self._moving_on() else []
        if blockers:
            if self.blocked_since is None:
                self.blocked_since = now
                ctx.events.append((now, ROBOT_ID, "robot_stopped", ",".join(str(ctx.ids[r]) for r in blockers)))
            limit = 0.0 if now - self.blocked_since < HOLD_SECONDS else min(CREEP_SPEED, self.max_vel)
        else:
            if self.blocked_since is not None:
                ctx.events.append((now, ROBOT_ID, "robot_resumed", ""))
            self.blocked_since = None
            limit = self.max_vel
        if crowd.robot_speed_limit != limit:
            crowd.set_robot_speed_limit(limit)

    def _moving_on(self) -> bool:
        """Whether the robot still has somewhere to drive (a robot standing at its goal blocks nobody)."""
        if self.task == "wait" or self._held_until is not None:
            return False
        return not self.crowd.robot_path_done


def split_at_stops(path: np.ndarray, stops: tuple[tuple[float, float, float], ...]) -> tuple[list[np.ndarray], list[float]]:
    """The path cut at the vertex nearest each stop (in path order), and each stop's seconds: legs[i] ends
    where the robot stands holds[i] seconds; the last leg ends at the goal."""
    legs: list[np.ndarray] = []
    holds: list[float] = []
    first = 0
    for x, y, seconds in stops:
        if path.shape[0] - first < 2:
            break
        rest = path[first:]
        j = first + int(np.argmin(np.hypot(rest[:, 0] - x, rest[:, 1] - y)))
        if first == 0 and j == 0 and not legs:
            legs.append(path[:1])  # a hold at the start: it waits there before it sets off
            holds.append(float(seconds))
            continue
        if j <= first or j >= path.shape[0] - 1:
            continue
        legs.append(path[first:j + 1])
        holds.append(float(seconds))
        first = j
    legs.append(path[first:])
    return legs, holds
