"""Velocity fields for the emergency preset: one dense unit-vector field per group, leading to an exit.

Construction follows Text-Crowd's label fields (peers.md section 6): at every free cell a vector that
converges onto the group's planned path and follows it toward the exit (pursuit of the path point a
little ahead of the nearest one), blended with a geodesic fallback. The fallback is the any-angle
geodesic direction to the exit: a Dijkstra from the exit cell over all free cells whose parent
pointers take Theta*'s line-of-sight shortcuts, so every free cell connected to the exit points
straight at a visible cell that is closer to the exit.

Walls: the path-pursuit weight fades to zero next to obstacles (the geodesic direction is used
there), and no stored vector, nor any sampled one, has a component pointing into a blocked
neighbouring cell. Following the field with steps shorter than half a cell therefore never enters
an occupied cell (the property tests integrate it from sampled cells of every shipped world).
"""

from __future__ import annotations

import math
import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numba
import numpy as np
from scipy.spatial import cKDTree

from grove_tui.errors import FieldFileError
from grove_tui.files import npz_bytes, write_bytes_atomic
from grove_tui.limits import NPZ_READ_ERRORS, InputLimitError, check_npz
from grove_tui.navigation.grid import MAX_RESOLUTION, MIN_RESOLUTION, OccupancyGrid
from grove_tui.limits import MAX_PADDED_COORDINATE as MAX_COORDINATE
from grove_tui.navigation.theta_star import PlanningError, ThetaStarPlanner, line_of_sight

_DR = np.array([0, 0, 1, -1, 1, 1, -1, -1], dtype=np.int64)
_DC = np.array([1, -1, 0, 0, 1, -1, 1, -1], dtype=np.int64)

# A field stores 8 bytes per grid cell; the largest world grid at 0.1 m (25 million cells) needs 200 MB.
MAX_FIELD_UNPACKED_BYTES = 256 * 1024 * 1024


CAPTURE_RADIUS = 3.0  # metres: beyond this distance from the path only the geodesic direction is used
LOOKAHEAD = 1.0  # metres along the path ahead of the nearest path point
WALL_FADE = (1.5, 3.5)  # cells of clearance over which the path pursuit fades in
ESCAPE_RADIUS = 1.0  # metres searched for a usable cell when a sample falls inside an obstacle


@dataclass
class VelocityField:
    """A unit-vector field over the grid's cells (zero where the exit cannot be reached)."""

    origin: tuple[float, float]  # lower-left corner of cell (0, 0), as OccupancyGrid.origin
    resolution: float
    vectors: np.ndarray  # (H, W, 2) float32, row = y, col = x
    exit: tuple[float, float]
    path: np.ndarray = field(default_factory=lambda: np.empty((0, 2)))  # the planned group path it follows

    def sample(self, x: float, y: float) -> tuple[float, float]:
        return sample_field(self.vectors, self.origin[0], self.origin[1], self.resolution, float(x), float(y))

    @property
    def reachable(self) -> np.ndarray:
        return np.any(self.vectors != 0.0, axis=2)

    def save(self, path: str | os.PathLike[str]) -> Path:
        arrays: dict[str, np.ndarray | np.generic] = {
            "origin": np.asarray(self.origin, dtype=np.float64),
            "resolution": np.float64(self.resolution),
            "vectors": self.vectors.astype(np.float32),
            "exit": np.asarray(self.exit, dtype=np.float64),
            "path": np.asarray(self.path, dtype=np.float64).reshape(-1, 2),
        }
        return write_bytes_atomic(path, npz_bytes(arrays))

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> VelocityField:
        """Read a field saved by `save`. The unpacked size is checked from the zip headers first (a
        3 MB zip bomb would otherwise unpack to gigabytes), then every value is checked."""
        try:
            check_npz(path, MAX_FIELD_UNPACKED_BYTES, MAX_FIELD_UNPACKED_BYTES, "velocity field")
        except InputLimitError as error:
            raise FieldFileError(str(error)) from None
        try:
            with np.load(Path(path), allow_pickle=False) as data:
                vectors = np.ascontiguousarray(data["vectors"], dtype=np.float32)
                if vectors.ndim != 3 or vectors.shape[2] != 2 or vectors.shape[0] == 0 or vectors.shape[1] == 0:
                    raise ValueError(f"vectors have shape {vectors.shape}, expected (H, W, 2)")
                if not np.isfinite(vectors).all():
                    raise ValueError("vectors hold NaN or infinite values")
                origin = np.asarray(data["origin"], dtype=np.float64).reshape(-1)
                exit_point = np.asarray(data["exit"], dtype=np.float64).reshape(-1)
                resolution = float(data["resolution"])
                path_points = np.asarray(data["path"], dtype=np.float64).reshape(-1, 2)
                for name, values in (("origin", origin), ("exit", exit_point)):
                    if values.shape != (2,) or not np.isfinite(values).all() or np.abs(values).max() > MAX_COORDINATE:
                        raise ValueError(f"{name} must be two finite numbers within +-{MAX_COORDINATE:g} m")
                if not np.isfinite(path_points).all():
                    raise ValueError("path holds NaN or infinite values")
                if not (MIN_RESOLUTION <= resolution <= MAX_RESOLUTION):
                    raise ValueError(f"resolution must be {MIN_RESOLUTION}..{MAX_RESOLUTION} m, got {resolution!r}")
                return cls(origin=(float(origin[0]), float(origin[1])), resolution=resolution, vectors=vectors,
                           exit=(float(exit_point[0]), float(exit_point[1])), path=path_points)
        except NPZ_READ_ERRORS as error:
            raise FieldFileError(f"cannot read velocity field {path}: {error}") from None


