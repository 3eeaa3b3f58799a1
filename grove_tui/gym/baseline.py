"""The scripted baseline: follow the planned path, avoid people with a sampled velocity obstacle.

Each control period the policy
1. takes the next waypoint of the robot's planned path (observation["waypoint"]) and wants to drive
   straight at it at full speed;
2. samples candidate velocities (speeds x headings around the wanted one) and drops every candidate
   inside the velocity obstacle of a person it observes: the candidate, relative to the person's
   velocity, would bring the two bodies (plus SAFETY_MARGIN) into contact within HORIZON seconds;
   or whose straight motion would bring the robot's body within WALL_MARGIN of a wall within
   WALL_LOOKAHEAD (unless it moves away from the wall);
3. drives the admissible candidate closest to the wanted velocity, or stops when none is.
It reads the observation (waypoint, people) and, from the environment, the robot's pose, size and the
world's walls; it works for both kinematics (unicycle: turn toward the chosen velocity, slow down while the turn is large).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

HORIZON = 2.0  # seconds a chosen velocity must stay collision-free
SAFETY_MARGIN = 0.15  # metres added to the two radii
CLOSE_IN = 0.1  # metres: how much closer a candidate may bring the robot to someone already within reach
CONTACT_MARGIN = 0.05  # metres: never plan to come nearer than this to a body
WALL_MARGIN = 0.05  # metres of air kept between the robot's body and a wall
WALL_LOOKAHEAD = (0.25, 0.5)  # seconds ahead at which a candidate's position is checked against walls
SPEED_FRACTIONS = (1.0, 0.75, 0.5, 0.25)
HEADING_OFFSETS = np.radians([0, 15, -15, 30, -30, 45, -45, 60, -60, 90, -90])
TURN_GAIN = 2.0  # rad/s of turn per radian of heading error (unicycle)


class PathFollowingVOPolicy:
    """Call `act(observation)` once per step of the environment it was made for (reset first)."""

    def __init__(self, env: Any) -> None:
        self.env = env.unwrapped if hasattr(env, "unwrapped") else env

    def act(self, observation: dict[str, np.ndarray]) -> np.ndarray:
        env = self.env
        position = np.asarray(env.sim.crowd.robot_pos, dtype=np.float64)
        frame = env.observation_frame()
        max_speed = float(env.robot_max_speed)
        target = observation["waypoint"][:2].astype(np.float64)  # in the observation frame
        distance = float(np.hypot(*target))
        wanted_speed = min(max_speed, distance / env.control_period)
        wanted_angle = math.atan2(target[1], target[0]) if distance > 1e-9 else 0.0
        wanted = wanted_speed * np.array([math.cos(wanted_angle), math.sin(wanted_angle)])

        people = observation["pedestrians"]
        present = people[:, 0] > 0.5
        rel_pos = people[present, 1:3].astype(np.float64)
        ped_vel = people[present, 3:5].astype(np.float64)
        body = people[present, 5].astype(np.float64) + env.robot_radius

        angles = wanted_angle + np.repeat(HEADING_OFFSETS[None, :], len(SPEED_FRACTIONS), axis=0).ravel()
        speeds = wanted_speed * np.repeat(np.asarray(SPEED_FRACTIONS), len(HEADING_OFFSETS))
        candidates = speeds[:, None] * np.column_stack([np.cos(angles), np.sin(angles)])  # frame velocities
        safe = ~_near_walls(candidates @ frame, position, env.current.walls, env.robot_radius + WALL_MARGIN)
        best: np.ndarray | None = None
        best_cost = math.inf
        for candidate in candidates[safe]:
            if rel_pos.shape[0] and _collides(candidate, rel_pos, ped_vel, body):
                continue
            cost = float(np.hypot(*(candidate - wanted)))
            if cost < best_cost:
                best, best_cost = candidate, cost
        chosen = best if best is not None else np.zeros(2)
        return self._command(chosen, max_speed)

    def _command(self, velocity: np.ndarray, max_speed: float) -> np.ndarray:
        env = self.env
        if env.kinematics == "holonomic":
            return velocity.astype(np.float32)  # the holonomic frame is the world's
        speed = float(np.hypot(*velocity))
        if speed < 1e-9:
            return np.zeros(2, dtype=np.float32)
        error = math.atan2(velocity[1], velocity[0])  # the frame's x axis is the heading
        turn = float(np.clip(TURN_GAIN * error, -env.max_angular_speed, env.max_angular_speed))
        forward = min(max_speed, speed) * max(0.0, math.cos(error))
        return np.array([forward, turn], dtype=np.float32)


def _collides(velocity: np.ndarray, rel_pos: np.ndarray, ped_vel: np.ndarray, body: np.ndarray) -> bool:
    """Whether the robot at `velocity` comes within body + SAFETY_MARGIN of any person within HORIZON
    seconds, everyone keeping their velocity (the velocity obstacle truncated at the horizon).

    A person already within that reach (standing in a doorway, say) blocks only velocities that would
    bring the robot CLOSE_IN closer or near contact: the robot may still skirt or back away.
    """
    v = velocity[None, :] - ped_vel  # robot's velocity relative to each person
    # closest approach of p(t) = rel_pos - v t over t in [0, HORIZON]
    vv = np.einsum("ij,ij->i", v, v)
    t = np.clip(np.einsum("ij,ij->i", rel_pos, v) / np.where(vv > 1e-12, vv, 1.0), 0.0, HORIZON)
    closest = rel_pos - v * t[:, None]
    approach = np.hypot(closest[:, 0], closest[:, 1])
    now = np.hypot(rel_pos[:, 0], rel_pos[:, 1])
    reach = body + SAFETY_MARGIN
    inside = now < reach
    blocked_inside = (approach < now - CLOSE_IN) | (approach < body + CONTACT_MARGIN)
    return bool(np.any(np.where(inside, blocked_inside, approach < reach)))


def _segment_distances(points: np.ndarray, walls: np.ndarray) -> np.ndarray:
    """(P,) distance from each point to its nearest wall segment."""
    a = walls[None, :, 0:2]
    ab = walls[None, :, 2:4] - a
    length2 = np.einsum("pij,pij->pi", ab, ab)
    ap = points[:, None, :] - a
    t = np.clip(np.einsum("pij,pij->pi", ap, ab) / np.where(length2 > 0, length2, 1.0), 0.0, 1.0)
    nearest = a + ab * t[:, :, None]
    return np.hypot(nearest[..., 0] - points[:, None, 0], nearest[..., 1] - points[:, None, 1]).min(axis=1)


def _near_walls(velocities: np.ndarray, position: np.ndarray, walls: np.ndarray, clearance: float) -> np.ndarray:
    """(C,) whether each world-frame velocity brings the robot within `clearance` of a wall within
    WALL_LOOKAHEAD while getting closer to it than it is now."""
    if walls.shape[0] == 0:
        return np.zeros(velocities.shape[0], dtype=bool)
    # only walls the robot could reach matter: a box around it cuts the segment count
    reach = float(np.abs(velocities).max(initial=0.0)) * max(WALL_LOOKAHEAD) + clearance + 1.0
    lo, hi = position - reach, position + reach
    x0, x1 = np.minimum(walls[:, 0], walls[:, 2]), np.maximum(walls[:, 0], walls[:, 2])
    y0, y1 = np.minimum(walls[:, 1], walls[:, 3]), np.maximum(walls[:, 1], walls[:, 3])
    nearby = walls[(x1 >= lo[0]) & (x0 <= hi[0]) & (y1 >= lo[1]) & (y0 <= hi[1])]
    if nearby.shape[0] == 0:
        return np.zeros(velocities.shape[0], dtype=bool)
    now = float(_segment_distances(position[None, :], nearby)[0])
    blocked = np.zeros(velocities.shape[0], dtype=bool)
    for seconds in WALL_LOOKAHEAD:
        distance = _segment_distances(position[None, :] + velocities * seconds, nearby)
        blocked |= (distance < clearance) & (distance < now)
    return blocked
