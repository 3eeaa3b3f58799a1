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
import os
import threading
from collections import OrderedDict
from collections.abc import Sequence
import hashlib
import weakref
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numba
import numpy as np
from scipy.ndimage import distance_transform_edt

from grove_tui.errors import PlanningError
from grove_tui.navigation.grid import OccupancyGrid
from grove_tui.world import World

if TYPE_CHECKING:
    from grove_tui.navigation.door_graph import DoorGraph
    from grove_tui.navigation.velocity_field import VelocityField

# PlanCache's key: world, resolution, inflation, kind, then the points (or a grid's shape) it is for
CacheKey = tuple[str, float, float, str, tuple[float, ...] | tuple[int, ...]]


SQRT2 = math.sqrt(2.0)
_NEIGHBOUR_DR = np.array([0, 0, 1, -1, 1, 1, -1, -1], dtype=np.int64)
_NEIGHBOUR_DC = np.array([1, -1, 0, 0, 1, -1, 1, -1], dtype=np.int64)
LANDMARK_UNREACHABLE = 65535  # uint16 landmark entry of a cell the landmark cannot reach

# ---- numba kernels -----------------------------------------------------------------------------
#
# The kernels read the grid through "sight maps": the clearance of every cell in half cells as
# uint8 (0 exactly on occupied cells, rounded down, capped at 255), once row-major and once
# transposed. One byte per cell keeps a 1000 x 1000 grid in the L2 cache, and walking a steep
# segment through the transposed copy reads memory in order instead of one row apart.


@numba.njit(cache=True, nogil=True)
def line_of_sight(sight_rows: np.ndarray, sight_cols: np.ndarray, r0: int, c0: int, r1: int, c1: int) -> bool:
    """True when the segment between the centres of cells (r0, c0) and (r1, c1) touches no occupied cell.

    Walks the segment one column (or row, for steep segments) at a time; in column i of D the
    segment spans minor offsets [(i - 1/2) d / D, (i + 1/2) d / D], and every cell whose closed square
    meets that span is checked. Where the clearance of the cell under the segment guarantees a free
    disc, whole runs of columns are skipped at once.
    """
    dr = r1 - r0
    dc = c1 - c0
    if abs(dc) >= abs(dr):
        sight = sight_rows
        u0, v0, big, small = c0, r0, abs(dc), abs(dr)
        su = 1 if dc >= 0 else -1
        sv = 1 if dr >= 0 else -1
    else:
        sight = sight_cols
        u0, v0, big, small = r0, c0, abs(dr), abs(dc)
        su = 1 if dr >= 0 else -1
        sv = 1 if dc >= 0 else -1
    if big == 0:
        return sight[v0, u0] != 0
    two_big = 2 * big
    slope = small / big
    inv_step = 1.0 / math.sqrt(1.0 + slope * slope)
    i = 0
    while i <= big:
        u = u0 + su * i
        # The cell under the segment at column i. i * slope is a fraction with denominator D, so it
        # is either exactly half-way (the segment touches both cells) or far from it: rounding the
        # float picks a cell the segment touches.
        under = sight[v0 + sv * int(i * slope + 0.5), u]
        if under == 0:
            return False
        # Skipping columns i .. i+k-1 is safe when each of their points, at most
        # 1/2 + (k - 1/2) step from this cell's centre, is more than sqrt(2)/2 from every occupied
        # centre: k < (clearance - 1/2 - sqrt(2)/2) / step + 1/2 (0.01 cell of margin).
        skip = int((under * 0.5 - 1.2172) * inv_step + 0.5)
        if skip >= 2:
            i += skip
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
            if sight[v0 + sv * j, u] == 0:
                return False
        i += 1
    return True


@numba.njit(cache=True, nogil=True, inline="always")
def _step_allowed(sight_rows: np.ndarray, r: int, c: int, nr: int, nc: int) -> bool:
    height, width = sight_rows.shape
    if nr < 0 or nr >= height or nc < 0 or nc >= width or sight_rows[nr, nc] == 0:
        return False
    if nr != r and nc != c:
        return sight_rows[r, nc] != 0 and sight_rows[nr, c] != 0
    return True


@numba.njit(cache=True, nogil=True)
def connected_components(occupied: np.ndarray) -> np.ndarray:
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
                if nr < 0 or nr >= height or nc < 0 or nc >= width or occupied[nr, nc]:
                    continue
                if nr != r and nc != c and (occupied[r, nc] or occupied[nr, c]):
                    continue
                if labels[nr, nc] < 0:
                    labels[nr, nc] = label
                    stack[top] = nr * width + nc
                    top += 1
        label += 1
    return labels


