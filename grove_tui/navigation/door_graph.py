"""The door graph: a world's zones and doors on one grid, so that a plan between rooms never searches the building.

Nodes are the doors; two doors of one zone are joined by their any-angle shortest path inside that
zone (one Dijkstra per door over the zone's own cells, computed once per world and grid and cached
in the data dir, `door_graphs/`). A query from one zone to another runs Theta* only inside the start
and the goal zone, from the start to the doors of its zone and from the doors of the goal's zone to
the goal, joins the cheapest pair through the graph's door-to-door distances, and pulls the joined
polyline tight along lines of sight (so it need not pass door centres). The cheapest pair is known
before any search: every door's distance to every cell of its zones is kept with the graph, so the
two Theta* legs run only for the doors chosen.
"""

from __future__ import annotations

import hashlib
import json
import math
import threading
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import shapely

from grove_tui.files import npz_bytes, write_bytes_atomic
from grove_tui.world import World, Zone
from grove_tui.navigation.theta_star import (
    ThetaStarPlanner,
    any_angle_distances,
    clearance_map,
    path_length,
    segment_is_free,
    sight_maps,
    theta_star_cells,
)

CACHE_FOLDER = "door_graphs"
# A door-to-door leg inside one zone: (door, door) -> (the zone, its (K, 2) points).
Legs = dict[tuple[int, int], tuple[int, np.ndarray]]
CACHE_VERSION = 2
# A cell belongs to a zone when its centre lies within this many cells of the zone's polygon: the
# cells of a door opening then belong to both zones it joins.
ZONE_MARGIN_CELLS = 1.5
DOOR_SNAP_CELLS = 6  # how far (cells) a door centre may move to reach a free cell of its zone


@dataclass
class ZoneCells:
    """One zone on the grid: its bounding box in cells and the grid cropped to it, outside cells occupied."""

    name: str
    r0: int
    c0: int
    occupied: np.ndarray  # (h, w) bool
    sight_rows: np.ndarray
    sight_cols: np.ndarray
    doors: list[int]  # door indices

    def contains(self, row: int, col: int) -> bool:
        r, c = row - self.r0, col - self.c0
        return 0 <= r < self.occupied.shape[0] and 0 <= c < self.occupied.shape[1] and not self.occupied[r, c]


def _zone_cells(zone: Zone, planner: ThetaStarPlanner) -> tuple[int, int, np.ndarray]:
    """(r0, c0, occupied crop) of the cells within ZONE_MARGIN_CELLS of the zone's polygon."""
    res = planner.resolution
    margin = ZONE_MARGIN_CELLS * res
    polygon = zone.polygon.buffer(margin)
    xmin, ymin, xmax, ymax = polygon.bounds
    height, width = planner.occupied.shape
    r0, c0 = planner.cell_of(xmin, ymin)
    r1, c1 = planner.cell_of(xmax, ymax)
    r0, c0 = max(r0, 0), max(c0, 0)
    r1, c1 = min(r1 + 1, height), min(c1 + 1, width)
    if r1 <= r0 or c1 <= c0:
        return 0, 0, np.ones((1, 1), dtype=bool)
    rows, cols = np.mgrid[r0:r1, c0:c1]
    xs = planner.centre_x + cols * res
    ys = planner.centre_y + rows * res
    shapely.prepare(polygon)
    inside = shapely.contains_xy(polygon, xs, ys)
    return r0, c0, planner.occupied[r0:r1, c0:c1] | ~inside