# ---- kernels -----------------------------------------------------------------------------------


@numba.njit(cache=True, nogil=True, inline="always")
def _usable(vectors: np.ndarray, r: int, c: int) -> bool:
    height, width = vectors.shape[0], vectors.shape[1]
    if r < 0 or r >= height or c < 0 or c >= width:
        return False
    return vectors[r, c, 0] != 0.0 or vectors[r, c, 1] != 0.0


@numba.njit(cache=True, nogil=True)
def _keep_off_walls(usable_e: bool, usable_w: bool, usable_n: bool, usable_s: bool, usable_ne: bool, usable_nw: bool,
                    usable_se: bool, usable_sw: bool, vx: float, vy: float) -> tuple[float, float]:
    """Drop velocity components that point into blocked neighbouring cells."""
    if not usable_e and vx > 0.0:
        vx = 0.0
    if not usable_w and vx < 0.0:
        vx = 0.0
    if not usable_n and vy > 0.0:
        vy = 0.0
    if not usable_s and vy < 0.0:
        vy = 0.0
    # A blocked diagonal cell can only be entered by moving towards it on both axes at once.
    if (not usable_ne and vx > 0.0 and vy > 0.0) or (not usable_sw and vx < 0.0 and vy < 0.0) \
            or (not usable_nw and vx < 0.0 and vy > 0.0) or (not usable_se and vx > 0.0 and vy < 0.0):
        if abs(vx) < abs(vy):
            vx = 0.0
        else:
            vy = 0.0
    return vx, vy


@numba.njit(cache=True, nogil=True, inline="always")
def _clamp_at(vectors: np.ndarray, r: int, c: int, vx: float, vy: float) -> tuple[float, float]:
    return _keep_off_walls(_usable(vectors, r, c + 1), _usable(vectors, r, c - 1), _usable(vectors, r + 1, c),
                           _usable(vectors, r - 1, c), _usable(vectors, r + 1, c + 1), _usable(vectors, r + 1, c - 1),
                           _usable(vectors, r - 1, c + 1), _usable(vectors, r - 1, c - 1), vx, vy)