# The open list is a binary heap of (f, g, vertex) rows in one array, so a sift touches one cache
# line per level. Ties on f go to the deeper vertex (larger g): fewer expansions on open ground.


@numba.njit(cache=True, nogil=True, inline="always")
def _heap_push(heap: np.ndarray, size: int, f: float, g: float, node: int) -> int:
    i = size
    while i > 0:
        up = (i - 1) >> 1
        f_up = heap[up, 0]
        if not (f < f_up or (f == f_up and g > heap[up, 1])):
            break
        heap[i, 0] = f_up
        heap[i, 1] = heap[up, 1]
        heap[i, 2] = heap[up, 2]
        i = up
    heap[i, 0] = f
    heap[i, 1] = g
    heap[i, 2] = node
    return size + 1


@numba.njit(cache=True, nogil=True, inline="always")
def _heap_pop(heap: np.ndarray, size: int) -> int:
    size -= 1
    f = heap[size, 0]
    g = heap[size, 1]
    node = heap[size, 2]
    i = 0
    while True:
        child = 2 * i + 1
        if child >= size:
            break
        if child + 1 < size:
            f_right = heap[child + 1, 0]
            f_left = heap[child, 0]
            if f_right < f_left or (f_right == f_left and heap[child + 1, 1] > heap[child, 1]):
                child += 1
        f_child = heap[child, 0]
        if not (f_child < f or (f_child == f and heap[child, 1] > g)):
            break
        heap[i, 0] = f_child
        heap[i, 1] = heap[child, 1]
        heap[i, 2] = heap[child, 2]
        i = child
    heap[i, 0] = f
    heap[i, 1] = g
    heap[i, 2] = node
    return size


@numba.njit(cache=True, nogil=True, inline="always")
def _heap_room(heap: np.ndarray, size: int) -> np.ndarray:
    if size < heap.shape[0]:
        return heap
    bigger = np.empty((2 * heap.shape[0], 3), dtype=np.float64)
    bigger[:size] = heap[:size]
    return bigger


@numba.njit(cache=True, nogil=True)
def any_angle_distances(sight_rows: np.ndarray, sight_cols: np.ndarray, sr: int, sc: int) -> tuple[np.ndarray, np.ndarray]:
    """Theta*-style Dijkstra from cell (sr, sc) over its whole free region.

    Returns flat (H * W) distances in cells (inf where unreachable) and parents (-1 there): every
    cell's parent is a cell in line of sight, closer to the source. Re-opening improved cells
    makes the result edge-consistent: for every allowed 8-connected step u -> v,
    d(v) <= d(u) + |u v|, so differences of these maps never exceed the 8-connected distance.
    """
    height, width = sight_rows.shape
    distance = np.full(height * width, np.inf)
    parent = np.full(height * width, -1, dtype=np.int64)
    source = sr * width + sc
    distance[source] = 0.0
    parent[source] = source
    heap = np.empty((4096, 3), dtype=np.float64)
    size = _heap_push(heap, 0, 0.0, 0.0, source)
    while size > 0:
        node = int(heap[0, 2])
        node_d = heap[0, 0]
        size = _heap_pop(heap, size)
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
            if not _step_allowed(sight_rows, r, c, nr, nc):
                continue
            nb = nr * width + nc
            if nb == p:
                continue
            via_parent = distance[p] + math.hypot(nr - pr, nc - pc)
            if distance[nb] <= via_parent:
                continue
            if p != node and line_of_sight(sight_rows, sight_cols, pr, pc, nr, nc):
                candidate = via_parent
                candidate_parent = p
            else:
                candidate = node_d + (SQRT2 if k >= 4 else 1.0)
                candidate_parent = node
            if candidate >= distance[nb]:
                continue
            distance[nb] = candidate
            parent[nb] = candidate_parent
            heap = _heap_room(heap, size)
            size = _heap_push(heap, size, candidate, -candidate, nb)
    return distance, parent


@numba.njit(cache=True, nogil=True)
def hop_distances(sight_rows: np.ndarray, sr: int, sc: int) -> np.ndarray:
    """Breadth-first 8-connected step counts from (sr, sc), flat; -1 where unreachable (cheap, for placing landmarks)."""
    height, width = sight_rows.shape
    hops = np.full(height * width, -1, dtype=np.int32)
    queue = np.empty(height * width, dtype=np.int64)
    source = sr * width + sc
    hops[source] = 0
    queue[0] = source
    head = 0
    tail = 1
    while head < tail:
        node = queue[head]
        head += 1
        r = node // width
        c = node % width
        for k in range(8):
            nr = r + _NEIGHBOUR_DR[k]
            nc = c + _NEIGHBOUR_DC[k]
            if not _step_allowed(sight_rows, r, c, nr, nc):
                continue
            nb = nr * width + nc
            if hops[nb] < 0:
                hops[nb] = hops[node] + 1
                queue[tail] = nb
                tail += 1
    return hops


