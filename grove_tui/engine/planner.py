"""Theta* (Daniel et al. 2010) on the inflated occupancy grid, compiled with numba.

Cells are addressed (row, col) with row = y and col = x, as in `grid.OccupancyGrid`. Inside the
kernels a cell is a square of side 1 centred on its integer (col, row) coordinates, and a segment
between two cell centres is "in line of sight" only if it touches no occupied square, not even at a
corner (a conservative supercover). The 8-connected expansion uses the same rule, so a diagonal step
is allowed only when both orthogonal neighbours are free and A*, Theta* and the line-of-sight test
agree on what "collision-free" means.

Three deviations from textbook Theta* make it fast and safe:
- line of sight jumps over open space using the Euclidean clearance of each cell (distance to the
  nearest occupied cell), so a long check costs a few steps instead of one per column;
- improved vertices are re-opened. With that, the returned path is never longer than the shortest
  8-connected grid path: Theta*'s shortcut only ever shortens the A* relaxation, so the argument
  for A* goes through for any heuristic that never exceeds the 8-connected distance to the goal
  (the property tests check it against a reference A*);
- that freedom buys a much stronger heuristic than the Euclidean distance: ALT landmark bounds
  (Goldberg & Harrelson 2005) from any-angle distance maps computed once per grid, which keep the
  search from flooding every room that is close to the goal as the crow flies.
"""

from __future__ import annotations

import math
import threading
from collections import OrderedDict

import numba
import numpy as np
from scipy.ndimage import distance_transform_edt

try:  # the shared errors module may define it; the planner owns the class otherwise
    from grove_tui.engine.errors import PlanningError
except ImportError:  # pragma: no cover - depends on the state of errors.py
    from grove_tui.engine.errors import GroveError

    class PlanningError(GroveError):
        """No collision-free path: an endpoint is inside an obstacle or the endpoints are disconnected."""


SQRT2 = math.sqrt(2.0)
_NEIGHBOUR_DR = np.array([0, 0, 1, -1, 1, 1, -1, -1], dtype=np.int64)
_NEIGHBOUR_DC = np.array([1, -1, 0, 0, 1, -1, 1, -1], dtype=np.int64)

# ---- numba kernels -----------------------------------------------------------------------------


@numba.njit(cache=True, nogil=True, inline="always")
def _blocked(occupied, transposed, major, minor):
    if transposed:
        return occupied[major, minor]
    return occupied[minor, major]