@numba.njit(cache=True, nogil=True)
def sample_field(vectors: np.ndarray, origin_x: float, origin_y: float, resolution: float, x: float, y: float) -> tuple[float, float]:
    """Direction of the field at world point (x, y): a unit vector, or (0, 0) far from any usable cell.

    Bilinear over the usable cells among the four nearest cell centres, then stripped of components
    pointing into blocked neighbours of the cell containing the point (falling back to that cell's
    own vector when nothing is left). Inside an obstacle (e.g. an agent pushed into the inflated
    margin) it points back to the nearest usable cell within ESCAPE_RADIUS.
    """
    height, width = vectors.shape[0], vectors.shape[1]
    gx = (x - origin_x) / resolution
    gy = (y - origin_y) / resolution
    row = int(math.floor(gy))
    col = int(math.floor(gx))
    fx = gx - 0.5
    fy = gy - 0.5
    c0 = int(math.floor(fx))
    r0 = int(math.floor(fy))
    tx = fx - c0
    ty = fy - r0
    vx = 0.0
    vy = 0.0
    weight = 0.0
    for dr in range(2):
        for dc in range(2):
            r = r0 + dr
            c = c0 + dc
            if not _usable(vectors, r, c):
                continue
            w = (tx if dc == 1 else 1.0 - tx) * (ty if dr == 1 else 1.0 - ty)
            vx += w * vectors[r, c, 0]
            vy += w * vectors[r, c, 1]
            weight += w
    if _usable(vectors, row, col):
        if weight > 0.0:
            vx /= weight
            vy /= weight
        vx, vy = _clamp_at(vectors, row, col, vx, vy)
        norm = math.hypot(vx, vy)
        if norm < 1e-6:
            return float(vectors[row, col, 0]), float(vectors[row, col, 1])
        return vx / norm, vy / norm
    # Inside an obstacle or an unreachable pocket: head for the nearest usable cell.
    reach = max(1, int(math.ceil(ESCAPE_RADIUS / resolution)))
    best_r = -1
    best_c = -1
    best_d = np.inf
    for radius in range(1, reach + 1):
        for r in range(row - radius, row + radius + 1):
            for c in range(col - radius, col + radius + 1):
                if max(abs(r - row), abs(c - col)) != radius or not _usable(vectors, r, c):
                    continue
                d = math.hypot(c + 0.5 - gx, r + 0.5 - gy)
                if d < best_d:
                    best_d = d
                    best_r = r
                    best_c = c
        if best_r >= 0 and best_d <= radius:
            break
    if best_r < 0:
        return 0.0, 0.0
    ux = (best_c + 0.5 - gx) / best_d
    uy = (best_r + 0.5 - gy) / best_d
    sx = ux + vectors[best_r, best_c, 0]
    sy = uy + vectors[best_r, best_c, 1]
    norm = math.hypot(sx, sy)
    if norm < 1e-6:
        return ux, uy
    return sx / norm, sy / norm


@numba.njit(cache=True, nogil=True)
def _blend_with_path(occupied: np.ndarray, clearance: np.ndarray, sight_rows: np.ndarray, sight_cols: np.ndarray,
                     parent: np.ndarray, exit_cx: float, exit_cy: float, samples: np.ndarray, nearest: np.ndarray,
                     nearest_distance: np.ndarray, capture_cells: float, lookahead_samples: int, fade_lo: float,
                     fade_hi: float, vectors: np.ndarray) -> None:
    """Fill `vectors` for every reachable cell: path pursuit blended with the geodesic direction."""
    height, width = occupied.shape
    last = samples.shape[0] - 1
    for r in range(height):
        for c in range(width):
            p = parent[r, c]
            if p < 0:
                continue
            pr = p // width
            pc = p % width
            if pr == r and pc == c:
                gx = exit_cx - c
                gy = exit_cy - r
            else:
                gx = float(pc - c)
                gy = float(pr - r)
            g_norm = math.hypot(gx, gy)
            if g_norm > 0.0:
                gx /= g_norm
                gy /= g_norm
            else:
                gx = 1e-3  # exit at the cell centre: any non-zero mark; the second pass picks a direction
            vx = gx
            vy = gy
            index = nearest[r, c]
            d = nearest_distance[r, c]
            if index >= 0 and d < capture_cells:
                wall = (clearance[r, c] - fade_lo) / (fade_hi - fade_lo)
                wall = min(max(wall, 0.0), 1.0)
                weight = (1.0 - d / capture_cells) * wall
                if weight > 0.0:
                    ahead = min(index + lookahead_samples, last)
                    ax = samples[ahead, 0]
                    ay = samples[ahead, 1]
                    ar = int(math.floor(ay + 0.5))
                    ac = int(math.floor(ax + 0.5))
                    px = ax - c
                    py = ay - r
                    p_norm = math.hypot(px, py)
                    if p_norm > 1e-9 and 0 <= ar < height and 0 <= ac < width and not occupied[ar, ac] \
                            and line_of_sight(sight_rows, sight_cols, r, c, ar, ac):
                        vx = weight * px / p_norm + (1.0 - weight) * gx
                        vy = weight * py / p_norm + (1.0 - weight) * gy
            vectors[r, c, 0] = vx
            vectors[r, c, 1] = vy
    # Second pass (vectors now mark which cells are usable): keep every vector off the walls.
    for r in range(height):
        for c in range(width):
            vx = vectors[r, c, 0]
            vy = vectors[r, c, 1]
            if vx == 0.0 and vy == 0.0:
                continue
            cx, cy = _clamp_at(vectors, r, c, vx, vy)
            norm = math.hypot(cx, cy)
            if norm < 1e-6:
                # The pursuit pointed at a wall: the geodesic direction never does (it follows a
                # line of sight), so fall back to it.
                p = parent[r, c]
                pr = p // width
                pc = p % width
                if pr == r and pc == c:
                    cx, cy = exit_cx - c, exit_cy - r
                else:
                    cx, cy = float(pc - c), float(pr - r)
                cx, cy = _clamp_at(vectors, r, c, cx, cy)
                norm = math.hypot(cx, cy)
            if norm < 1e-6:
                # exit cell hemmed in: any open direction keeps agents moving off it
                for k in range(8):
                    if _usable(vectors, r + _DR[k], c + _DC[k]):
                        cx, cy = _clamp_at(vectors, r, c, float(_DC[k]), float(_DR[k]))
                        norm = math.hypot(cx, cy)
                        if norm >= 1e-6:
                            break
            if norm < 1e-6:
                cx, cy, norm = 1.0, 0.0, 1.0  # an isolated usable cell: nowhere to go, direction irrelevant
            vectors[r, c, 0] = cx / norm
            vectors[r, c, 1] = cy / norm


