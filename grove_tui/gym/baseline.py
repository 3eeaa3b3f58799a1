"""The scripted baseline: follow the planned path, avoid people with a sampled velocity obstacle.

Each control period the policy
1. takes the next waypoint of the robot's planned path (observation["waypoint"]) and wants to drive
   straight at it at full speed;
2. samples candidate velocities (speeds x headings all around the wanted one, and standing still)
   and drops every candidate inside the velocity obstacle of a person it observes: the candidate,
   relative to the person's velocity, would bring the two bodies (plus SAFETY_MARGIN) into contact
   within HORIZON seconds;
   or whose straight motion would bring the robot's body within WALL_MARGIN of a wall within
   WALL_LOOKAHEAD (unless it moves away from the wall);
3. drives the admissible candidate closest to the wanted velocity; when none is admissible, the one
   that puts the contact off longest (backing away from someone walking at the robot).
It reads the observation (waypoint, people) and, from the environment, the robot's pose, size and the
world's walls. Holonomic candidates are velocities; unicycle candidates are (v, w) pairs, each judged
by the velocity the robot has once it has turned for one control period.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

HORIZON = 2.0  # seconds a chosen velocity must stay collision-free
SAFETY_MARGIN = 0.15  # metres added to the two radii
CLOSE_IN = 0.1  # metres: how much closer a candidate may bring the robot to someone already within reach
CONTACT_MARGIN = 0.05  # metres: never plan to come nearer than this to a body
ESCAPE_LOOKAHEAD = 0.5  # seconds: when cornered, the room to everyone is judged this far ahead
WALL_MARGIN = 0.05  # metres of air kept between the robot's body and a wall
WALL_LOOKAHEAD = (0.25, 0.5)  # seconds ahead at which a candidate's position is checked against walls
SPEED_FRACTIONS = (1.0, 0.75, 0.5, 0.25)
HEADING_OFFSETS = np.radians([0, 15, -15, 30, -30, 45, -45, 60, -60, 90, -90, 120, -120, 150, -150, 180])
TURN_STEPS = 7  # unicycle: turn rates sampled evenly in [-max, max]
FACING_WEIGHT = 0.2  # unicycle: cost (m/s) per radian left between the heading and the wanted direction


class PathFollowingVOPolicy:
    """Call `act(observation)` once per step of the environment it was made for (reset first)."""

    def __init__(self, env: Any) -> None:  # Any: a SocialNavEnv or a Gymnasium wrapper around one
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

        if env.kinematics == "holonomic":
            angles = wanted_angle + np.tile(HEADING_OFFSETS, len(SPEED_FRACTIONS))
            speeds = wanted_speed * np.repeat(np.asarray(SPEED_FRACTIONS), len(HEADING_OFFSETS))
            velocities = speeds[:, None] * np.column_stack([np.cos(angles), np.sin(angles)])
            velocities = np.vstack([velocities, np.zeros((1, 2))])  # standing still is a choice too
            commands = velocities
            cost = np.hypot(*(velocities - wanted).T)
        else:
            # (v, w) pairs; the robot moves along the heading it has turned to by the period's end
            v = max_speed * np.repeat(np.asarray((*SPEED_FRACTIONS, 0.0)), TURN_STEPS)
            rates = np.linspace(-env.max_angular_speed, env.max_angular_speed, TURN_STEPS)
            w = np.tile(rates, len(SPEED_FRACTIONS) + 1)
            turned = w * env.control_period
            velocities = v[:, None] * np.column_stack([np.cos(turned), np.sin(turned)])
            commands = np.column_stack([v, w])
            facing = np.abs((wanted_angle - turned + np.pi) % (2 * np.pi) - np.pi)
            cost = np.hypot(*(velocities - wanted).T) + FACING_WEIGHT * facing
        walls_ok = ~_near_walls(velocities @ frame, position, env.current.walls, env.robot_radius + WALL_MARGIN)
        ttc = time_to_collision(velocities, rel_pos, ped_vel, body)
        safe = walls_ok & (ttc > HORIZON)
        if safe.any():
            chosen = np.flatnonzero(safe)[np.argmin(cost[safe])]
        else:
            # Nothing is safe for the whole horizon: put off the contact longest; among equals (someone
            # already close), keep the most room to everyone a moment from now, then stay near the plan.
            pool = np.flatnonzero(walls_ok) if walls_ok.any() else np.arange(len(commands))
            room = clearance_after(velocities[pool], rel_pos, ped_vel, body, ESCAPE_LOOKAHEAD)
            chosen = pool[np.lexsort((cost[pool], -np.round(room, 2), -ttc[pool]))[0]]
        return commands[chosen].astype(np.float32)


def clearance_after(velocities: np.ndarray, rel_pos: np.ndarray, ped_vel: np.ndarray, body: np.ndarray,
                    seconds: float) -> np.ndarray:
    """(C,) smallest gap between the robot's body and anyone's after `seconds` at each velocity."""
    if rel_pos.shape[0] == 0:
        return np.full(velocities.shape[0], np.inf)
    later = rel_pos[None, :, :] - (velocities[:, None, :] - ped_vel[None, :, :]) * seconds
    return (np.hypot(later[..., 0], later[..., 1]) - body[None, :]).min(axis=1)


def time_to_collision(velocities: np.ndarray, rel_pos: np.ndarray, ped_vel: np.ndarray,
                      body: np.ndarray) -> np.ndarray:
    """(C,) seconds until the robot at each candidate velocity comes within body + SAFETY_MARGIN of a
    person, everyone keeping their velocity (inf: never). This is the velocity obstacle: a candidate
    is inside it when its time to collision is within the horizon.

    A person already within that reach (standing in a doorway, say) counts as a collision now (0)
    only for velocities that would bring the robot CLOSE_IN closer within the horizon, or near
    contact: the robot may still skirt them or back away.
    """
    out = np.full(velocities.shape[0], np.inf)
    if rel_pos.shape[0] == 0:
        return out
    v = velocities[:, None, :] - ped_vel[None, :, :]  # (C, P, 2) robot's velocity relative to each person
    p = rel_pos[None, :, :]
    reach = (body + SAFETY_MARGIN)[None, :]
    a = np.einsum("cpk,cpk->cp", v, v)
    b = np.einsum("cpk,cpk->cp", np.broadcast_to(p, v.shape), v)
    c = np.einsum("pk,pk->p", rel_pos, rel_pos)[None, :] - reach ** 2
    disc = b * b - a * c
    moving = a > 1e-12
    root = np.where(moving & (disc >= 0), (b - np.sqrt(np.maximum(disc, 0.0))) / np.where(moving, a, 1.0), np.inf)
    ttc = np.where(root >= 0, root, np.inf)
    inside = c < 0
    if inside.any():
        # closest approach within the horizon, for the people already within reach
        t = np.clip(b / np.where(moving, a, 1.0), 0.0, HORIZON)
        closest = np.hypot(*(p - v * t[:, :, None]).transpose(2, 0, 1))
        now = np.hypot(rel_pos[:, 0], rel_pos[:, 1])[None, :]
        pressing = (closest < now - CLOSE_IN) | (closest < body[None, :] + CONTACT_MARGIN)
        ttc = np.where(inside, np.where(pressing, 0.0, np.inf), ttc)
    return ttc.min(axis=1)


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
