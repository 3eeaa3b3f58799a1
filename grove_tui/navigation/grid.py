"""Occupancy grid of a world: what the global planner and spawner treat as free floor.

A cell is occupied when its centre is outside every zone, inside an entity or obstacle
footprint, or within `inflation` metres (the agent radius) of a wall segment. Distances to
segments are exact, so the grid does not depend on how finely walls were rasterised.
"""

from __future__ import annotations

import math
import os
from collections import OrderedDict
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import shapely
from scipy import ndimage

from grove_tui.files import npz_bytes, write_bytes_atomic
from grove_tui.errors import GridError
from grove_tui.limits import NPZ_READ_ERRORS, InputLimitError, check_npz
from grove_tui.world import World
from grove_tui.limits import MAX_PADDED_COORDINATE as MAX_COORDINATE


# The largest grid built or read: 100 million cells (a 250,000 m^2 world at 0.05 m). The planner's
# maps take about 10 bytes per cell, so this bounds a run's memory at about 1 GB.
MAX_GRID_CELLS = 100_000_000
# A saved grid packs 8 cells per byte; the file and its unpacked arrays stay far below this.
MAX_GRID_FILE_BYTES = 64 * 1024 * 1024
MIN_RESOLUTION = 0.01
MAX_RESOLUTION = 2.0


def check_grid_shape(shape: tuple[int, int], what: str = "") -> None:
    """Refuse a grid shape that is empty or over MAX_GRID_CELLS, before anything is allocated."""
    height, width = shape
    if height <= 0 or width <= 0:
        raise ValueError(f"grid shape {height} x {width} is empty")
    if height * width > MAX_GRID_CELLS:
        raise ValueError(f"a grid of {height:,} x {width:,} cells{what} is over the limit of {MAX_GRID_CELLS:,} cells")