# ---- construction ------------------------------------------------------------------------------


def _resample(points_cells: np.ndarray, spacing: float) -> np.ndarray:
    samples = [points_cells[0]]
    for a, b in zip(points_cells[:-1], points_cells[1:]):
        length = float(np.hypot(*(b - a)))
        steps = max(1, int(math.ceil(length / spacing)))
        t = np.arange(1, steps + 1, dtype=np.float64)[:, None] / steps
        samples.extend(a + t * (b - a))
    return np.asarray(samples, dtype=np.float64)


def build_velocity_field(grid: OccupancyGrid, path: np.ndarray, exit_point: Sequence[float], exit_label: str = "exit",
                         planner: ThetaStarPlanner | None = None) -> VelocityField:
    """Field over `grid` following `path` (a planned (K, 2) world path ending at the exit) to `exit_point`.

    Every free cell connected to the exit gets a unit vector; the rest stay zero. An exit point
    inside an obstacle is taken to the nearest free cell within one cell (PlanningError otherwise).
    """
    planner = planner or ThetaStarPlanner(grid, landmarks=0)  # only its grid maps are used here
    occupied = planner.occupied
    height, width = occupied.shape
    ex, ey = float(exit_point[0]), float(exit_point[1])
    er, ec = planner.snap(ex, ey, exit_label, "exit")
    # the exit's shortest-path tree, shared with the exit choice and every other field to this exit
    _distance, parent = planner.geodesic(er, ec)
    parent = parent.reshape(height, width)
    res = planner.resolution
    exit_cx = (ex - planner.centre_x) / res
    exit_cy = (ey - planner.centre_y) / res
    if planner.cell_of(ex, ey) != (er, ec):
        exit_cx, exit_cy = float(ec), float(er)  # the exit lies in an obstacle: aim at its free cell
    path = np.asarray(path, dtype=np.float64).reshape(-1, 2)
    nearest = np.full((height, width), -1, dtype=np.int64)
    nearest_distance = np.full((height, width), np.inf)
    spacing = 0.5
    samples = np.empty((0, 2))
    if len(path) >= 2:
        path_cells = np.column_stack(((path[:, 0] - planner.centre_x) / res, (path[:, 1] - planner.centre_y) / res))
        samples = _resample(path_cells, spacing)
        # only cells within the capture radius of the path pursue it: look for nearest samples there
        capture = CAPTURE_RADIUS / res
        c0 = max(int(math.floor(samples[:, 0].min() - capture)), 0)
        c1 = min(int(math.ceil(samples[:, 0].max() + capture)) + 1, width)
        r0 = max(int(math.floor(samples[:, 1].min() - capture)), 0)
        r1 = min(int(math.ceil(samples[:, 1].max() + capture)) + 1, height)
        rows, cols = np.nonzero(parent[r0:r1, c0:c1] >= 0)
        rows += r0
        cols += c0
        if len(rows):
            distances, indices = cKDTree(samples).query(np.column_stack((cols, rows)).astype(np.float64),
                                                        distance_upper_bound=capture)
            near = np.isfinite(distances)
            nearest[rows[near], cols[near]] = indices[near]
            nearest_distance[rows[near], cols[near]] = distances[near]
    else:
        samples = np.array([[exit_cx, exit_cy]], dtype=np.float64)
    vectors = np.zeros((height, width, 2), dtype=np.float32)
    _blend_with_path(occupied, planner.clearance, planner.sight_rows, planner.sight_cols, parent, exit_cx, exit_cy, samples, nearest, nearest_distance,
                     CAPTURE_RADIUS / res, max(1, int(round(LOOKAHEAD / res / spacing))),
                     WALL_FADE[0], WALL_FADE[1], vectors)
    ox, oy = getattr(grid, "origin", (planner.centre_x - res / 2, planner.centre_y - res / 2))
    return VelocityField(origin=(float(ox), float(oy)), resolution=res, vectors=vectors, exit=(ex, ey), path=path.copy())


