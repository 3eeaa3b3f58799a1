"""HuNavSim evaluator's force-based robot metrics (hunav_evaluator/hunav_metrics.py 2.0 with its sfm.py).

Per recorded frame the evaluator measures, with lightsfm's default parameters:

- social force on the robot: sum over people of |F_social(person -> robot)|;
- social force on the agents: sum over people of |F_social(robot -> person)|;
- obstacle force on the robot: |F_obstacle(robot)|;
- obstacle force on the agents: mean over the people present of |F_obstacle(person)|;
- social work: |sum over people of F_social(person -> robot)| + |F_obstacle(robot)|
  + sum over people of |F_social(robot -> person)| (social_force_window_planner's cost).

Each metric is the sum of its per-frame value over the frames the robot was recorded in, as the
evaluator sums over the messages it received: the totals are in m/s^2 x frames, so they grow
with the recording rate (ours is the simulation step, 20 Hz by default) and with the run's length.

The forces are the simulator's own kernels (`sfm._social_force`, `sfm._point_obstacle_force`);
only the parameters differ: the evaluator builds its SFM with lightsfm's defaults (social
weight 2.1, not HuNavSim's 5) and without our head-on tie-breaking shift (epsilon 0).
Every person counts, at any distance: the evaluator applies no social cutoff.

Obstacles: the evaluator reads `closest_obs`, the points the Gazebo wrapper finds around each
agent (Gazebo Classic: the nearest point of the nearest model's bounding box within 10 m) and
averages the force over them. Our bundles record no such points, so each body gets the one
nearest point of the world's wall segments (`World.walls()`: walls minus door openings plus the
footprint edges of furniture and obstacles, the geometry the simulated crowd itself avoids)
within the same 10 m; with no wall that close the body feels no obstacle force, as in the
evaluator. The exact segments are used rather than the inflated occupancy grid, whose cells sit
up to an inflation radius closer than the real surfaces.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba as nb
import numpy as np

# numba's on-disk cache of the kernels below tracks this file only: after editing these sfm
# functions, clear __pycache__ (or touch this file) so the metrics pick the change up.
from grove_tui.crowd.sfm import (
    P_SIGMA_OBS,
    SFMParams,
    _closest_on_segment,
    _point_obstacle_force,
    _social_force,
    _wall_cell,
    bucket_walls,
)

# lightsfm's defaults as hunav_evaluator/sfm.py sets them: social weight 2.1, obstacle weight 10,
# obstacle sigma 0.2, lambda 2, gamma 0.35, n 2, n' 3. epsilon 0 keeps the plain Moussaid angle.
# lightsfm's forces, not GROVE's default pedestrian model: these metrics reproduce HuNavSim's evaluator,
# which recomputes forces with lightsfm whatever moved the people.
EVALUATOR_SFM = SFMParams.lightsfm(social_weight=2.1, obstacle_weight=10.0, obstacle_sigma=0.2,
                                   lambda_=2.0, gamma=0.35, n=2.0, n_prime=3.0, epsilon=0.0)
# How far the Gazebo Classic wrapper looks for an agent's closest obstacle.
OBSTACLE_SEARCH_RANGE = 10.0
ROBOT_ID = 0

# Columns of the per-frame table `force_series` returns.
SOCIAL_ON_ROBOT = 0
SOCIAL_ON_AGENTS = 1
SOCIAL_WORK = 2
OBSTACLE_ON_ROBOT = 3
OBSTACLE_ON_AGENTS = 4
_COLUMNS = 5


@dataclass(frozen=True)
class ForceSeries:
    """Per-frame force moduli (m/s^2) over the frames the robot was recorded in.

    `obstacle_on_agents` is NaN in frames with nobody present (the evaluator's mean over no
    agents is undefined); the obstacle columns and `social_work` are None without wall geometry.
    """

    social_on_robot: np.ndarray
    social_on_agents: np.ndarray
    social_work: np.ndarray | None
    obstacle_on_robot: np.ndarray | None
    obstacle_on_agents: np.ndarray | None


@nb.njit(cache=True)
def _nearest_wall_point(x: float, y: float, search_range: float, walls: np.ndarray, wall_meta: np.ndarray,
                        wall_start: np.ndarray, wall_items: np.ndarray) -> tuple[bool, float, float]:
    """Closest point of any wall within `search_range` of (x, y): (found, px, py)."""
    cell = _wall_cell(x, y, wall_meta)
    if cell < 0:
        return False, 0.0, 0.0
    best = search_range
    found = False
    best_x = 0.0
    best_y = 0.0
    for k in range(wall_start[cell], wall_start[cell + 1]):
        w = wall_items[k]
        cx, cy, _t = _closest_on_segment(x, y, walls[w, 0], walls[w, 1], walls[w, 2], walls[w, 3])
        d = math.sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy))
        if d <= best:
            best = d
            found = True
            best_x = cx
            best_y = cy
    return found, best_x, best_y


@nb.njit(cache=True)
def _obstacle_force_modulus(x: float, y: float, radius: float, body_id: int, params: np.ndarray,
                            obstacle_weight: float, search_range: float, walls: np.ndarray, wall_meta: np.ndarray,
                            wall_start: np.ndarray, wall_items: np.ndarray) -> float:
    found, ox, oy = _nearest_wall_point(x, y, search_range, walls, wall_meta, wall_start, wall_items)
    if not found:
        return 0.0
    fx, fy = _point_obstacle_force(x, y, ox, oy, radius, obstacle_weight, params[P_SIGMA_OBS], body_id)
    return math.sqrt(fx * fx + fy * fy)


@nb.njit(cache=True)
def _force_table(robot: np.ndarray, robot_vel: np.ndarray, robot_radius: float, people: np.ndarray,
                 people_vel: np.ndarray, people_radius: np.ndarray, people_ids: np.ndarray, params: np.ndarray,
                 social_weight: float, obstacle_weight: float, with_obstacles: bool, search_range: float,
                 walls: np.ndarray, wall_meta: np.ndarray, wall_start: np.ndarray,
                 wall_items: np.ndarray) -> np.ndarray:
    frames = robot.shape[0]
    out = np.zeros((frames, _COLUMNS))
    for f in range(frames):
        rx = robot[f, 0]
        ry = robot[f, 1]
        rvx = robot_vel[f, 0]
        rvy = robot_vel[f, 1]
        # The vector sum of the people's forces on the robot enters social work; the rest are sums of moduli.
        on_robot_x = 0.0
        on_robot_y = 0.0
        on_robot = 0.0
        on_agents = 0.0
        obstacle_agents = 0.0
        present = 0
        for k in range(people.shape[1]):
            px = people[f, k, 0]
            py = people[f, k, 1]
            if not (math.isfinite(px) and math.isfinite(py)):
                continue
            present += 1
            pvx = people_vel[f, k, 0]
            pvy = people_vel[f, k, 1]
            agent_id = people_ids[k]
            fx, fy = _social_force(rx, ry, rvx, rvy, px, py, pvx, pvy, ROBOT_ID, agent_id, params)
            fx *= social_weight
            fy *= social_weight
            on_robot_x += fx
            on_robot_y += fy
            on_robot += math.sqrt(fx * fx + fy * fy)
            gx, gy = _social_force(px, py, pvx, pvy, rx, ry, rvx, rvy, agent_id, ROBOT_ID, params)
            on_agents += social_weight * math.sqrt(gx * gx + gy * gy)
            if with_obstacles:
                obstacle_agents += _obstacle_force_modulus(px, py, people_radius[k], agent_id, params,
                                                           obstacle_weight, search_range,
                                                           walls, wall_meta, wall_start, wall_items)
        out[f, SOCIAL_ON_ROBOT] = on_robot
        out[f, SOCIAL_ON_AGENTS] = on_agents
        if with_obstacles:
            obstacle_robot = _obstacle_force_modulus(rx, ry, robot_radius, ROBOT_ID, params, obstacle_weight,
                                                     search_range, walls, wall_meta, wall_start, wall_items)
            out[f, OBSTACLE_ON_ROBOT] = obstacle_robot
            out[f, SOCIAL_WORK] = math.sqrt(on_robot_x * on_robot_x + on_robot_y * on_robot_y) \
                + obstacle_robot + on_agents
            out[f, OBSTACLE_ON_AGENTS] = obstacle_agents / present if present else math.nan
    return out


def force_series(robot: np.ndarray, robot_vel: np.ndarray, people: np.ndarray, people_vel: np.ndarray,
                 people_ids: np.ndarray, *, robot_radius: float, person_radius: float | np.ndarray,
                 walls: np.ndarray | None, params: SFMParams = EVALUATOR_SFM,
                 search_range: float = OBSTACLE_SEARCH_RANGE) -> ForceSeries:
    """Per-frame forces for robot poses (F, >=2), robot velocities (F, 2), people (F, N, 2) NaN where absent.

    Without wall geometry (`walls` None) the obstacle forces, and so social work, are not computed;
    an empty wall array means a world without obstacles, where they are zero.
    """
    robot_xy = np.ascontiguousarray(robot[:, :2], dtype=np.float64)
    # A frame recorded without a velocity is treated as standing still rather than poisoning the sums.
    robot_v = np.nan_to_num(np.ascontiguousarray(robot_vel, dtype=np.float64))
    people = np.ascontiguousarray(people, dtype=np.float64)
    people_v = np.nan_to_num(np.ascontiguousarray(people_vel, dtype=np.float64))
    ids = np.ascontiguousarray(people_ids, dtype=np.int64)
    radii = np.ascontiguousarray(np.broadcast_to(np.asarray(person_radius, dtype=np.float64), ids.shape))
    with_obstacles = walls is not None
    wall_array = np.ascontiguousarray(np.zeros((0, 4)) if walls is None else walls, dtype=np.float64).reshape(-1, 4)
    # Cells as wide as the search range: a body's own cell lists every wall it could pick.
    meta, starts, items = bucket_walls(wall_array, search_range)
    table = _force_table(robot_xy, robot_v, float(robot_radius), people, people_v, radii, ids,
                         params.as_array(), float(params.social_weight), float(params.obstacle_weight),
                         with_obstacles, float(search_range), wall_array, meta, starts, items)
    return ForceSeries(
        social_on_robot=table[:, SOCIAL_ON_ROBOT],
        social_on_agents=table[:, SOCIAL_ON_AGENTS],
        social_work=table[:, SOCIAL_WORK] if with_obstacles else None,
        obstacle_on_robot=table[:, OBSTACLE_ON_ROBOT] if with_obstacles else None,
        obstacle_on_agents=table[:, OBSTACLE_ON_AGENTS] if with_obstacles else None,
    )


def force_metrics(series: ForceSeries) -> dict[str, float]:
    """The evaluator's cumulative force metrics from per-frame forces.

    With nobody present the social forces are 0, a sum over no one, as in the evaluator.
    `obstacle_force_on_agents` is left out when nobody was ever present (the evaluator divides by
    zero there); frames without people add nothing to it. The obstacle metrics and `social_work`
    are left out without wall geometry, as `wall_penetrations` is among the crowd metrics.
    """
    out = {
        "social_force_on_agents": float(series.social_on_agents.sum()),
        "social_force_on_robot": float(series.social_on_robot.sum()),
    }
    if series.obstacle_on_robot is not None and series.social_work is not None:
        out["social_work"] = float(series.social_work.sum())
        out["obstacle_force_on_robot"] = float(series.obstacle_on_robot.sum())
    if series.obstacle_on_agents is not None:
        present = np.isfinite(series.obstacle_on_agents)
        if present.any():
            out["obstacle_force_on_agents"] = float(series.obstacle_on_agents[present].sum())
    return out