@dataclass(eq=False)
class OccupancyGrid:
    origin: tuple[float, float]          # world coordinates of the lower-left corner of cell (0, 0)
    resolution: float                    # cell side in metres
    occupied: np.ndarray                 # bool (H, W); row = y, col = x
    inflation: float                     # radius the free space was shrunk by
    world_name: str = ""
    _nearest: tuple[np.ndarray, np.ndarray] | None = field(default=None, repr=False)
    # The World build_grid rasterised (None for a grid read from a file): planners of the grid use its
    # zones and doors (navigation/door_graph.py). Not saved.
    world: World | None = field(default=None, repr=False)

    @property
    def shape(self) -> tuple[int, int]:
        rows, cols = self.occupied.shape
        return rows, cols

    @property
    def height(self) -> int:
        return int(self.occupied.shape[0])

    @property
    def width(self) -> int:
        return int(self.occupied.shape[1])

    def extent(self) -> tuple[float, float, float, float]:
        """xmin, ymin, xmax, ymax covered by the grid."""
        x0, y0 = self.origin
        return (x0, y0, x0 + self.width * self.resolution, y0 + self.height * self.resolution)

    def world_to_cell(self, x: float, y: float) -> tuple[int, int]:
        """(row, col) of the cell containing the point; may lie outside the grid."""
        return (int(math.floor((y - self.origin[1]) / self.resolution)),
                int(math.floor((x - self.origin[0]) / self.resolution)))

    def cell_to_world(self, row: int, col: int) -> tuple[float, float]:
        """Centre of the cell."""
        return (self.origin[0] + (col + 0.5) * self.resolution, self.origin[1] + (row + 0.5) * self.resolution)

    def in_grid(self, row: int, col: int) -> bool:
        return 0 <= row < self.height and 0 <= col < self.width

    def is_free(self, x: float, y: float) -> bool:
        row, col = self.world_to_cell(x, y)
        return self.in_grid(row, col) and not bool(self.occupied[row, col])

    def free_cells(self) -> np.ndarray:
        """(K, 2) int array of (row, col) of every free cell."""
        return np.argwhere(~self.occupied)

    def nearest_free(self, x: float, y: float, max_dist: float | None = None) -> tuple[float, float] | None:
        """(x, y) itself when free, else the centre of the nearest free cell; None if none within max_dist."""
        if self.is_free(x, y):
            return (float(x), float(y))
        row, col = self.world_to_cell(x, y)
        if self.in_grid(row, col):
            rows, cols = self._nearest_free_index()
            free_row, free_col = int(rows[row, col]), int(cols[row, col])
            if self.occupied[free_row, free_col]:
                return None
            best = self.cell_to_world(free_row, free_col)
        else:
            free = self.free_cells()
            if len(free) == 0:
                return None
            centres_x = self.origin[0] + (free[:, 1] + 0.5) * self.resolution
            centres_y = self.origin[1] + (free[:, 0] + 0.5) * self.resolution
            index = int(np.argmin((centres_x - x) ** 2 + (centres_y - y) ** 2))
            best = (float(centres_x[index]), float(centres_y[index]))
        if max_dist is not None and math.dist(best, (x, y)) > max_dist:
            return None
        return best

    def _nearest_free_index(self) -> tuple[np.ndarray, np.ndarray]:
        if self._nearest is None:
            # EDT of the occupied mask: for every cell, the indices of the closest free cell.
            indices = ndimage.distance_transform_edt(self.occupied, return_distances=False, return_indices=True)
            self._nearest = (indices[0].astype(np.int32), indices[1].astype(np.int32))
        return self._nearest

    def save(self, path: str | os.PathLike[str]) -> Path:
        arrays: dict[str, np.ndarray | np.generic] = {
            "origin": np.asarray(self.origin, dtype=np.float64),
            "resolution": np.float64(self.resolution),
            "inflation": np.float64(self.inflation),
            "occupied": np.packbits(self.occupied, axis=None),
            "shape": np.asarray(self.occupied.shape),
            "world_name": np.str_(self.world_name),
        }
        return write_bytes_atomic(path, npz_bytes(arrays))

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> OccupancyGrid:
        """Read a grid saved by `save`; every field is checked before the cells are unpacked."""
        try:
            check_npz(path, MAX_GRID_FILE_BYTES, MAX_GRID_FILE_BYTES, "occupancy grid")
        except InputLimitError as error:
            raise GridError(str(error)) from None
        try:
            with np.load(Path(path), allow_pickle=False) as data:
                shape_values = np.asarray(data["shape"])
                if shape_values.shape != (2,) or shape_values.dtype.kind not in "iu":
                    raise ValueError(f"shape must be two integers, got {shape_values.tolist()!r}")
                shape = (int(shape_values[0]), int(shape_values[1]))
                check_grid_shape(shape)
                origin = np.asarray(data["origin"], dtype=np.float64).reshape(-1)
                resolution = float(data["resolution"])
                inflation = float(data["inflation"])
                if origin.shape != (2,) or not np.isfinite(origin).all() or np.abs(origin).max() > MAX_COORDINATE:
                    raise ValueError(f"origin must be two finite numbers within +-{MAX_COORDINATE:g} m, "
                                     f"got {origin.tolist()!r}")
                if not (MIN_RESOLUTION <= resolution <= MAX_RESOLUTION):
                    raise ValueError(f"resolution must be {MIN_RESOLUTION}..{MAX_RESOLUTION} m, got {resolution!r}")
                if not (0.0 <= inflation <= MAX_RESOLUTION * 10):
                    raise ValueError(f"inflation must be 0..{MAX_RESOLUTION * 10} m, got {inflation!r}")
                packed = np.asarray(data["occupied"], dtype=np.uint8)
                if packed.size * 8 < shape[0] * shape[1]:
                    raise ValueError(f"{packed.size * 8} cells stored for a {shape[0]} x {shape[1]} grid")
                bits = np.unpackbits(packed, count=shape[0] * shape[1])
                occupied = bits.reshape(shape).astype(bool)
                return cls(origin=(float(origin[0]), float(origin[1])), resolution=resolution, occupied=occupied,
                           inflation=inflation, world_name=str(data["world_name"]))
        except NPZ_READ_ERRORS as error:
            raise GridError(f"cannot read occupancy grid {path}: {error}") from None


def _mark_polygon(mask: np.ndarray, polygon: shapely.Geometry, origin: tuple[float, float],
                  resolution: float, value: bool) -> None:
    """Set mask cells whose centre is covered by the polygon (only the polygon's bounding box is tested)."""
    xmin, ymin, xmax, ymax = polygon.bounds
    height, width = mask.shape
    c0 = max(int(math.floor((xmin - origin[0]) / resolution)), 0)
    c1 = min(int(math.ceil((xmax - origin[0]) / resolution)), width)
    r0 = max(int(math.floor((ymin - origin[1]) / resolution)), 0)
    r1 = min(int(math.ceil((ymax - origin[1]) / resolution)), height)
    if c0 >= c1 or r0 >= r1:
        return
    xs = origin[0] + (np.arange(c0, c1) + 0.5) * resolution
    ys = origin[1] + (np.arange(r0, r1) + 0.5) * resolution
    grid_x, grid_y = np.meshgrid(xs, ys)
    shapely.prepare(polygon)
    inside = shapely.contains_xy(polygon, grid_x, grid_y)
    mask[r0:r1, c0:c1][inside] = value