@numba.njit(cache=True, nogil=True)
def _store_landmark(table: np.ndarray, column: int, distance: np.ndarray, scale: float) -> None:
    # Rounded to 1/scale cell; the heuristic takes one unit off the difference, so the bound stays
    # below the true distance difference. Clamping keeps it a lower bound (|clamp a - clamp b| <= |a - b|).
    for i in range(distance.shape[0]):
        d = distance[i]
        if d == np.inf:
            table[i, column] = LANDMARK_UNREACHABLE
        else:
            table[i, column] = min(int(d * scale + 0.5), LANDMARK_UNREACHABLE - 1)


@numba.njit(cache=True, nogil=True, inline="always")
def _heuristic(landmarks: np.ndarray, goal_row: np.ndarray, use_landmarks: bool, inv_scale: float, node: int,
               nr: int, nc: int, gr: int, gc: int, guide: np.ndarray, guide_block: int, guide_cols: int,
               guide_slack: float) -> float:
    # Euclidean, raised by the landmark (ALT) bound. Both are lower bounds of the 8-connected grid
    # distance to the goal (the landmark maps are edge-consistent), which is all the "never longer
    # than A*" argument needs; being any-angle distances they also stay nearly consistent with
    # Theta*'s own costs, so few vertices are re-opened. A guide (block distances to the goal,
    # see block_distances) raises it further, less its slack: no longer a strict lower bound.
    h = math.sqrt((gr - nr) * (gr - nr) + (gc - nc) * (gc - nc))
    if use_landmarks:
        row = landmarks[node]
        widest: int | np.int64 = 0
        for l in range(row.shape[0]):
            gap = np.int64(goal_row[l]) - np.int64(row[l])
            if gap < 0:
                gap = -gap
            if gap > widest:
                widest = gap
        bound = (widest - 1) * inv_scale - 0.001  # the unit absorbs rounding to the table, 0.001 float error
        if bound > h:
            h = bound
    if guide_block > 0:
        ahead = guide[(nr // guide_block) * guide_cols + nc // guide_block] - guide_slack
        if ahead > h and ahead < np.inf:
            h = ahead
    return h


@numba.njit(cache=True, nogil=True)
def theta_star_cells(sight_rows: np.ndarray, sight_cols: np.ndarray, landmarks: np.ndarray, inv_scale: float,
                     sr: int, sc: int, gr: int, gc: int, g_cost: np.ndarray, parent: np.ndarray, touched: np.ndarray,
                     guide: np.ndarray, guide_block: int, guide_cols: int, guide_slack: float) -> np.ndarray:
    """Theta* from cell (sr, sc) to (gr, gc); returns the (K, 2) int64 array of path cells, empty if none.

    `landmarks` is the (H * W, L) uint16 table in units of 1 / `inv_scale` cells (L may be 0);
    `guide` the goal's block distances (block_distances) or empty.
    `g_cost` (all inf between queries), `parent` and `touched` are flat work buffers of H * W
    entries reused across queries; only the cells a query touched are reset to inf at its end, so
    a query costs what it explores, not the grid size.
    """
    height, width = sight_rows.shape
    start = sr * width + sc
    goal = gr * width + gc
    heap = np.empty((4096, 3), dtype=np.float64)
    g_cost[start] = 0.0
    parent[start] = start
    touched[0] = start
    touched_count = 1
    goal_row = landmarks[goal]
    use_landmarks = landmarks.shape[1] > 0 and goal_row[0] != LANDMARK_UNREACHABLE
    size = _heap_push(heap, 0, _heuristic(landmarks, goal_row, use_landmarks, inv_scale, start, sr, sc, gr, gc, guide, guide_block,
                                 guide_cols, guide_slack),
                      0.0, start)
    found = False
    while size > 0:
        node = int(heap[0, 2])
        node_g = heap[0, 1]
        size = _heap_pop(heap, size)
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
            if not _step_allowed(sight_rows, r, c, nr, nc):
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
            if p != node and line_of_sight(sight_rows, sight_cols, pr, pc, nr, nc):
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
            heap = _heap_room(heap, size)
            h = _heuristic(landmarks, goal_row, use_landmarks, inv_scale, nb, nr, nc, gr, gc, guide, guide_block,
                           guide_cols, guide_slack)
            size = _heap_push(heap, size, candidate + h, candidate, nb)
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


# ---- block guide ------------------------------------------------------------------------------
#
# On big grids the open list of an exact search floods every room and dead end that is close to
# the goal as the crow flies (a long query on the 1000 x 1000 benchmark grid expanded 40,000 to
# 130,000 cells for a path of 1,000). A coarse graph of 8 x 8-cell blocks (adjacent blocks joined
# where some pair of free cells touches across their border, so every grid path is a block path)
# gives, per query, one Dijkstra over the blocks from the goal's block: a distance-to-goal that
# knows the walls. Raised by it (less one and a half blocks of slack), Theta* heads for the goal
# and expands a tenth of that; paths came out 0.3-0.5 % longer on the benchmark queries.


@numba.njit(cache=True, nogil=True)
def block_graph(occupied: np.ndarray, block: int) -> np.ndarray:
    """(rows, cols, 8) bool: whether each block of `block` x `block` cells reaches its neighbour in
    direction k (the order of _NEIGHBOUR_DR/_DC) through a step the grid allows."""
    height, width = occupied.shape
    rows = (height + block - 1) // block
    cols = (width + block - 1) // block
    joined = np.zeros((rows, cols, 8), dtype=np.bool_)
    for br in range(rows):
        for bc in range(cols):
            r0 = br * block
            c0 = bc * block
            r1 = min(r0 + block, height)
            c1 = min(c0 + block, width)
            if c1 < width and bc + 1 < cols:  # east
                for r in range(r0, r1):
                    if not occupied[r, c1 - 1] and not occupied[r, c1]:
                        joined[br, bc, 0] = True
                        joined[br, bc + 1, 1] = True
                        break
            if r1 < height and br + 1 < rows:  # north (row + 1)
                for c in range(c0, c1):
                    if not occupied[r1 - 1, c] and not occupied[r1, c]:
                        joined[br, bc, 2] = True
                        joined[br + 1, bc, 3] = True
                        break
            # diagonals: the corner step is allowed only with both orthogonal cells free
            if r1 < height and c1 < width and br + 1 < rows and bc + 1 < cols:
                if not (occupied[r1 - 1, c1 - 1] or occupied[r1, c1] or occupied[r1 - 1, c1] or occupied[r1, c1 - 1]):
                    joined[br, bc, 4] = True
                    joined[br + 1, bc + 1, 7] = True
            if r1 < height and c0 > 0 and br + 1 < rows and bc > 0:
                if not (occupied[r1 - 1, c0] or occupied[r1, c0 - 1] or occupied[r1 - 1, c0 - 1] or occupied[r1, c0]):
                    joined[br, bc, 5] = True
                    joined[br + 1, bc - 1, 6] = True
    return joined


@numba.njit(cache=True, nogil=True)
def block_distances(joined: np.ndarray, goal_row: int, goal_col: int, block: int) -> np.ndarray:
    """Flat octile distances in cells from the goal's block to every block (inf where unjoined)."""
    rows, cols = joined.shape[0], joined.shape[1]
    distance = np.full(rows * cols, np.inf)
    source = goal_row * cols + goal_col
    distance[source] = 0.0
    heap = np.empty((4096, 3), dtype=np.float64)
    size = _heap_push(heap, 0, 0.0, 0.0, source)
    diagonal = block * SQRT2
    while size > 0:
        node = int(heap[0, 2])
        d = heap[0, 0]
        size = _heap_pop(heap, size)
        if d > distance[node]:
            continue
        r = node // cols
        c = node % cols
        for k in range(8):
            if not joined[r, c, k]:
                continue
            nb = (r + _NEIGHBOUR_DR[k]) * cols + c + _NEIGHBOUR_DC[k]
            candidate = d + (diagonal if k >= 4 else block)
            if candidate < distance[nb]:
                distance[nb] = candidate
                heap = _heap_room(heap, size)
                size = _heap_push(heap, size, candidate, -candidate, nb)
    return distance


# ---- Python API --------------------------------------------------------------------------------


def clearance_map(occupied: np.ndarray) -> np.ndarray:
    """Distance (in cells) from every cell centre to the nearest occupied cell centre; outside counts as occupied."""
    padded = np.zeros((occupied.shape[0] + 2, occupied.shape[1] + 2), dtype=bool)
    padded[1:-1, 1:-1] = ~occupied
    return distance_transform_edt(padded)[1:-1, 1:-1].astype(np.float32)


def sight_maps(clearance: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The kernels' view of a grid: clearance in half cells as uint8 (0 on occupied cells), row-major and transposed.

    Free cells have a clearance of at least one cell, so 0 marks exactly the occupied ones; rounding
    down and capping at 255 only make the line-of-sight skips shorter, never unsafe.
    """
    half_cells = np.floor(np.minimum(np.asarray(clearance, dtype=np.float64) * 2.0, 255.0)).astype(np.uint8)
    return np.ascontiguousarray(half_cells), np.ascontiguousarray(half_cells.T)


# Landmark maps (ALT) keep Theta*'s "never longer than 8-connected A*" on any grid, but pay for
# themselves on big grids and many queries only: sixteen of them cost about 0.5 s of CPU per 100k
# cells, once (hospital at 0.05 m, 1.1M cells: ~6 s of CPU), and 32 bytes per cell. Grids of
# GUIDE_MIN_CELLS or more are guided by blocks instead (see block_graph), built in milliseconds:
# on the benchmark grids p90 fell from 33-36 ms to 11-17 ms (CPU, loaded machine). A caller that
# wants exact paths there asks for landmarks explicitly.
GUIDE_MIN_CELLS = 500_000
GUIDE_BLOCK = 8
GUIDE_SLACK_BLOCKS = 1.5


def landmark_sites(sight_rows: np.ndarray, seed_cell: tuple[int, int], count: int) -> list[int]:
    """Up to `count` flat cell indices spread over the seed's free region by farthest-point selection on step counts."""
    height, width = sight_rows.shape
    spread = hop_distances(sight_rows, *seed_cell)
    sites: list[int] = []
    for _ in range(count):
        farthest = int(np.argmax(spread))
        if spread[farthest] <= 0:
            break
        sites.append(farthest)
        np.minimum(spread, hop_distances(sight_rows, farthest // width, farthest % width), out=spread)
    return sites


GEODESICS_KEPT = 8  # shortest-path trees kept per grid (8 bytes x 2 per cell each)
# From the TREE_AFTER-th plan to one goal cell on, plans to it are read off its shortest-path tree:
# one Dijkstra over the grid (0.15 s of CPU for the hospital at 0.1 m) instead of a search each.
TREE_AFTER = 16


@dataclass(eq=False)
class _SharedMaps:
    """What every planner of one grid object shares: its lookup maps, block guides, trees, door graphs."""

    fingerprint: bytes
    occupied: np.ndarray
    clearance: np.ndarray
    sight_rows: np.ndarray
    sight_cols: np.ndarray
    components: np.ndarray
    lock: threading.RLock = field(default_factory=threading.RLock)
    block_graph: np.ndarray | None = None
    guides: OrderedDict = field(default_factory=OrderedDict)
    geodesics: OrderedDict = field(default_factory=OrderedDict)
    door_graphs: dict = field(default_factory=dict)
    goal_requests: dict = field(default_factory=dict)


_SHARED: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_SHARED_LOCK = threading.Lock()


def _shared_maps(grid: OccupancyGrid, occupied: np.ndarray) -> _SharedMaps:
    """The grid's shared maps, rebuilt when its cells changed since (a grid object is not always read-only)."""
    fingerprint = hashlib.blake2b(np.packbits(occupied).tobytes() + str(occupied.shape).encode(),
                                  digest_size=16).digest()
    with _SHARED_LOCK:
        try:
            shared = _SHARED.get(grid)
        except TypeError:  # an unhashable grid-like object: nothing to share it through
            shared = None
        if shared is not None and shared.fingerprint == fingerprint:
            return shared
    clearance = clearance_map(occupied)
    sight_rows, sight_cols = sight_maps(clearance)
    shared = _SharedMaps(fingerprint, occupied, clearance, sight_rows, sight_cols, connected_components(occupied))
    with _SHARED_LOCK:
        try:
            _SHARED[grid] = shared
        except TypeError:
            pass
    return shared


class ThetaStarPlanner:
    """Any-angle shortest paths on one occupancy grid; builds its lookup maps once, then plans in milliseconds.

    `landmarks`: number of ALT landmark maps, built on the first query (exact paths); None picks none,
    and grids of at least GUIDE_MIN_CELLS cells are guided by blocks. `world`: the world the grid was
    built from (by default the grid's own, see build_grid); without landmarks, plans between its zones
    then search only the start and goal zones (DoorGraph).
    Create one planner per grid
    and keep it (PlanCache.planner does). Thread-safe: queries share work buffers behind a lock
    (the kernels release the GIL).
    """

    def __init__(self, grid: OccupancyGrid, landmarks: int | None = None, world: World | None = None,
                 door_graph_dir: Path | None = None):
        self.grid = grid
        # With the grid's world (given, or the one build_grid made the grid from), plans between
        # zones go through its door graph (door_graph.py), built on first use or read from the data dir.
        self.world = world if world is not None else getattr(grid, "world", None)
        self._door_graph_dir = door_graph_dir
        occupied = np.ascontiguousarray(grid.occupied, dtype=np.bool_)
        if occupied.ndim != 2 or occupied.size == 0:
            raise PlanningError(f"occupancy grid has shape {occupied.shape}; a planner needs a non-empty 2-D grid")
        # Everything derived from the grid alone is shared by every planner of that grid object:
        # generation, exit choice, fields and the simulation each make one, and pay for them once.
        shared = _shared_maps(grid, occupied)
        self._shared = shared
        self.occupied = shared.occupied
        self.resolution = float(grid.resolution)
        # Centre of cell (0, 0), asked of the grid so both agree on where cells are.
        self.centre_x, self.centre_y = (float(v) for v in grid.cell_to_world(0, 0))
        self.clearance = shared.clearance
        self.sight_rows, self.sight_cols = shared.sight_rows, shared.sight_cols
        self.components = shared.components
        cells = self.occupied.size
        self.guide_block = GUIDE_BLOCK if landmarks is None and cells >= GUIDE_MIN_CELLS else 0
        self.landmark_count = int(landmarks or 0)
        self._landmark_maps: np.ndarray | None = None
        self._landmark_scale = 16.0
        self._landmark_lock = threading.Lock()
        self._g_cost = np.full(cells, np.inf)
        self._parent = np.zeros(cells, dtype=np.int32)
        self._touched = np.zeros(cells, dtype=np.int32)
        self._lock = threading.Lock()

    def geodesic(self, row: int, col: int) -> tuple[np.ndarray, np.ndarray]:
        """Any-angle distances (cells, flat) from cell (row, col) to every cell and the shortest-path tree
        (flat parents, each in line of sight): one Dijkstra per cell and grid, shared by everyone who
        heads there (exit choice, the fields of every group, their paths)."""
        shared = self._shared
        with shared.lock:
            key = (int(row), int(col))
            found = shared.geodesics.get(key)
            if found is None:
                found = any_angle_distances(self.sight_rows, self.sight_cols, key[0], key[1])
                shared.geodesics[key] = found
                while len(shared.geodesics) > GEODESICS_KEPT:
                    shared.geodesics.popitem(last=False)
            shared.geodesics.move_to_end(key)
            return found

    def path_in_tree(self, start: Sequence[float], goal: Sequence[float], start_label: str = "start", goal_label: str = "goal") -> np.ndarray:
        """`plan(start, goal)` read off the goal's shortest-path tree (`geodesic`): no search of its own, so
        every agent heading to one goal costs one Dijkstra in all. The tree's corners are pulled tight."""
        sx, sy = (float(v) for v in start)
        gx, gy = (float(v) for v in goal)
        start_cell = self.snap(sx, sy, start_label, "start")
        goal_cell = self.snap(gx, gy, goal_label, "goal")
        distance, parent = self.geodesic(*goal_cell)
        width = self.occupied.shape[1]
        node = start_cell[0] * width + start_cell[1]
        if not np.isfinite(distance[node]):
            return self.plan(start, goal, start_label, goal_label)  # the same error, worded once
        corners = [self.cell_centre(*start_cell)]
        while parent[node] != node:
            node = int(parent[node])
            corners.append(self.cell_centre(node // width, node % width))
        return self._with_endpoints(start_cell, goal_cell, corners, sx, sy, gx, gy)

    @property
    def landmarks(self) -> np.ndarray:
        """(H * W, L) uint16 any-angle distances from L landmarks of the largest free region, in 1/`landmark_scale` cells."""
        with self._landmark_lock:
            if self._landmark_maps is None:
                self._landmark_maps = self._build_landmarks(self.landmark_count)
            return self._landmark_maps

    @property
    def landmark_scale(self) -> float:
        """Landmark table units per cell."""
        self.landmarks
        return self._landmark_scale

    def _build_landmarks(self, count: int) -> np.ndarray:
        labels = self.components
        if count <= 0 or labels.max() < 0:
            return np.zeros((labels.size, 0), dtype=np.uint16)
        biggest = np.bincount(labels[labels >= 0]).argmax()
        seed = int(np.flatnonzero(labels.ravel() == biggest)[0])
        width = labels.shape[1]
        sites = landmark_sites(self.sight_rows, (seed // width, seed % width), count)
        if not sites:
            return np.zeros((labels.size, 0), dtype=np.uint16)
        # Any two cells of the region are at most twice the farthest step count from the seed
        # apart, and an any-angle distance is at most sqrt(2) per step: pick the finest unit that fits.
        seed_hops = hop_distances(self.sight_rows, seed // width, seed % width)
        diameter = 2.0 * SQRT2 * float(seed_hops.max()) + 1.0
        self._landmark_scale = min(16.0, (LANDMARK_UNREACHABLE - 1) / diameter)
        table = np.empty((labels.size, len(sites)), dtype=np.uint16)

        def fill(column: int) -> None:
            site = sites[column]
            distance, _parent = any_angle_distances(self.sight_rows, self.sight_cols, site // width, site % width)
            _store_landmark(table, column, distance, self._landmark_scale)

        # The maps are independent and the kernel releases the GIL: build them on every core.
        with ThreadPoolExecutor(max_workers=max(1, min(len(sites), os.cpu_count() or 1))) as pool:
            list(pool.map(fill, range(len(sites))))
        return table

    def landmark_bound(self, cell_a: tuple[int, int], cell_b: tuple[int, int]) -> float:
        """The landmark lower bound on the distance (cells) between two free cells of the largest region; 0 without landmarks."""
        table = self.landmarks
        if table.shape[1] == 0:
            return 0.0
        width = self.occupied.shape[1]
        row_a = table[cell_a[0] * width + cell_a[1]].astype(np.int64)
        row_b = table[cell_b[0] * width + cell_b[1]].astype(np.int64)
        if row_a[0] == LANDMARK_UNREACHABLE or row_b[0] == LANDMARK_UNREACHABLE:
            return 0.0
        return max(0.0, (float(np.max(np.abs(row_a - row_b))) - 1.0) / self._landmark_scale - 0.001)

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
        landmarks = self.landmarks
        guide = self._guide(gr, gc)
        with self._lock:
            return theta_star_cells(self.sight_rows, self.sight_cols, landmarks, 1.0 / self._landmark_scale,
                                    sr, sc, gr, gc, self._g_cost, self._parent, self._touched,
                                    guide, self.guide_block, guide.shape[0] and self._block_cols,
                                    GUIDE_SLACK_BLOCKS * self.guide_block)

    def _guide(self, goal_row: int, goal_col: int) -> np.ndarray:
        """The block distances to the goal's block (empty when the planner is not guided); the last few are kept."""
        if not self.guide_block:
            return np.empty(0)
        shared = self._shared
        with shared.lock:
            if shared.block_graph is None:
                shared.block_graph = block_graph(self.occupied, self.guide_block)
            key = (goal_row // self.guide_block, goal_col // self.guide_block)
            guide = shared.guides.get(key)
            if guide is None:
                guide = block_distances(shared.block_graph, key[0], key[1], self.guide_block)
                shared.guides[key] = guide
                while len(shared.guides) > 16:
                    shared.guides.popitem(last=False)
            shared.guides.move_to_end(key)
            return guide

    @property
    def _block_cols(self) -> int:
        return (self.occupied.shape[1] + self.guide_block - 1) // self.guide_block

    def plan(self, start: Sequence[float], goal: Sequence[float], start_label: str = "start",
             goal_label: str = "goal") -> np.ndarray:
        """(K, 2) float64 world points from `start` to `goal` inclusive, every segment collision-free.

        An endpoint inside an obstacle (or on the border of one) but within one cell of free space is
        joined through the centre of the nearest free cell: that first/last short segment is the only
        one that may touch an occupied cell.
        """
        sx, sy = (float(v) for v in start)
        gx, gy = (float(v) for v in goal)
        start_cell = self.snap(sx, sy, start_label, "start")
        goal_cell = self.snap(gx, gy, goal_label, "goal")
        with self._shared.lock:
            asked = self._shared.goal_requests.get(goal_cell, 0) + 1
            self._shared.goal_requests[goal_cell] = asked
        if asked > TREE_AFTER and self.components[start_cell] == self.components[goal_cell]:
            # many people head for this goal (a counter, an exit): one shortest-path tree serves them all
            return self.path_in_tree((sx, sy), (gx, gy), start_label, goal_label)
        through_doors = self.door_graph.plan(start_cell, goal_cell) if self.door_graph is not None else None
        if through_doors is not None:
            return self._with_endpoints(start_cell, goal_cell, [tuple(p) for p in through_doors], sx, sy, gx, gy)
        cells = self.plan_cells(start_cell, goal_cell)
        if len(cells) == 0:
            raise PlanningError(
                f"no collision-free path from {start_label!r} ({sx:.2f}, {sy:.2f}) to {goal_label!r} "
                f"({gx:.2f}, {gy:.2f}): they lie in separate walkable regions of the grid "
                f"(resolution {self.resolution:g} m, inflation {getattr(self.grid, 'inflation', 0.0):.2f} m); "
                f"a wall or a narrow door blocks the way")
        corners = [self.cell_centre(int(r), int(c)) for r, c in cells]
        return self._with_endpoints(start_cell, goal_cell, corners, sx, sy, gx, gy)

    @property
    def door_graph(self) -> DoorGraph | None:
        """The world's DoorGraph on this grid (None without a world), built or loaded on first use."""
        if self.world is None or not getattr(self.world, "zones", None) or self.landmark_count:
            return None  # landmarks ask for exact Theta* paths: the door graph's are pulled tight, not exact
        shared = self._shared
        with shared.lock:
            key = (id(self.world), str(self._door_graph_dir))
            graph = shared.door_graphs.get(key)
            if graph is None:
                from grove_tui.navigation.door_graph import DoorGraph

                graph = DoorGraph(self.world, self, self._door_graph_dir)
                shared.door_graphs[key] = graph
            return graph

    def _with_endpoints(self, start_cell: tuple[int, int], goal_cell: tuple[int, int],
                        corners: list[tuple[float, float]], sx: float, sy: float, gx: float,
                        gy: float) -> np.ndarray:
        """The exact endpoints joined to a path of cell centres (`corners`, from the start's cell to the goal's)."""
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
def segment_is_free(occupied: np.ndarray, centre_x: float, centre_y: float, resolution: float, x0: float, y0: float, x1: float,
                    y1: float) -> bool:
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

    def __init__(self, max_entries: int = 4096) -> None:
        self.max_entries = max_entries
        # a planner, a path (np.ndarray) or a VelocityField, by a key whose fourth part names the kind
        self._entries: OrderedDict[CacheKey, object] = OrderedDict()
        self._lock = threading.Lock()
        self.hits = 0
        self.misses = 0

    @staticmethod
    def key(world_name: str, resolution: float, inflation: float, kind: str, *points: Sequence[float]) -> CacheKey:
        rounded = tuple(round(float(v), 2) + 0.0 for p in points for v in p)
        return (str(world_name), round(float(resolution), 6), round(float(inflation), 6), kind, rounded)

    def get(self, key: CacheKey) -> object | None:
        with self._lock:
            if key in self._entries:
                self._entries.move_to_end(key)
                self.hits += 1
                return self._entries[key]
            self.misses += 1
            return None

    def put(self, key: CacheKey, value: object) -> None:
        with self._lock:
            self._entries[key] = value
            self._entries.move_to_end(key)
            while len(self._entries) > self.max_entries:
                self._entries.popitem(last=False)

    def __len__(self) -> int:
        return len(self._entries)

    def planner(self, grid: OccupancyGrid, landmarks: int | None = None) -> ThetaStarPlanner:
        """One planner per (world, resolution, inflation): its landmark maps cost seconds on big grids."""
        key = (str(getattr(grid, "world_name", "")), round(float(grid.resolution), 6),
               round(float(getattr(grid, "inflation", 0.0)), 6), "planner", grid.occupied.shape)
        planner = self.get(key)
        if not isinstance(planner, ThetaStarPlanner) or planner.grid is not grid and not np.array_equal(planner.occupied, grid.occupied):
            planner = ThetaStarPlanner(grid, landmarks=landmarks)
            self.put(key, planner)
        return planner

    def plan(self, world_name: str, planner: ThetaStarPlanner, start: Sequence[float], goal: Sequence[float],
             start_label: str = "start", goal_label: str = "goal") -> np.ndarray:
        """`planner.plan` through the cache (errors are not cached: they are cheap to reproduce)."""
        key = self.key(world_name, planner.resolution, getattr(planner.grid, "inflation", 0.0), "path", start, goal)
        path = self.get(key)
        if not isinstance(path, np.ndarray):
            path = planner.plan(start, goal, start_label=start_label, goal_label=goal_label)
            path.setflags(write=False)
            self.put(key, path)
        return path

    def field(self, world_name: str, planner: ThetaStarPlanner, start: Sequence[float], exit_point: Sequence[float],
              start_label: str = "group", exit_label: str = "exit") -> VelocityField:
        """Velocity field from a group centroid to an exit, planned and built once per key."""
        from grove_tui.navigation.velocity_field import VelocityField, build_velocity_field

        key = self.key(world_name, planner.resolution, getattr(planner.grid, "inflation", 0.0), "field",
                       start, exit_point)
        field = self.get(key)
        if not isinstance(field, VelocityField):
            # the group's path is read off the exit's shortest-path tree, which the field is built on
            # too: one Dijkstra per exit serves the exit choice, every group's path and every field
            path = planner.path_in_tree(start, exit_point, start_label=start_label, goal_label=exit_label)
            field = build_velocity_field(planner.grid, path, exit_point, exit_label=exit_label, planner=planner)
            self.put(key, field)
        return field