def exit_walks(planner: ThetaStarPlanner, exits: dict[str, tuple[float, float]],
               starts: list[tuple[float, float]]) -> tuple[list[str], np.ndarray]:
    """Exit names (sorted) and the (exits, starts) matrix of walking distances in metres from each start.

    With the planner's door graph (a world planner, every exit one of its doors) a walk is the leg to
    a door of the start's zone plus the graph's door-to-exit distance: milliseconds for any crowd.
    Otherwise one any-angle Dijkstra per exit covers every start (shared with the fields to that
    exit). A start that reaches no exit raises PlanningError; an unreachable pair is inf.
    """
    names = sorted(exits)
    height, width = planner.occupied.shape
    walks = np.full((len(names), len(starts)), np.inf)
    start_cells = []
    for x, y in starts:
        start_cells.append(planner.snap(float(x), float(y), f"({x:.2f}, {y:.2f})", "start"))
    graph = planner.door_graph
    if graph is not None and all(name in graph.door_names for name in names):
        walks = graph.walks(start_cells, [graph.door_names.index(name) for name in names])
    else:
        flat = np.asarray([r * width + c for r, c in start_cells], dtype=np.int64)
        for k, name in enumerate(names):
            er, ec = planner.snap(*exits[name], name, "exit")
            distance, _parent = planner.geodesic(er, ec)
            walks[k] = distance[flat] * planner.resolution  # cells to metres
    if len(starts) and not np.isfinite(walks.min(axis=0)).all():
        stuck = int(np.flatnonzero(~np.isfinite(walks.min(axis=0)))[0])
        raise PlanningError(f"start ({starts[stuck][0]:.2f}, {starts[stuck][1]:.2f}) reaches none of the exits "
                            f"{', '.join(names)}")
    return names, walks


def nearest_exits(planner: ThetaStarPlanner, exits: dict[str, tuple[float, float]],
                  starts: list[tuple[float, float]]) -> list[str]:
    """For each start, the exit with the shortest walk (any-angle geodesic over the planner's grid).

    An exit nobody can reach from a start is never chosen for it; a start that reaches no exit
    raises PlanningError.
    """
    names, walks = exit_walks(planner, exits, starts)
    return [names[k] for k in np.argmin(walks, axis=0).tolist()] if len(starts) else []


# Persons per second per metre of door width that a queue drains at: the middle of RiMEA 12's
# empirical 1.3-1.9 /s/m. Only the ratio between doors matters for the choice, and a door
# narrower than one body still passes people one at a time.
DOOR_SPECIFIC_FLOW = 1.6


def least_congested_exits(planner: ThetaStarPlanner, exits: dict[str, tuple[tuple[float, float], float]],
                          starts: list[tuple[float, float]], speeds: list[float]) -> list[str]:
    """For each start, the exit through which it expects to be out soonest (RiMEA 11's route choice).

    Each door is a queue that lets one person through every 1 / capacity seconds. People choose in
    the order they would reach their nearest door; one reaching door e at walk_e / speed is out at
    max(that, when the door is next free) + 1 / capacity, and takes the door where that is soonest.
    Walking to a far door pays off once the near door's queue would take longer to clear than the
    detour; with nobody queueing, this is the nearest-exit choice. `exits` maps a name to (door
    centre, door width in metres).
    """
    names, walks = exit_walks(planner, {n: p for n, (p, _w) in exits.items()}, starts)
    if not len(starts):
        return []
    passage = 1.0 / np.array([DOOR_SPECIFIC_FLOW * max(float(exits[n][1]), 0.5) for n in names])
    speed = np.maximum(np.asarray(speeds, dtype=np.float64), 0.1)
    arrival = walks / speed[None, :]
    free_at = np.zeros(len(names))
    choice = np.empty(len(starts), dtype=np.int64)
    # ties broken by start index: the same starts always give the same choice
    for person in np.lexsort((np.arange(len(starts)), arrival.min(axis=0))).tolist():
        out_at = np.maximum(arrival[:, person], free_at) + passage
        best = int(np.argmin(out_at))
        choice[person] = best
        free_at[best] = out_at[best]
    return [names[k] for k in choice.tolist()]
