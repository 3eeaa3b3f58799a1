"""Draw a world as a character map for the terminal: walls, doors, exits, entities, zone labels.

`render_world_text(world, width, height)` returns a `rich.text.Text`; `WorldCanvas` exposes the
projection so callers can overlay their own markers (agents, goals) on the same picture.
A terminal cell is about twice as tall as it is wide, so one row covers twice the metres of a column.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import shapely
from rich.table import Table
from rich.text import Text

from grove_tui.world.model import World, Zone

CHAR_ASPECT = 2.0  # terminal cell height / width

FLOOR, WALL, DOOR, EXIT, ENTITY, OBSTACLE, LABEL, MARKER = range(8)
STYLES = {
    FLOOR: "",
    WALL: "bright_white",
    DOOR: "bold green",
    EXIT: "bold red",
    ENTITY: "yellow",
    OBSTACLE: "grey50",
    LABEL: "bold cyan",
}

# Entity type -> map symbol; other types use the first letter of the type.
SYMBOLS: dict[str, str] = {
    "bed": "B", "chair": "h", "bench": "h", "sofa": "S", "table": "T", "desk": "D", "counter": "C",
    "reception_desk": "R", "vending_machine": "V", "coffee_machine": "c", "tv": "t", "kiosk": "K",
    "ticket_machine": "K", "shelf": "=", "locker": "=", "wardrobe": "=", "cabinet": "=", "sink": "s",
    "toilet": "w", "bathtub": "b", "fridge": "F", "elevator": "E", "stairs": "%", "printer": "P",
    "whiteboard": "W", "water_dispenser": "~", "server_rack": "#", "exam_table": "X", "xray_machine": "X",
    "ct_scanner": "X", "cart": "+", "coat_rack": "y", "wheelchair_station": "@",
}
OBSTACLE_SYMBOL = "▪"

# Wall glyph from which of the four neighbours are walls: (up, down, left, right).
BOX = {
    (0, 0, 1, 1): "─", (0, 0, 1, 0): "─", (0, 0, 0, 1): "─", (1, 1, 0, 0): "│", (1, 0, 0, 0): "│",
    (0, 1, 0, 0): "│", (0, 1, 0, 1): "┌", (0, 1, 1, 0): "┐", (1, 0, 0, 1): "└", (1, 0, 1, 0): "┘",
    (1, 1, 0, 1): "├", (1, 1, 1, 0): "┤", (0, 1, 1, 1): "┬", (1, 0, 1, 1): "┴", (1, 1, 1, 1): "┼",
    (0, 0, 0, 0): "▫",
}


def symbol_for(entity_type: str) -> str:
    return SYMBOLS.get(entity_type, entity_type[:1].upper() or "?")


@dataclass(frozen=True)
class MapProjection:
    """World metres <-> character cells; row 0 is the top (largest y)."""

    xmin: float
    ymax: float
    cell_width: float   # metres per column
    cell_height: float  # metres per row
    columns: int
    rows: int

    def to_cell(self, x: float, y: float) -> tuple[int, int]:
        return (int(math.floor((self.ymax - y) / self.cell_height)), int(math.floor((x - self.xmin) / self.cell_width)))

    def to_world(self, row: int, col: int) -> tuple[float, float]:
        return (self.xmin + (col + 0.5) * self.cell_width, self.ymax - (row + 0.5) * self.cell_height)

    def contains(self, row: int, col: int) -> bool:
        return 0 <= row < self.rows and 0 <= col < self.columns


def fit_projection(bounds: tuple[float, float, float, float], width: int, height: int | None = None) -> MapProjection:
    """The largest scale at which the bounds fit in width columns (and height rows, if given)."""
    xmin, ymin, xmax, ymax = bounds
    width = max(int(width), 8)
    # One cell of margin keeps the outer walls off the frame edge.
    span_x = (xmax - xmin) * (width / max(width - 2, 1))
    metres_per_column = span_x / width
    if height is not None:
        height = max(int(height), 4)
        metres_per_column = max(metres_per_column, (ymax - ymin) / max(height - 2, 1) / CHAR_ASPECT)
    cell_height = metres_per_column * CHAR_ASPECT
    columns = min(width, int(math.ceil((xmax - xmin) / metres_per_column)) + 2)
    rows = int(math.ceil((ymax - ymin) / cell_height)) + 2
    if height is not None:
        rows = min(rows, height)
    return MapProjection(xmin - metres_per_column, ymax + cell_height, metres_per_column, cell_height, columns, rows)


def _sample_segment(x1: float, y1: float, x2: float, y2: float, step: float) -> np.ndarray:
    count = max(int(math.ceil(math.hypot(x2 - x1, y2 - y1) / step)), 1)
    t = np.linspace(0.0, 1.0, count + 1)
    return np.column_stack((x1 + t * (x2 - x1), y1 + t * (y2 - y1)))


class WorldCanvas:
    """The static map of a world at one size; `render(markers)` draws it with optional overlays."""

    def __init__(self, world: World, width: int, height: int | None = None) -> None:
        self.world = world
        self.projection = fit_projection(world.bounds(), width, height)
        rows, columns = self.projection.rows, self.projection.columns
        self.chars = np.full((rows, columns), " ", dtype="<U1")
        self.kinds = np.full((rows, columns), FLOOR, dtype=np.int8)
        self._draw_entities()
        self._draw_walls()
        self._draw_doors()
        self._restore_hidden_entities()
        self._draw_labels()

    # --- layers ------------------------------------------------------------------------------

    def _cells_covered(self, polygon: shapely.Geometry) -> tuple[np.ndarray, np.ndarray]:
        p = self.projection
        xmin, ymin, xmax, ymax = polygon.bounds
        r0, c0 = p.to_cell(xmin, ymax)
        r1, c1 = p.to_cell(xmax, ymin)
        r0, c0 = max(r0, 0), max(c0, 0)
        r1, c1 = min(r1, p.rows - 1), min(c1, p.columns - 1)
        if r0 > r1 or c0 > c1:
            return np.zeros(0, dtype=int), np.zeros(0, dtype=int)
        rr, cc = np.mgrid[r0:r1 + 1, c0:c1 + 1]
        xs = p.xmin + (cc + 0.5) * p.cell_width
        ys = p.ymax - (rr + 0.5) * p.cell_height
        inside = shapely.contains_xy(polygon, xs, ys)
        if not inside.any():
            # Smaller than a cell: still show it, in the cell holding its centre.
            centre = polygon.centroid
            row, col = p.to_cell(centre.x, centre.y)
            if p.contains(row, col):
                return np.array([row]), np.array([col])
        return rr[inside], cc[inside]

    def _draw_entities(self) -> None:
        for entity in self.world.entities():
            rows, cols = self._cells_covered(entity.polygon)
            self.chars[rows, cols] = symbol_for(entity.type)
            self.kinds[rows, cols] = ENTITY
        for obstacle in self.world.obstacles:
            rows, cols = self._cells_covered(obstacle.polygon)
            self.chars[rows, cols] = OBSTACLE_SYMBOL
            self.kinds[rows, cols] = OBSTACLE

    def _restore_hidden_entities(self) -> None:
        """Entities thinner than a cell against a wall vanish under it; show them just in front."""
        p = self.projection
        for entity in self.world.entities():
            rows, cols = self._cells_covered(entity.polygon)
            if len(rows) and (self.kinds[rows, cols] == ENTITY).any():
                continue
            centre = entity.polygon.centroid
            for x, y in _sample_segment(centre.x, centre.y, *entity.interaction_point, min(p.cell_width, p.cell_height) / 3):
                row, col = p.to_cell(x, y)
                if p.contains(row, col) and self.kinds[row, col] == FLOOR:
                    self.chars[row, col] = symbol_for(entity.type)
                    self.kinds[row, col] = ENTITY
                    break

    def _mark_segments(self, segments: Iterable[tuple[float, float, float, float]]) -> np.ndarray:
        p = self.projection
        mask = np.zeros((p.rows, p.columns), dtype=bool)
        step = min(p.cell_width, p.cell_height) / 3.0
        for x1, y1, x2, y2 in segments:
            points = _sample_segment(x1, y1, x2, y2, step)
            rows = np.floor((p.ymax - points[:, 1]) / p.cell_height).astype(int)
            cols = np.floor((points[:, 0] - p.xmin) / p.cell_width).astype(int)
            keep = (rows >= 0) & (rows < p.rows) & (cols >= 0) & (cols < p.columns)
            mask[rows[keep], cols[keep]] = True
        return mask

    def _draw_walls(self) -> None:
        walls = self._mark_segments(self.world.room_walls())
        padded = np.pad(walls, 1)
        up, down = padded[:-2, 1:-1], padded[2:, 1:-1]
        left, right = padded[1:-1, :-2], padded[1:-1, 2:]
        for row, col in zip(*np.nonzero(walls)):
            key = (int(up[row, col]), int(down[row, col]), int(left[row, col]), int(right[row, col]))
            self.chars[row, col] = BOX[key]
            self.kinds[row, col] = WALL

    def _draw_doors(self) -> None:
        for door in self.world.doors():
            (x1, y1), (x2, y2) = door.opening
            mask = self._mark_segments([(x1, y1, x2, y2)])
            horizontal = abs(door.along[0]) >= abs(door.along[1])
            if door.exit:
                glyph = "━" if horizontal else "┃"
            else:
                glyph = "╌" if horizontal else "┆"
            self.chars[mask] = glyph
            self.kinds[mask] = EXIT if door.exit else DOOR

    def _draw_labels(self) -> None:
        p = self.projection
        for zone in self.world.zones:
            label = zone.name
            anchor_row, anchor_col = p.to_cell(*zone.anchor)
            best: tuple[int, int, int] | None = None  # (length, row, start)
            for offset in (0, -1, 1, -2, 2):
                row = anchor_row + offset
                if not 0 <= row < p.rows:
                    continue
                start, stop = self._free_run(zone, row, anchor_col)
                length = stop - start
                if best is None or length > best[0]:
                    best = (length, row, start)
                if length >= len(label):
                    break
            if best is None or best[0] < 3:
                continue
            length, row, start = best
            text = label if len(label) <= length else label[: max(length - 1, 1)] + "…"
            centre = min(max(anchor_col - len(text) // 2, start), start + length - len(text))
            for offset, character in enumerate(text):
                self.chars[row, centre + offset] = character
                self.kinds[row, centre + offset] = LABEL

    def _free_run(self, zone: Zone, row: int, col: int) -> tuple[int, int]:
        """Columns [start, stop) of empty floor inside the zone on this row, around col."""
        p = self.projection
        polygon = zone.polygon

        def usable(c: int) -> bool:
            if not 0 <= c < p.columns or self.kinds[row, c] != FLOOR:
                return False
            x, y = p.to_world(row, c)
            return bool(shapely.contains_xy(polygon, x, y))

        if not usable(col):
            candidates = [c for c in range(max(col - 6, 0), min(col + 7, p.columns)) if usable(c)]
            if not candidates:
                return (col, col)
            col = min(candidates, key=lambda c: abs(c - col))
        start = col
        while usable(start - 1):
            start -= 1
        stop = col + 1
        while usable(stop):
            stop += 1
        return (start, stop)

    # --- output ------------------------------------------------------------------------------

    def render(self, markers: Iterable[tuple[float, float, str, str]] = ()) -> Text:
        """The map as rich Text; markers are (x, y, one character, rich style) drawn on top."""
        chars = self.chars.copy()
        styles: dict[tuple[int, int], str] = {}
        for x, y, character, style in markers:
            row, col = self.projection.to_cell(x, y)
            if self.projection.contains(row, col):
                chars[row, col] = character[:1]
                styles[(row, col)] = style
        text = Text(no_wrap=True, overflow="crop")
        for row in range(self.projection.rows):
            line = chars[row]
            kinds = self.kinds[row]
            start = 0
            while start < len(line):
                stop = start + 1
                key = styles.get((row, start))
                while (stop < len(line) and kinds[stop] == kinds[start] and styles.get((row, stop)) == key):
                    stop += 1
                text.append("".join(line[start:stop]), style=key or STYLES.get(int(kinds[start]), ""))
                start = stop
            if row < self.projection.rows - 1:
                text.append("\n")
        return text


@lru_cache(maxsize=16)
def _canvas(world: World, width: int, height: int | None) -> WorldCanvas:
    return WorldCanvas(world, width, height)


def render_world_text(world: World, width: int, height: int | None = None,
                      markers: Iterable[tuple[float, float, str, str]] = ()) -> Text:
    """The world drawn in at most `width` columns (and `height` rows if given)."""
    return _canvas(world, int(width), None if height is None else int(height)).render(markers)


def legend(world: World) -> Table:
    """Symbols used on the map of this world, with the entity types they stand for."""
    table = Table(box=None, show_header=False, padding=(0, 1), pad_edge=False)
    types = sorted({entity.type for entity in world.entities()})
    cells: list[Text] = [Text.assemble(("╌┆", STYLES[DOOR]), " door"), Text.assemble(("━┃", STYLES[EXIT]), " exit")]
    if world.obstacles:
        cells.append(Text.assemble((OBSTACLE_SYMBOL, STYLES[OBSTACLE]), " obstacle"))
    for entity_type in types:
        cells.append(Text.assemble((symbol_for(entity_type), STYLES[ENTITY]), " " + entity_type.replace("_", " ")))
    per_row = 4
    for _ in range(per_row):
        table.add_column()
    for start in range(0, len(cells), per_row):
        row = cells[start:start + per_row]
        table.add_row(*(row + [Text("")] * (per_row - len(row))))
    return table