def _mark_near_segments(mask: np.ndarray, segments: np.ndarray, origin: tuple[float, float],
                        resolution: float, radius: float) -> None:
    """Set cells whose centre lies within `radius` of any segment (exact point-segment distance)."""
    height, width = mask.shape
    radius_sq = radius * radius
    for x1, y1, x2, y2 in segments:
        c0 = max(int(math.floor((min(x1, x2) - radius - origin[0]) / resolution)), 0)
        c1 = min(int(math.ceil((max(x1, x2) + radius - origin[0]) / resolution)) + 1, width)
        r0 = max(int(math.floor((min(y1, y2) - radius - origin[1]) / resolution)), 0)
        r1 = min(int(math.ceil((max(y1, y2) + radius - origin[1]) / resolution)) + 1, height)
        if c0 >= c1 or r0 >= r1:
            continue
        px = (origin[0] + (np.arange(c0, c1) + 0.5) * resolution)[None, :] - x1
        py = (origin[1] + (np.arange(r0, r1) + 0.5) * resolution)[:, None] - y1
        dx, dy = x2 - x1, y2 - y1
        length_sq = dx * dx + dy * dy
        t = np.clip((px * dx + py * dy) / length_sq, 0.0, 1.0) if length_sq > 0 else np.zeros((1, 1))
        distance_sq = (px - t * dx) ** 2 + (py - t * dy) ** 2
        mask[r0:r1, c0:c1] |= distance_sq <= radius_sq


def _rasterize(world: World, resolution: float, inflation: float) -> OccupancyGrid:
    xmin, ymin, xmax, ymax = world.bounds()
    # A border of occupied cells around the world so every wall has both sides in the grid.
    pad = 2 * resolution
    origin = (xmin - pad, ymin - pad)
    width = int(math.ceil((xmax - xmin + 2 * pad) / resolution))
    height = int(math.ceil((ymax - ymin + 2 * pad) / resolution))
    try:
        check_grid_shape((height, width), f" at {resolution} m")
    except ValueError as error:
        raise GridError(f"world {world.name!r}: {error}; use a coarser resolution") from None
    inside = np.zeros((height, width), dtype=bool)
    for zone in world.zones:
        _mark_polygon(inside, zone.polygon, origin, resolution, True)
    occupied = ~inside
    for entity in world.entities():
        _mark_polygon(occupied, entity.polygon, origin, resolution, True)
    for obstacle in world.obstacles:
        _mark_polygon(occupied, obstacle.polygon, origin, resolution, True)
    # Never thinner than half a cell diagonal: the marked cells then form a 4-connected chain
    # along every wall, so 8-connected planners cannot slip diagonally through it.
    radius = max(inflation, resolution * math.sqrt(0.5))
    _mark_near_segments(occupied, world.walls(), origin, resolution, radius)
    occupied.flags.writeable = False
    return OccupancyGrid(origin=origin, resolution=resolution, occupied=occupied, inflation=inflation,
                         world_name=world.name, world=world)


_GRIDS: OrderedDict[tuple[str, float, float], OccupancyGrid] = OrderedDict()
_GRID_CACHE_SIZE = 12


def with_blocked(grid: OccupancyGrid, shapes: Sequence[shapely.Geometry]) -> OccupancyGrid:
    """A copy of the grid with the cells under `shapes` occupied (places a group must keep out of). The
    copy has no world: its planners search the grid itself, not the world's door graph, which would lead
    through the blocked places."""
    occupied = np.array(grid.occupied, dtype=bool, copy=True)
    for shape in shapes:
        _mark_polygon(occupied, shape, grid.origin, grid.resolution, True)
    return OccupancyGrid(grid.origin, grid.resolution, occupied, grid.inflation, grid.world_name)


def build_grid(world: World, resolution: float = 0.1, inflation: float = 0.35) -> OccupancyGrid:
    """Rasterise the world; grids are cached in memory per (world content, resolution, inflation).

    The returned grid's `occupied` array is read-only because cached grids are shared.
    """
    if not (MIN_RESOLUTION <= resolution <= MAX_RESOLUTION):
        raise GridError(f"grid resolution must be {MIN_RESOLUTION}..{MAX_RESOLUTION} m, got {resolution}")
    if not (0 <= inflation <= MAX_RESOLUTION * 10):
        raise GridError(f"grid inflation must be 0..{MAX_RESOLUTION * 10} m, got {inflation}")
    key = (world.fingerprint, round(float(resolution), 9), round(float(inflation), 9))
    grid = _GRIDS.get(key)
    if grid is None:
        grid = _rasterize(world, float(resolution), float(inflation))
        _GRIDS[key] = grid
        if len(_GRIDS) > _GRID_CACHE_SIZE:
            _GRIDS.popitem(last=False)
    else:
        _GRIDS.move_to_end(key)
    return grid
