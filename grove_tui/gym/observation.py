"""The observation's parts, computed from the simulation's arrays in numpy (no Python loop per person).

Everything is expressed in the observation frame: centred on the robot; its x axis is the robot's
heading for unicycle kinematics, and the world's x axis for holonomic kinematics (whose actions are
world-frame velocities, so the policy sees the axes it acts in).
"""

from __future__ import annotations

import numpy as np

from grove_tui.gym.config import BEHAVIORS
from grove_tui.navigation.grid import OccupancyGrid

# Columns of one row of observation["pedestrians"].
PEDESTRIAN_COLUMNS = ("present", "x", "y", "vx", "vy", "radius", "gap") + tuple(f"is_{b}" for b in BEHAVIORS)


def rotation(angle: float) -> np.ndarray:
    """2x2 matrix taking world vectors to a frame rotated by `angle` (world -> frame: R @ v)."""
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, s], [-s, c]])


def behavior_one_hot(behaviors: tuple[str, ...]) -> np.ndarray:
    """(n, len(BEHAVIORS)) one-hot rows; an unknown behavior is all zeros."""
    table = np.zeros((len(behaviors), len(BEHAVIORS)), dtype=np.float32)
    index = {name: k for k, name in enumerate(BEHAVIORS)}
    for row, name in enumerate(behaviors):
        if name in index:
            table[row, index[name]] = 1.0
    return table


def nearest_pedestrians(robot_xy: np.ndarray, robot_radius: float, frame: np.ndarray, pos: np.ndarray,
                        vel: np.ndarray, radius: np.ndarray, active: np.ndarray, one_hot: np.ndarray,
                        k: int, sensor_range: float) -> np.ndarray:
    """(k, len(PEDESTRIAN_COLUMNS)) float32: the k nearest active people within sensor range, nearest
    first, positions and velocities in the frame; rows without a person are all zero (present = 0)."""
    out = np.zeros((k, len(PEDESTRIAN_COLUMNS)), dtype=np.float32)
    if pos.shape[0] == 0:
        return out
    offset = pos - robot_xy
    centre = np.hypot(offset[:, 0], offset[:, 1])
    seen = np.flatnonzero(active & (centre <= sensor_range))
    if seen.size == 0:
        return out
    chosen = seen[np.argsort(centre[seen], kind="stable")[:k]]
    m = chosen.size
    out[:m, 0] = 1.0
    out[:m, 1:3] = offset[chosen] @ frame.T
    out[:m, 3:5] = vel[chosen] @ frame.T
    out[:m, 5] = radius[chosen]
    out[:m, 6] = centre[chosen] - radius[chosen] - robot_radius
    out[:m, 7:] = one_hot[chosen]
    return out


def occupancy_patch(grid: OccupancyGrid, robot_xy: np.ndarray, frame: np.ndarray, cells: int,
                    resolution: float) -> np.ndarray:
    """(cells, cells) uint8, 1 where the world is blocked (walls, furniture, outside every zone).

    Cell [i, j] is centred at frame coordinates x = (j - (cells - 1) / 2) * resolution,
    y = (i - (cells - 1) / 2) * resolution: rows go along the frame's y axis, columns along its x axis.
    """
    half = (cells - 1) / 2.0
    steps = (np.arange(cells) - half) * resolution
    fx, fy = np.meshgrid(steps, steps)  # fx varies along columns, fy along rows
    # frame -> world is the transpose of the rotation
    wx = robot_xy[0] + frame[0, 0] * fx + frame[1, 0] * fy
    wy = robot_xy[1] + frame[0, 1] * fx + frame[1, 1] * fy
    col = np.floor((wx - grid.origin[0]) / grid.resolution).astype(np.int64)
    row = np.floor((wy - grid.origin[1]) / grid.resolution).astype(np.int64)
    height, width = grid.occupied.shape
    inside = (row >= 0) & (row < height) & (col >= 0) & (col < width)
    patch = np.ones((cells, cells), dtype=np.uint8)
    patch[inside] = grid.occupied[row[inside], col[inside]]
    return patch