class DoorGraph:
    """Zones and doors of `world` on `planner`'s grid (see the module docstring)."""

    def __init__(self, world: World, planner: ThetaStarPlanner, cache_dir: Path | None = None) -> None:
        self.world = world
        self.planner = planner
        self.zones: list[ZoneCells] = []
        for zone in world.zones:
            r0, c0, occupied = _zone_cells(zone, planner)
            rows, cols = sight_maps(clearance_map(occupied))
            self.zones.append(ZoneCells(zone.name, r0, c0, occupied, rows, cols, []))
        index = {z.name: k for k, z in enumerate(self.zones)}
        self.door_names: list[str] = []
        self.door_points: list[tuple[float, float]] = []
        self.door_zones: list[list[int]] = []
        for door in world.doors():
            zones = [index[n] for n in (door.zone, door.leads_to) if n in index]
            self.door_names.append(door.name)
            self.door_points.append((float(door.position[0]), float(door.position[1])))
            self.door_zones.append(zones)
            for z in zones:
                self.zones[z].doors.append(len(self.door_names) - 1)
        # each door's free cell inside each of its zones, as (zone, door) -> crop cell
        self._door_cell: dict[tuple[int, int], tuple[int, int]] = {}
        for d, zones in enumerate(self.door_zones):
            # one cell for the door in all its zones, so that legs joined at the door meet there
            cell = self._snap_in_zones(zones, *self.door_points[d])
            for z in zones:
                if cell is not None:
                    self._door_cell[(z, d)] = (cell[0] - self.zones[z].r0, cell[1] - self.zones[z].c0)
        self._buffers: dict[int, tuple[np.ndarray, np.ndarray, np.ndarray]] = {}
        # (zone, door) -> metres from the door to every cell of the zone's crop (float32, flat, inf
        # where the zone does not reach): the exact first and last legs of every plan and walk
        self.fields: dict[tuple[int, int], np.ndarray] = {}
        self._lock = threading.Lock()
        self.key = self._key()
        self.built_from_cache = False
        self.distance, self.hop, self.legs = self._load_or_build(cache_dir)

    # ------------------------------------------------------------------ construction

    def _key(self) -> str:
        grid = self.planner.grid
        digest = hashlib.sha256()
        digest.update(np.packbits(self.planner.occupied).tobytes())
        described = {"version": CACHE_VERSION, "shape": list(self.planner.occupied.shape),
                     "resolution": self.planner.resolution, "origin": [self.planner.centre_x, self.planner.centre_y],
                     "inflation": float(getattr(grid, "inflation", 0.0)),
                     "zones": [[z.name, [list(map(float, p)) for p in z.boundary]] for z in self.world.zones],
                     "doors": [[n, list(p), zs] for n, p, zs in zip(self.door_names, self.door_points, self.door_zones)]}
        digest.update(json.dumps(described, sort_keys=True).encode())
        return digest.hexdigest()[:24]

    def _snap_in_zones(self, zones: list[int], x: float, y: float) -> tuple[int, int] | None:
        """The grid cell nearest the door centre that is free in every one of its zones (None if none is near)."""
        row, col = self.planner.cell_of(x, y)
        best, best_d = None, math.inf
        for dr in range(-DOOR_SNAP_CELLS, DOOR_SNAP_CELLS + 1):
            for dc in range(-DOOR_SNAP_CELLS, DOOR_SNAP_CELLS + 1):
                if dr * dr + dc * dc < best_d and all(self.zones[z].contains(row + dr, col + dc) for z in zones):
                    best, best_d = (row + dr, col + dc), float(dr * dr + dc * dc)
        return best

    def _cache_file(self, cache_dir: Path | None) -> Path | None:
        if cache_dir is None:
            from grove_tui.settings import data_dir

            cache_dir = data_dir() / CACHE_FOLDER
        name = "".join(ch if ch.isalnum() or ch in "-_" else "_" for ch in str(getattr(self.world, "name", "world")))
        return Path(cache_dir) / f"{name}_{self.key}.npz"

    def _load_or_build(self, cache_dir: Path | None) -> tuple[np.ndarray, np.ndarray, Legs]:
        path = self._cache_file(cache_dir)
        if path is not None and path.is_file():
            try:
                with np.load(path, allow_pickle=False) as data:
                    if str(data["key"]) == self.key:
                        legs: Legs = {}
                        starts = data["leg_start"]
                        for (a, b, z), s0, s1 in zip(data["leg_ends"], starts[:-1], starts[1:]):
                            legs[(int(a), int(b))] = (int(z), np.array(data["leg_points"][s0:s1]))
                        bounds = data["field_start"]
                        values = data["field_values"]
                        for (z, d), f0, f1 in zip(data["field_keys"], bounds[:-1], bounds[1:]):
                            self.fields[(int(z), int(d))] = np.array(values[f0:f1])
                        self.built_from_cache = True
                        return np.array(data["distance"]), np.array(data["hop"]), legs
            except (OSError, KeyError, ValueError):
                pass  # a broken or foreign cache file is rebuilt and replaced
        distance, hop, legs = self._build()
        if path is not None:
            keys = sorted(self.fields)
            field_start = np.zeros(len(keys) + 1, dtype=np.int64)
            np.cumsum([self.fields[k].size for k in keys], out=field_start[1:])
            ends = sorted(legs)
            points = [legs[e][1] for e in ends]
            start = np.zeros(len(ends) + 1, dtype=np.int64)
            np.cumsum([len(p) for p in points], out=start[1:])
            try:
                path.parent.mkdir(parents=True, exist_ok=True)
                write_bytes_atomic(path, npz_bytes({
                    "key": np.array(self.key), "distance": distance, "hop": hop,
                    "leg_ends": np.array([(a, b, legs[(a, b)][0]) for a, b in ends], dtype=np.int64).reshape(-1, 3),
                    "leg_start": start,
                    "leg_points": np.concatenate(points) if points else np.zeros((0, 2)),
                    "field_keys": np.array(keys, dtype=np.int64).reshape(-1, 2), "field_start": field_start,
                    "field_values": (np.concatenate([self.fields[k] for k in keys]) if keys
                                     else np.zeros(0, dtype=np.float32)),
                }))
            except OSError:
                pass  # a read-only data dir costs the next run the build, nothing else
        return distance, hop, legs

    def _build(self) -> tuple[np.ndarray, np.ndarray, Legs]:
        """Door-to-door legs inside every zone, then all-pairs distances over the door graph."""
        n = len(self.door_names)
        edge = np.full((n, n), np.inf)
        np.fill_diagonal(edge, 0.0)
        legs: Legs = {}
        res = self.planner.resolution
        for z, zone in enumerate(self.zones):
            width = zone.occupied.shape[1]
            members = [d for d in zone.doors if (z, d) in self._door_cell]
            for a in members:
                ar, ac = self._door_cell[(z, a)]
                distance, parent = any_angle_distances(zone.sight_rows, zone.sight_cols, ar, ac)
                self.fields[(z, a)] = (distance * res).astype(np.float32)
                for b in members:
                    if b == a:
                        continue
                    br, bc = self._door_cell[(z, b)]
                    d = distance[br * width + bc] * res
                    if not np.isfinite(d) or d >= edge[a, b]:
                        continue
                    cells = [(br, bc)]
                    node = br * width + bc
                    while parent[node] != node:
                        node = parent[node]
                        cells.append((node // width, node % width))
                    cells.reverse()  # a -> b
                    points = np.array([self.planner.cell_centre(r + zone.r0, c + zone.c0) for r, c in cells])
                    edge[a, b] = d
                    legs[(a, b)] = (z, points)
        distance = edge.copy()
        hop = np.where(np.isfinite(edge), np.arange(n)[None, :], -1).astype(np.int64)
        for k in range(n):  # Floyd-Warshall: a few dozen doors
            through = distance[:, k:k + 1] + distance[k:k + 1, :]
            better = through < distance
            distance = np.where(better, through, distance)
            hop = np.where(better, hop[:, k:k + 1], hop)
        return distance, hop, legs

    # ------------------------------------------------------------------ queries

    def zones_of(self, row: int, col: int) -> list[int]:
        return [k for k, zone in enumerate(self.zones) if zone.contains(row, col)]

    def door_route(self, a: int, b: int) -> list[int]:
        """Doors from a to b along the graph's shortest route, both included ([] if none)."""
        if not np.isfinite(self.distance[a, b]):
            return []
        route = [a]
        while route[-1] != b:
            route.append(int(self.hop[route[-1], b]))
            if len(route) > len(self.door_names) + 1:
                return []
        return route

    def _leg(self, z: int, start: tuple[int, int], goal: tuple[int, int]) -> np.ndarray:
        """Theta* inside zone z between two crop cells: world points, empty if they do not connect."""
        zone = self.zones[z]
        buffers = self._buffers.get(z)
        if buffers is None:
            size = zone.occupied.size
            buffers = (np.full(size, np.inf), np.zeros(size, dtype=np.int32), np.zeros(size, dtype=np.int32))
            self._buffers[z] = buffers
        cells = theta_star_cells(zone.sight_rows, zone.sight_cols, np.zeros((zone.occupied.size, 0), dtype=np.uint16),
                                 1.0, start[0], start[1], goal[0], goal[1], *buffers, np.empty(0), 0, 0, 0.0)
        return np.array([self.planner.cell_centre(int(r) + zone.r0, int(c) + zone.c0) for r, c in cells])

    def plan(self, start_cell: tuple[int, int], goal_cell: tuple[int, int]) -> np.ndarray | None:
        """World points between the centres of two cells in different zones through the door graph, pulled
        tight; None when either cell is in no zone, both share one, or no door route joins them."""
        zs, zg = self.zones_of(*start_cell), self.zones_of(*goal_cell)
        if not zs or not zg or set(zs) & set(zg):
            return None
        with self._lock:
            return self._plan(start_cell, goal_cell, zs, zg)

    def _door_distance(self, z: int, door: int, cell: tuple[int, int]) -> float:
        """Metres from `door` to grid cell `cell` inside zone z (inf if the zone does not join them)."""
        zone = self.zones[z]
        field = self.fields.get((z, door))
        if field is None:
            return math.inf
        r, c = cell[0] - zone.r0, cell[1] - zone.c0
        return float(field[r * zone.occupied.shape[1] + c])

    def _plan(self, start_cell: tuple[int, int], goal_cell: tuple[int, int], zs: list[int],
              zg: list[int]) -> np.ndarray | None:
        ends_s = [(z, d) for z in zs for d in self.zones[z].doors if (z, d) in self.fields]
        ends_g = [(z, d) for z in zg for d in self.zones[z].doors if (z, d) in self.fields]
        best, choice = math.inf, None
        for z, a in ends_s:
            head = self._door_distance(z, a, start_cell)
            if not head < best:
                continue
            for w, b in ends_g:
                total = head + self.distance[a, b] + self._door_distance(w, b, goal_cell)
                if total < best:
                    best, choice = total, (z, a, w, b)
        if choice is None:
            return None
        z, a, w, b = choice
        zone_s, zone_g = self.zones[z], self.zones[w]
        first = self._leg(z, (start_cell[0] - zone_s.r0, start_cell[1] - zone_s.c0), self._door_cell[(z, a)])
        last = self._leg(w, self._door_cell[(w, b)], (goal_cell[0] - zone_g.r0, goal_cell[1] - zone_g.c0))
        if len(first) == 0 or len(last) == 0:
            return None
        pieces = [first]
        route = self.door_route(a, b)
        for u, v in zip(route[:-1], route[1:]):
            pieces.append(self.legs[(u, v)][1])
        pieces.append(last)
        return pull_tight(np.concatenate(pieces), self.planner)

    def walks(self, start_cells: list[tuple[int, int]], doors: list[int]) -> np.ndarray:
        """(len(doors), len(starts)) metres from each start cell to each door: the exact leg inside the
        start's zone to one of its doors, then the graph (inf where no route; starts in no zone too)."""
        walks = np.full((len(doors), len(start_cells)), np.inf)
        target = np.asarray(doors, dtype=np.int64)
        for k, cell in enumerate(start_cells):
            for z in self.zones_of(*cell):
                for a in self.zones[z].doors:
                    head = self._door_distance(z, a, cell)
                    if np.isfinite(head):
                        np.minimum(walks[:, k], head + self.distance[a, target], out=walks[:, k])
        return walks


def _cells_along(planner: ThetaStarPlanner, a: np.ndarray, b: np.ndarray) -> list[tuple[int, int]]:
    """The 4-connected chain of cells a straight segment between two cell centres passes (its supercover
    walked one axis step at a time): free wherever the segment is, each step between neighbours."""
    r0, c0 = planner.cell_of(*a)
    r1, c1 = planner.cell_of(*b)
    cells = [(r0, c0)]
    dr, dc = r1 - r0, c1 - c0
    sr, sc = (1 if dr > 0 else -1), (1 if dc > 0 else -1)
    nr, nc = abs(dr), abs(dc)
    i = j = 0
    r, c = r0, c0
    while i < nr or j < nc:
        # step along the axis whose next cell border the segment reaches first
        if j < nc and (i >= nr or (2 * j + 1) * nr < (2 * i + 1) * nc):
            c += sc
            j += 1
        else:
            r += sr
            i += 1
        cells.append((r, c))
    return cells


def pull_tight(points: np.ndarray, planner: ThetaStarPlanner, spacing_cells: int = 2) -> np.ndarray:
    """The polyline pulled tight. Candidate corners are the cell centres along it (every `spacing_cells`-th,
    and any needed to keep neighbouring candidates in sight of each other, so the chain itself stays
    free); from each kept corner the line goes to the farthest candidate in sight (walking forward
    until the view is blocked twice). Corners stay cell centres, as Theta*'s: written with two
    decimals (waypoint ports) a corner off the centres could move onto the obstacle it grazes."""
    def free(p: tuple[float, float], q: tuple[float, float]) -> bool:
        return bool(segment_is_free(planner.occupied, planner.centre_x, planner.centre_y, planner.resolution,
                                    p[0], p[1], q[0], q[1]))

    chain: list[tuple[float, float]] = [(float(points[0][0]), float(points[0][1]))]
    for a, b in zip(points[:-1], points[1:]):
        cells = _cells_along(planner, a, b)
        for k, cell in enumerate(cells[1:], start=1):
            if k % spacing_cells == 0 or k == len(cells) - 1:
                centre = planner.cell_centre(*cell)
                if not free(chain[-1], centre):
                    chain.append(planner.cell_centre(*cells[k - 1]))
                chain.append(centre)
    chain[-1] = (float(points[-1][0]), float(points[-1][1]))
    keep = [0]
    i, last = 0, len(chain) - 1
    while i < last:
        j, seen, misses = i + 1, i + 1, 0
        while j < last and misses < 2:
            j += 1
            if free(chain[i], chain[j]):
                seen, misses = j, 0
            else:
                misses += 1
        keep.append(seen)
        i = seen
    out = np.array([chain[k] for k in keep], dtype=np.float64)
    distinct = np.ones(len(out), dtype=bool)
    distinct[1:] = np.any(np.abs(np.diff(out, axis=0)) > 1e-9, axis=1)
    return out[distinct]