@numba.njit(cache=True, nogil=True)
def line_of_sight(occupied, clearance, r0, c0, r1, c1):
    """True when the segment between the centres of cells (r0, c0) and (r1, c1) touches no occupied cell.

    Walks the segment one column (or row, for steep segments) at a time; in column i of D the
    segment spans minor offsets [(i - 1/2) d / D, (i + 1/2) d / D], and every cell whose closed square
    meets that span is checked. Where the clearance of the cell under the segment guarantees a free
    disc, whole runs of columns are skipped at once.
    """
    dr = r1 - r0
    dc = c1 - c0
    if abs(dc) >= abs(dr):
        transposed = False
        u0, v0, big, small = c0, r0, abs(dc), abs(dr)
        su = 1 if dc >= 0 else -1
        sv = 1 if dr >= 0 else -1
    else:
        transposed = True
        u0, v0, big, small = r0, c0, abs(dr), abs(dc)
        su = 1 if dr >= 0 else -1
        sv = 1 if dc >= 0 else -1
    if big == 0:
        return not occupied[r0, c0]
    two_big = 2 * big
    i = 0
    while i <= big:
        u = u0 + su * i
        centre_offset = (2 * i * small + big) // two_big
        v_centre = v0 + sv * centre_offset
        if transposed:
            free_radius = clearance[u, v_centre]
        else:
            free_radius = clearance[v_centre, u]
        # Columns i..i+k lie within sqrt(2) (k + 1) of this centre; occupied squares are at least
        # clearance - sqrt(2)/2 away (margins rounded towards safety).
        reach = (free_radius - 0.7072) / 1.4143
        if reach >= 2.0:
            i += int(math.floor(reach))
            continue
        if i == 0:
            j_min = 0
        else:
            num = (2 * i - 1) * small - big
            j_min = -((-num) // two_big)
            if j_min < 0:
                j_min = 0
        if i == big:
            j_max = small
        else:
            j_max = ((2 * i + 1) * small + big) // two_big
            if j_max > small:
                j_max = small
        for j in range(j_min, j_max + 1):
            if _blocked(occupied, transposed, u, v0 + sv * j):
                return False
        i += 1
    return True


@numba.njit(cache=True, nogil=True)
def connected_components(occupied):
    """Label 8-connected free regions (diagonal steps need both orthogonal neighbours free); -1 = occupied."""
    height, width = occupied.shape
    labels = np.full((height, width), -1, dtype=np.int32)
    stack = np.empty(height * width, dtype=np.int64)
    label = 0
    for start in range(height * width):
        sr = start // width
        sc = start % width
        if occupied[sr, sc] or labels[sr, sc] >= 0:
            continue
        labels[sr, sc] = label
        top = 0
        stack[top] = start
        top += 1
        while top > 0:
            top -= 1
            node = stack[top]
            r = node // width
            c = node % width
            for k in range(8):
                nr = r + _NEIGHBOUR_DR[k]
                nc = c + _NEIGHBOUR_DC[k]
                if not _step_allowed(occupied, r, c, nr, nc):
                    continue
                if labels[nr, nc] < 0:
                    labels[nr, nc] = label
                    stack[top] = nr * width + nc
                    top += 1
        label += 1
    return labels


@numba.njit(cache=True, nogil=True, inline="always")
def _step_allowed(occupied, r, c, nr, nc):
    height, width = occupied.shape
    if nr < 0 or nr >= height or nc < 0 or nc >= width or occupied[nr, nc]:
        return False
    if nr != r and nc != c:
        return not occupied[r, nc] and not occupied[nr, c]
    return True


@numba.njit(cache=True, nogil=True, inline="always")
def _before(f_a, g_a, f_b, g_b):
    # Ties on f go to the deeper vertex (larger g): fewer expansions on open ground.
    return f_a < f_b or (f_a == f_b and g_a > g_b)


@numba.njit(cache=True, nogil=True)
def _heap_push(hf, hg, hn, size, f, g, node):
    i = size
    while i > 0:
        up = (i - 1) >> 1
        if not _before(f, g, hf[up], hg[up]):
            break
        hf[i] = hf[up]
        hg[i] = hg[up]
        hn[i] = hn[up]
        i = up
    hf[i] = f
    hg[i] = g
    hn[i] = node
    return size + 1


@numba.njit(cache=True, nogil=True)
def _heap_pop(hf, hg, hn, size):
    size -= 1
    f = hf[size]
    g = hg[size]
    node = hn[size]
    i = 0
    while True:
        child = 2 * i + 1
        if child >= size:
            break
        if child + 1 < size and _before(hf[child + 1], hg[child + 1], hf[child], hg[child]):
            child += 1
        if not _before(hf[child], hg[child], f, g):
            break
        hf[i] = hf[child]
        hg[i] = hg[child]
        hn[i] = hn[child]
        i = child
    hf[i] = f
    hg[i] = g
    hn[i] = node
    return size


@numba.njit(cache=True, nogil=True)
def any_angle_distances(occupied, clearance, sr, sc):
    """Theta*-style Dijkstra from cell (sr, sc) over its whole free region.

    Returns flat (H * W) distances in cells (inf where unreachable) and parents (-1 there): every
    cell's parent is a cell in line of sight, closer to the source. Re-opening improved cells
    makes the result edge-consistent: for every allowed 8-connected step u -> v,
    d(v) <= d(u) + |u v|, so differences of these maps never exceed the 8-connected distance.
    """
    height, width = occupied.shape
    distance = np.full(height * width, np.inf)
    parent = np.full(height * width, -1, dtype=np.int64)
    source = sr * width + sc
    distance[source] = 0.0
    parent[source] = source
    capacity = 4096
    hf = np.empty(capacity, dtype=np.float64)
    hg = np.empty(capacity, dtype=np.float64)
    hn = np.empty(capacity, dtype=np.int64)
    size = _heap_push(hf, hg, hn, 0, 0.0, 0.0, source)
    while size > 0:
        node = hn[0]
        node_d = hf[0]
        size = _heap_pop(hf, hg, hn, size)
        if node_d > distance[node]:
            continue
        r = node // width
        c = node % width
        p = parent[node]
        pr = p // width
        pc = p % width
        for k in range(8):
            nr = r + _NEIGHBOUR_DR[k]
            nc = c + _NEIGHBOUR_DC[k]
            if not _step_allowed(occupied, r, c, nr, nc):
                continue
            nb = nr * width + nc
            if nb == p:
                continue
            via_parent = distance[p] + math.hypot(nr - pr, nc - pc)
            if distance[nb] <= via_parent:
                continue
            if p != node and line_of_sight(occupied, clearance, pr, pc, nr, nc):
                candidate = via_parent
                candidate_parent = p
            else:
                candidate = node_d + (SQRT2 if k >= 4 else 1.0)
                candidate_parent = node
            if candidate >= distance[nb]:
                continue
            distance[nb] = candidate
            parent[nb] = candidate_parent
            if size >= capacity:
                capacity *= 2
                hf2 = np.empty(capacity, dtype=np.float64)
                hg2 = np.empty(capacity, dtype=np.float64)
                hn2 = np.empty(capacity, dtype=np.int64)
                hf2[:size] = hf[:size]
                hg2[:size] = hg[:size]
                hn2[:size] = hn[:size]
                hf, hg, hn = hf2, hg2, hn2
            size = _heap_push(hf, hg, hn, size, candidate, -candidate, nb)
    return distance, parent


@numba.njit(cache=True, nogil=True)
def landmark_table(occupied, clearance, seed_r, seed_c, count):
    """(H * W, count) float32 any-angle distances from `count` landmarks spread by farthest-point selection."""
    height, width = occupied.shape
    table = np.full((height * width, count), np.inf, dtype=np.float32)
    spread, _ = any_angle_distances(occupied, clearance, seed_r, seed_c)
    for l in range(count):
        best = -1
        best_d = -1.0
        for i in range(height * width):
            if spread[i] < np.inf and spread[i] > best_d:
                best_d = spread[i]
                best = i
        if best < 0 or best_d <= 0.0:
            break
        d, _ = any_angle_distances(occupied, clearance, best // width, best % width)
        for i in range(height * width):
            table[i, l] = d[i]
            if d[i] < spread[i] or l == 0:
                spread[i] = d[i]
    return table


@numba.njit(cache=True, nogil=True, inline="always")
def _heuristic(landmarks, goal_row, use_landmarks, node, nr, nc, gr, gc):
    # Euclidean, raised by the landmark (ALT) bound. Both are lower bounds of the 8-connected grid
    # distance to the goal (the landmark maps are edge-consistent), which is all the "never longer
    # than A*" argument needs; being any-angle distances they also stay nearly consistent with
    # Theta*'s own costs, so few vertices are re-opened. The margin absorbs float32 rounding.
    h = math.sqrt((gr - nr) * (gr - nr) + (gc - nc) * (gc - nc))
    if use_landmarks:
        row = landmarks[node]
        for l in range(row.shape[0]):
            bound = abs(goal_row[l] - row[l]) - 0.01
            if bound > h:
                h = bound
    return h


@numba.njit(cache=True, nogil=True)
def theta_star_cells(occupied, clearance, landmarks, sr, sc, gr, gc, g_cost, parent, touched):
    """Theta* from cell (sr, sc) to (gr, gc); returns the (K, 2) int64 array of path cells, empty if none.

    `g_cost` (all inf between queries), `parent` and `touched` are flat work buffers of H * W
    entries reused across queries; only the cells a query touched are reset to inf at its end, so
    a query costs what it explores, not the grid size.
    """
    height, width = occupied.shape
    start = sr * width + sc
    goal = gr * width + gc
    capacity = 4096
    hf = np.empty(capacity, dtype=np.float64)
    hg = np.empty(capacity, dtype=np.float64)
    hn = np.empty(capacity, dtype=np.int64)
    g_cost[start] = 0.0
    parent[start] = start
    touched[0] = start
    touched_count = 1
    goal_row = landmarks[goal]
    use_landmarks = landmarks.shape[1] > 0 and goal_row[0] < np.inf
    size = _heap_push(hf, hg, hn, 0, _heuristic(landmarks, goal_row, use_landmarks, start, sr, sc, gr, gc),
                      0.0, start)
    found = False
    while size > 0:
        node = hn[0]
        node_g = hg[0]
        size = _heap_pop(hf, hg, hn, size)
        if node_g > g_cost[node]:
            continue  # stale entry: the vertex was improved and pushed again
        if node == goal:
            found = True
            break
        r = node // width
        c = node % width
        p = parent[node]
        pr = p // width
        pc = p % width
        g_p = g_cost[p]
        for k in range(8):
            nr = r + _NEIGHBOUR_DR[k]
            nc = c + _NEIGHBOUR_DC[k]
            if not _step_allowed(occupied, r, c, nr, nc):
                continue
            nb = nr * width + nc
            if nb == p:
                continue
            g_known = g_cost[nb]
            via_parent = g_p + math.sqrt((nr - pr) * (nr - pr) + (nc - pc) * (nc - pc))
            # Neither relaxation can beat g(parent) + |parent n| (triangle inequality): skip the
            # line-of-sight test when the neighbour is already at least that good.
            if g_known <= via_parent:
                continue
            if p != node and line_of_sight(occupied, clearance, pr, pc, nr, nc):
                candidate = via_parent
                candidate_parent = p
            else:
                step = SQRT2 if (nr != r and nc != c) else 1.0
                candidate = node_g + step
                candidate_parent = node
            if candidate >= g_known:
                continue
            if g_known == np.inf:
                touched[touched_count] = nb
                touched_count += 1
            g_cost[nb] = candidate
            parent[nb] = candidate_parent
            if size >= capacity:
                capacity *= 2
                hf2 = np.empty(capacity, dtype=np.float64)
                hg2 = np.empty(capacity, dtype=np.float64)
                hn2 = np.empty(capacity, dtype=np.int64)
                hf2[:size] = hf[:size]
                hg2[:size] = hg[:size]
                hn2[:size] = hn[:size]
                hf, hg, hn = hf2, hg2, hn2
            h = _heuristic(landmarks, goal_row, use_landmarks, nb, nr, nc, gr, gc)
            size = _heap_push(hf, hg, hn, size, candidate + h, candidate, nb)
    for i in range(touched_count):
        g_cost[touched[i]] = np.inf
    if not found:
        return np.empty((0, 2), dtype=np.int64)
    count = 1
    node = goal
    while node != start:
        node = parent[node]
        count += 1
    cells = np.empty((count, 2), dtype=np.int64)
    node = goal
    for i in range(count - 1, -1, -1):
        cells[i, 0] = node // width
        cells[i, 1] = node % width
        node = parent[node]
    return cells


# ---- Python API --------------------------------------------------------------------------------


def clearance_map(occupied: np.ndarray) -> np.ndarray:
    """Distance (in cells) from every cell centre to the nearest occupied cell centre; outside counts as occupied."""
    padded = np.zeros((occupied.shape[0] + 2, occupied.shape[1] + 2), dtype=bool)
    padded[1:-1, 1:-1] = ~occupied
    return distance_transform_edt(padded)[1:-1, 1:-1].astype(np.float32)


# Landmark maps pay for themselves on big grids and many queries only: the eight of them cost
# 0.5-1 s of CPU per 100k cells, once (hospital at 0.05 m: 7 s for 1.1M cells). Below the
# threshold (every shipped world at 0.1 m) a query with the Euclidean heuristic alone takes tens
# of milliseconds at worst; a caller planning many legs on a grid can ask for landmarks explicitly.
AUTO_LANDMARKS = 8
AUTO_LANDMARKS_MIN_CELLS = 500_000


class ThetaStarPlanner:
    """Any-angle shortest paths on one occupancy grid; builds its lookup maps once, then plans in milliseconds.

    `landmarks`: number of ALT landmark maps, built on the first query; None picks AUTO_LANDMARKS
    for grids of at least AUTO_LANDMARKS_MIN_CELLS cells and none below. Create one planner per grid
    and keep it (PlanCache.planner does). Thread-safe: queries share work buffers behind a lock
    (the kernels release the GIL).
    """

    def __init__(self, grid, landmarks: int | None = None):
        self.grid = grid
        self.occupied = np.ascontiguousarray(grid.occupied, dtype=np.bool_)
        if self.occupied.ndim != 2 or self.occupied.size == 0:
            raise PlanningError(f"occupancy grid has shape {self.occupied.shape}; a planner needs a non-empty 2-D grid")
        self.resolution = float(grid.resolution)
        # Centre of cell (0, 0), asked of the grid so both agree on where cells are.
        self.centre_x, self.centre_y = (float(v) for v in grid.cell_to_world(0, 0))
        self.clearance = clearance_map(self.occupied)
        self.components = connected_components(self.occupied)
        cells = self.occupied.size
        if landmarks is None:
            landmarks = AUTO_LANDMARKS if cells >= AUTO_LANDMARKS_MIN_CELLS else 0
        self.landmark_count = int(landmarks)
        self._landmark_maps: np.ndarray | None = None
        self._g_cost = np.full(cells, np.inf)
        self._parent = np.zeros(cells, dtype=np.int32)
        self._touched = np.zeros(cells, dtype=np.int32)
        self._lock = threading.Lock()

    @property
    def landmarks(self) -> np.ndarray:
        """(H * W, L) float32 any-angle distances from L landmarks of the largest free region (built once)."""
        if self._landmark_maps is None:
            self._landmark_maps = self._build_landmarks(self.landmark_count)
        return self._landmark_maps

    def _build_landmarks(self, count: int) -> np.ndarray:
        labels = self.components
        if count <= 0 or labels.max() < 0:
            return np.zeros((labels.size, 0), dtype=np.float32)
        biggest = np.bincount(labels[labels >= 0]).argmax()
        seed = np.flatnonzero(labels.ravel() == biggest)[0]
        width = labels.shape[1]
        return landmark_table(self.occupied, self.clearance, seed // width, seed % width, count)

    @property
    def shape(self) -> tuple[int, int]:
        return self.occupied.shape

    def cell_of(self, x: float, y: float) -> tuple[int, int]:
        """The (row, col) whose square contains (x, y); may lie outside the grid."""
        col = math.floor((x - self.centre_x) / self.resolution + 0.5)
        row = math.floor((y - self.centre_y) / self.resolution + 0.5)
        return row, col

    def cell_centre(self, row: int, col: int) -> tuple[float, float]:
        return self.centre_x + col * self.resolution, self.centre_y + row * self.resolution

    def cell_is_free(self, row: int, col: int) -> bool:
        height, width = self.occupied.shape
        return 0 <= row < height and 0 <= col < width and not self.occupied[row, col]

    def snap(self, x: float, y: float, label: str, role: str) -> tuple[int, int]:
        """The free cell for an endpoint: its own cell, or the nearest free cell at most one cell away."""
        row, col = self.cell_of(x, y)
        if self.cell_is_free(row, col):
            return row, col
        best = None
        best_distance = math.inf
        for dr in (-1, 0, 1):
            for dc in (-1, 0, 1):
                if self.cell_is_free(row + dr, col + dc):
                    cx, cy = self.cell_centre(row + dr, col + dc)
                    distance = math.hypot(cx - x, cy - y)
                    if distance < best_distance:
                        best, best_distance = (row + dr, col + dc), distance
        if best is None:
            height, width = self.occupied.shape
            where = "outside the grid" if not (0 <= row < height and 0 <= col < width) else "inside an obstacle"
            raise PlanningError(
                f"{role} {label!r} at ({x:.2f}, {y:.2f}) is {where} (after inflation by "
                f"{getattr(self.grid, 'inflation', 0.0):.2f} m) and no free cell lies within one cell "
                f"({self.resolution:g} m); move it into walkable space")
        return best

    def segment_is_free(self, x0: float, y0: float, x1: float, y1: float) -> bool:
        """Whether the straight segment between two world points touches no occupied cell (exact, conservative)."""
        return segment_is_free(self.occupied, self.centre_x, self.centre_y, self.resolution, x0, y0, x1, y1)

    def plan_cells(self, start_cell: tuple[int, int], goal_cell: tuple[int, int]) -> np.ndarray:
        """Theta* between two free cells: (K, 2) int64 (row, col), empty when they are disconnected."""
        (sr, sc), (gr, gc) = start_cell, goal_cell
        if self.components[sr, sc] != self.components[gr, gc]:
            return np.empty((0, 2), dtype=np.int64)
        with self._lock:
            return theta_star_cells(self.occupied, self.clearance, self.landmarks, sr, sc, gr, gc,
                                    self._g_cost, self._parent, self._touched)

    def plan(self, start, goal, start_label: str = "start", goal_label: str = "goal") -> np.ndarray:
        """(K, 2) float64 world points from `start` to `goal` inclusive, every segment collision-free.

        An endpoint inside an obstacle (or on the border of one) but within one cell of free space is
        joined through the centre of the nearest free cell: that first/last short segment is the only
        one that may touch an occupied cell.
        """
        sx, sy = (float(v) for v in start)
        gx, gy = (float(v) for v in goal)
        start_cell = self.snap(sx, sy, start_label, "start")
        goal_cell = self.snap(gx, gy, goal_label, "goal")
        cells = self.plan_cells(start_cell, goal_cell)
        if len(cells) == 0:
            raise PlanningError(
                f"no collision-free path from {start_label!r} ({sx:.2f}, {sy:.2f}) to {goal_label!r} "
                f"({gx:.2f}, {gy:.2f}): they lie in separate walkable regions of the grid "
                f"(resolution {self.resolution:g} m, inflation {getattr(self.grid, 'inflation', 0.0):.2f} m); "
                f"a wall or a narrow door blocks the way")
        corners = [self.cell_centre(int(r), int(c)) for r, c in cells]
        points = [(sx, sy)]
        interior = corners[1:-1]
        # The exact endpoints replace the centres of their cells when the straight line allows it,
        # otherwise the path goes through the cell centre (a segment inside one free cell is free).
        first_target = interior[0] if interior else (gx, gy)
        # A point on the border of an occupied cell already touches it: treat it like a snapped one.
        start_in_free_cell = self.cell_of(sx, sy) == tuple(start_cell) and self.segment_is_free(sx, sy, sx, sy)
        if not (start_in_free_cell and self.segment_is_free(sx, sy, *first_target)):
            points.append(corners[0])
        points.extend(interior)
        last_from = points[-1]
        goal_in_free_cell = self.cell_of(gx, gy) == tuple(goal_cell) and self.segment_is_free(gx, gy, gx, gy)
        if not (goal_in_free_cell and self.segment_is_free(*last_from, gx, gy)) and len(corners) > 1:
            points.append(corners[-1])
        points.append((gx, gy))
        path = np.array(points, dtype=np.float64)
        keep = np.ones(len(path), dtype=bool)
        keep[1:] = np.any(np.abs(np.diff(path, axis=0)) > 1e-9, axis=1)
        return path[keep]


@numba.njit(cache=True, nogil=True)
def segment_is_free(occupied, centre_x, centre_y, resolution, x0, y0, x1, y1):
    """Exact test of a world-space segment against occupied cell squares (touching counts as a hit)."""
    height, width = occupied.shape
    # cell units with integer cell centres; a cell (r, c) covers [c - 1/2, c + 1/2] x [r - 1/2, r + 1/2]
    ax = (x0 - centre_x) / resolution
    ay = (y0 - centre_y) / resolution
    bx = (x1 - centre_x) / resolution
    by = (y1 - centre_y) / resolution
    eps = 1e-9
    col_lo = int(math.floor(min(ax, bx) + 0.5 - eps))
    col_hi = int(math.floor(max(ax, bx) + 0.5 + eps))
    for c in range(col_lo, col_hi + 1):
        # part of the segment whose x lies in the closed column [c - 1/2, c + 1/2]
        xl = max(c - 0.5, min(ax, bx))
        xh = min(c + 0.5, max(ax, bx))
        if xh < xl - eps:
            continue
        if abs(bx - ax) < 1e-12:
            ylo = min(ay, by)
            yhi = max(ay, by)
        else:
            t0 = (xl - ax) / (bx - ax)
            t1 = (xh - ax) / (bx - ax)
            ya = ay + t0 * (by - ay)
            yb = ay + t1 * (by - ay)
            ylo = min(ya, yb)
            yhi = max(ya, yb)
        r_lo = int(math.floor(ylo + 0.5 - eps))
        r_hi = int(math.floor(yhi + 0.5 + eps))
        for r in range(r_lo, r_hi + 1):
            if r < 0 or r >= height or c < 0 or c >= width or occupied[r, c]:
                return False
    return True


def path_length(path: np.ndarray) -> float:
    return float(np.sum(np.hypot(*np.diff(np.asarray(path, dtype=np.float64), axis=0).T))) if len(path) > 1 else 0.0


class PlanCache:
    """Plans and velocity fields by (world name, resolution, inflation, endpoints rounded to 1 cm).

    Bounded LRU; the TUI keeps one per session so re-generating a scenario does not re-plan what it has.
    """

    def __init__(self, max_entries: int = 4096):
        self.max_entries = max_entries
        self._entries: OrderedDict = OrderedDict()
        self._lock = threading.Lock()
        self.hits = 0
        self.misses = 0

    @staticmethod
    def key(world_name: str, resolution: float, inflation: float, kind: str, *points) -> tuple:
        rounded = tuple(round(float(v), 2) + 0.0 for p in points for v in p)
        return (str(world_name), round(float(resolution), 6), round(float(inflation), 6), kind, rounded)

    def get(self, key):
        with self._lock:
            if key in self._entries:
                self._entries.move_to_end(key)
                self.hits += 1
                return self._entries[key]
            self.misses += 1
            return None

    def put(self, key, value) -> None:
        with self._lock:
            self._entries[key] = value
            self._entries.move_to_end(key)
            while len(self._entries) > self.max_entries:
                self._entries.popitem(last=False)

    def __len__(self) -> int:
        return len(self._entries)

    def planner(self, grid, landmarks: int | None = None) -> ThetaStarPlanner:
        """One planner per (world, resolution, inflation): its landmark maps cost seconds on big grids."""
        key = (str(getattr(grid, "world_name", "")), round(float(grid.resolution), 6),
               round(float(getattr(grid, "inflation", 0.0)), 6), "planner", grid.occupied.shape)
        planner = self.get(key)
        if planner is None or planner.grid is not grid and not np.array_equal(planner.occupied, grid.occupied):
            planner = ThetaStarPlanner(grid, landmarks=landmarks)
            self.put(key, planner)
        return planner

    def plan(self, world_name: str, planner: ThetaStarPlanner, start, goal,
             start_label: str = "start", goal_label: str = "goal") -> np.ndarray:
        """`planner.plan` through the cache (errors are not cached: they are cheap to reproduce)."""
        key = self.key(world_name, planner.resolution, getattr(planner.grid, "inflation", 0.0), "path", start, goal)
        path = self.get(key)
        if path is None:
            path = planner.plan(start, goal, start_label=start_label, goal_label=goal_label)
            path.setflags(write=False)
            self.put(key, path)
        return path

    def field(self, world_name: str, planner: ThetaStarPlanner, start, exit_point,
              start_label: str = "group", exit_label: str = "exit"):
        """Velocity field from a group centroid to an exit, planned and built once per key."""
        from grove_tui.engine.velocity_field import build_velocity_field

        key = self.key(world_name, planner.resolution, getattr(planner.grid, "inflation", 0.0), "field",
                       start, exit_point)
        field = self.get(key)
        if field is None:
            path = self.plan(world_name, planner, start, exit_point, start_label=start_label, goal_label=exit_label)
            field = build_velocity_field(planner.grid, path, exit_point)
            self.put(key, field)
        return field