def wall_boxes(walls: np.ndarray) -> np.ndarray:
    """(M, 4) xmin, ymin, xmax, ymax of each wall segment: computed once per scenario, so the per-step
    wall queries below look only at the few segments whose box is near."""
    return np.column_stack([np.minimum(walls[:, 0], walls[:, 2]), np.minimum(walls[:, 1], walls[:, 3]),
                            np.maximum(walls[:, 0], walls[:, 2]), np.maximum(walls[:, 1], walls[:, 3])])


def _near(boxes: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    return (boxes[:, 2] >= lo[0]) & (boxes[:, 0] <= hi[0]) & (boxes[:, 3] >= lo[1]) & (boxes[:, 1] <= hi[1])


def wall_distance(point: np.ndarray, walls: np.ndarray, within: float = np.inf,
                  boxes: np.ndarray | None = None) -> float:
    """Distance from a point to the nearest wall segment; with `within`, any distance above it may be
    reported as inf (only segments whose box lies within that range are measured)."""
    if walls.shape[0] and np.isfinite(within):
        boxes = wall_boxes(walls) if boxes is None else boxes
        walls = walls[_near(boxes, point - within, point + within)]
    if walls.shape[0] == 0:
        return float("inf")
    a = walls[:, 0:2]
    ab = walls[:, 2:4] - a
    length2 = np.einsum("ij,ij->i", ab, ab)
    t = np.clip(np.einsum("ij,ij->i", point - a, ab) / np.where(length2 > 0, length2, 1.0), 0.0, 1.0)
    nearest = a + ab * t[:, None]
    return float(np.hypot(nearest[:, 0] - point[0], nearest[:, 1] - point[1]).min())


def _point_segment_distances(points: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """(M,) distance from points[k] to segment a[k]-b[k]."""
    ab = b - a
    length2 = np.einsum("ij,ij->i", ab, ab)
    t = np.clip(np.einsum("ij,ij->i", points - a, ab) / np.where(length2 > 0, length2, 1.0), 0.0, 1.0)
    nearest = a + ab * t[:, None]
    return np.hypot(nearest[:, 0] - points[:, 0], nearest[:, 1] - points[:, 1])


def segment_clear(p: np.ndarray, q: np.ndarray, walls: np.ndarray, clearance: float,
                  boxes: np.ndarray | None = None) -> bool:
    """Whether a body of radius `clearance` can move straight from p to q without touching a wall
    (`boxes`: wall_boxes(walls), when the caller keeps them)."""
    if walls.shape[0] == 0:
        return True
    boxes = wall_boxes(walls) if boxes is None else boxes
    near = walls[_near(boxes, np.minimum(p, q) - clearance, np.maximum(p, q) + clearance)]
    if near.shape[0] == 0:
        return True
    a, b = near[:, 0:2], near[:, 2:4]
    m = near.shape[0]
    pp, qq = np.broadcast_to(p, (m, 2)), np.broadcast_to(q, (m, 2))

    def orient(u: np.ndarray, v: np.ndarray, w: np.ndarray) -> np.ndarray:
        return (v[:, 0] - u[:, 0]) * (w[:, 1] - u[:, 1]) - (v[:, 1] - u[:, 1]) * (w[:, 0] - u[:, 0])

    if np.any((orient(a, b, pp) * orient(a, b, qq) < 0) & (orient(pp, qq, a) * orient(pp, qq, b) < 0)):
        return False  # the motion crosses a wall
    distance = np.minimum.reduce([_point_segment_distances(pp, a, b), _point_segment_distances(qq, a, b),
                                  _point_segment_distances(a, pp, qq), _point_segment_distances(b, pp, qq)])
    return bool(distance.min() >= clearance)
