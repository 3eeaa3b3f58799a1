"""Rasterise a world, its scenario overlays and a crowd frame into terminal cells.

Pure numpy (no textual) so the map widget, the simulation view and the fps benchmark share it.
Every cell holds one character code and one style index; walls, paths and agents are drawn with
braille dots (2 x 4 per cell), which gives square dots because a terminal cell is about twice as
tall as it is wide.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from grove_tui.tui.widgets.map_styles import (  # noqa: F401  (re-exported for callers)
    DOOR,
    ENTITY,
    FIELD,
    FLOOR,
    GOAL,
    GROUP_BASE,
    GROUP_COLOURS,
    HIGHLIGHT,
    ROBOT,
    ROBOT_PATH,
    SELECTED,
    SPAWN,
    STYLE_COUNT,
    WALL,
    WAYPOINT,
    ZONE_LABEL,
)

if TYPE_CHECKING:
    from grove_tui.services.domain import VelocityField, World, Zone

BRAILLE_BASE = 0x2800
# Braille dot bit for dot column c (0..1) and dot row r (0..3) inside one cell.
BRAILLE_BITS = np.array([[0x01, 0x08], [0x02, 0x10], [0x04, 0x20], [0x40, 0x80]], dtype=np.uint8)
ARROWS = "→↗↑↖←↙↓↘"
SPACE = ord(" ")
MARGIN_M = 0.5


@dataclass(frozen=True)
class Overlay:
    """What the inspect and simulation screens draw on the static map."""

    spawns: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    goals: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    waypoints: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    robot_path: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    highlight_path: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    highlight_points: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    fields: tuple[VelocityField, ...] = ()  # origin, resolution, vectors (H, W, 2)


class MapRaster:
    """A world drawn at `cols_per_metre` (rows per metre is half of it)."""

    def __init__(self, world: World, cols_per_metre: float) -> None:
        self.world = world
        self.cols_per_metre = cols_per_metre
        self.dots_per_metre = 2.0 * cols_per_metre
        xmin, ymin, xmax, ymax = world.bounds()
        self.x0 = xmin - MARGIN_M
        self.y1 = ymax + MARGIN_M
        self.width = max(1, math.ceil((xmax - xmin + 2 * MARGIN_M) * self.dots_per_metre / 2))
        self.height = max(1, math.ceil((ymax - ymin + 2 * MARGIN_M) * self.dots_per_metre / 4))
        # Walls, entities and doors; zone labels go on last, into the cells the overlays leave empty.
        self._plain_chars, self._plain_styles = self._draw_world()
        self.base_chars, self.base_styles = self._plain_chars.copy(), self._plain_styles.copy()
        self.labels_abbreviated = False  # whether the last labels painted shortened a name (the legend says how)
        self._paint_labels(self.base_chars, self.base_styles)

    @staticmethod
    def fit_scale(world: World, cols: int, rows: int) -> float:
        """Columns per metre so the whole world fits `cols` x `rows` cells."""
        xmin, ymin, xmax, ymax = world.bounds()
        span_x = xmax - xmin + 2 * MARGIN_M
        span_y = ymax - ymin + 2 * MARGIN_M
        return max(0.05, min(cols / span_x, 2.0 * rows / span_y))

    # coordinates -------------------------------------------------------------------------------------
    def to_dots(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        points = np.asarray(points, dtype=np.float64).reshape(-1, 2)
        dx = np.floor((points[:, 0] - self.x0) * self.dots_per_metre).astype(np.int64)
        dy = np.floor((self.y1 - points[:, 1]) * self.dots_per_metre).astype(np.int64)
        return dx, dy

    def to_cells(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        dx, dy = self.to_dots(points)
        return dy // 4, dx // 2

    def cell_centre(self, row: int, col: int) -> tuple[float, float]:
        return (self.x0 + (col + 0.5) * 2 / self.dots_per_metre, self.y1 - (row + 0.5) * 4 / self.dots_per_metre)

    # drawing primitives ---------------------------------------------------------------------------------
    def _segment_dots(self, segments: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Dots along segments (M, 4), sampled at half a dot so lines have no gaps."""
        if len(segments) == 0:
            return np.zeros(0, np.int64), np.zeros(0, np.int64)
        segments = np.asarray(segments, dtype=np.float64)
        lengths = np.hypot(segments[:, 2] - segments[:, 0], segments[:, 3] - segments[:, 1])
        counts = np.maximum(2, np.ceil(lengths * self.dots_per_metre * 2).astype(np.int64) + 1)
        owner = np.repeat(np.arange(len(segments)), counts)
        starts = np.cumsum(counts) - counts
        fraction = (np.arange(counts.sum()) - np.repeat(starts, counts)) / np.repeat(counts - 1, counts)
        seg = segments[owner]
        xs = seg[:, 0] + (seg[:, 2] - seg[:, 0]) * fraction
        ys = seg[:, 1] + (seg[:, 3] - seg[:, 1]) * fraction
        return self.to_dots(np.column_stack([xs, ys]))

    def _paint_dots(self, chars: np.ndarray, styles: np.ndarray, dx: np.ndarray, dy: np.ndarray, style: int) -> None:
        keep = (dx >= 0) & (dy >= 0) & (dx < self.width * 2) & (dy < self.height * 4)
        dx, dy = dx[keep], dy[keep]
        if len(dx) == 0:
            return
        rows, cols = dy // 4, dx // 2
        bits = np.zeros((self.height, self.width), dtype=np.uint8)
        np.bitwise_or.at(bits, (rows, cols), BRAILLE_BITS[dy % 4, dx % 2])
        hit = bits > 0
        existing = chars[hit]
        was_braille = (existing >= BRAILLE_BASE) & (existing < BRAILLE_BASE + 256)
        merged = bits[hit].astype(np.uint32) | np.where(was_braille, existing - BRAILLE_BASE, 0).astype(np.uint32)
        chars[hit] = BRAILLE_BASE + merged
        styles[hit] = style

    def _paint_glyphs(self, chars: np.ndarray, styles: np.ndarray, points: np.ndarray, glyph: str, style: int) -> None:
        if len(points) == 0:
            return
        rows, cols = self.to_cells(points)
        keep = (rows >= 0) & (cols >= 0) & (rows < self.height) & (cols < self.width)
        chars[rows[keep], cols[keep]] = ord(glyph)
        styles[rows[keep], cols[keep]] = style

    def _paint_label(self, chars: np.ndarray, styles: np.ndarray, row: int, col: int, name: str, style: int) -> bool:
        """Write a zone's name centred on (row, col) in a run of empty cells, trying nearby rows; where
        the whole name does not fit, its words are shortened by `abbreviate` (the legend says how).
        Returns whether the name was shortened."""
        full = label_words(name)
        limit = max(MIN_LABEL_ROOM, self.width // 3)  # a label never takes more than a third of the map's width
        best: tuple[int, int, int] | None = None
        for candidate in (row, row - 1, row + 1, row - 2, row + 2):
            if not (0 <= candidate < self.height and 0 <= col < self.width) or chars[candidate, col] != SPACE:
                continue
            start, end = col, col + 1
            while start > 0 and chars[candidate, start - 1] == SPACE:
                start -= 1
            while end < self.width and chars[candidate, end] == SPACE:
                end += 1
            # keep one blank on each side so the label does not touch a wall
            start, end = start + 1, end - 1
            if end - start >= MIN_LABEL_CELLS and (best is None or end - start > best[2] - best[1]):
                best = (candidate, start, end)
                if end - start >= min(len(full), limit):
                    break
        if best is None:
            return False
        candidate, start, end = best
        label = abbreviate(name, min(end - start, limit))
        if not label:
            return False
        left = min(max(start, col - len(label) // 2), end - len(label))
        for offset, char in enumerate(label):
            chars[candidate, left + offset] = ord(char)
            styles[candidate, left + offset] = style
        return label != full

    @staticmethod
    def _polygon_segments(points: npt.ArrayLike) -> np.ndarray:
        ring = np.asarray(points, dtype=np.float64).reshape(-1, 2)
        if len(ring) < 2:
            return np.zeros((0, 4))
        return np.column_stack([ring, np.roll(ring, -1, axis=0)])

    # layers ---------------------------------------------------------------------------------------------
    def _draw_world(self) -> tuple[np.ndarray, np.ndarray]:
        chars = np.full((self.height, self.width), SPACE, dtype=np.uint32)
        styles = np.zeros((self.height, self.width), dtype=np.uint8)
        world = self.world
        self._paint_dots(chars, styles, *self._segment_dots(world.walls()), WALL)
        for entity in world.entities():
            self._paint_dots(chars, styles, *self._segment_dots(self._polygon_segments(entity.footprint)), ENTITY)
        for door in world.doors():
            self._paint_glyphs(chars, styles, np.asarray([door.position], dtype=np.float64), "▒", DOOR)
        return chars, styles

    def _paint_labels(self, chars: np.ndarray, styles: np.ndarray) -> None:
        """Zone names into empty cells near each zone's centre: markers move a label, never cut it, and
        a name with no room for all of it is shortened by `abbreviate` (`labels_abbreviated` says so)."""
        shortened = False
        for zone in self.world.zones:
            cx, cy = _centroid_xy(zone)
            rows, cols = self.to_cells(np.array([[cx, cy]]))
            shortened |= self._paint_label(chars, styles, int(rows[0]), int(cols[0]), zone.name, ZONE_LABEL)
        self.labels_abbreviated = shortened

    def compose(self, overlay: Overlay | None) -> tuple[np.ndarray, np.ndarray]:
        """The static map with scenario overlays; what the simulation draws agents on."""
        if overlay is None:
            return self.base_chars.copy(), self.base_styles.copy()
        chars = self._plain_chars.copy()
        styles = self._plain_styles.copy()
        if len(overlay.robot_path) > 1:
            path = np.asarray(overlay.robot_path, dtype=np.float64)
            self._paint_dots(chars, styles, *self._segment_dots(np.column_stack([path[:-1], path[1:]])), ROBOT_PATH)
        if len(overlay.highlight_path) > 1:
            path = np.asarray(overlay.highlight_path, dtype=np.float64)
            self._paint_dots(chars, styles, *self._segment_dots(np.column_stack([path[:-1], path[1:]])), HIGHLIGHT)
        # markers go over the paths so a route never hides its own goals
        self._paint_glyphs(chars, styles, overlay.waypoints, "·", WAYPOINT)
        self._paint_glyphs(chars, styles, overlay.spawns, "○", SPAWN)
        self._paint_glyphs(chars, styles, overlay.goals, "◎", GOAL)
        self._paint_glyphs(chars, styles, overlay.highlight_points, "◆", SELECTED)
        self._paint_labels(chars, styles)
        # Field arrows last: they fill only the cells still empty, so paths, markers and labels stay whole.
        for velocity_field in overlay.fields:
            self._paint_field(chars, styles, velocity_field)
        return chars, styles

    def _paint_field(self, chars: np.ndarray, styles: np.ndarray, velocity_field: VelocityField) -> None:
        vectors = np.asarray(velocity_field.vectors)
        origin_x, origin_y = velocity_field.origin
        resolution = float(velocity_field.resolution)
        rows, cols = np.mgrid[0 : self.height : 2, 0 : self.width : 3]
        rows, cols = rows.ravel(), cols.ravel()
        xs = self.x0 + (cols + 0.5) * 2 / self.dots_per_metre
        ys = self.y1 - (rows + 0.5) * 4 / self.dots_per_metre
        fr = np.floor((ys - origin_y) / resolution).astype(np.int64)
        fc = np.floor((xs - origin_x) / resolution).astype(np.int64)
        inside = (fr >= 0) & (fc >= 0) & (fr < vectors.shape[0]) & (fc < vectors.shape[1])
        rows, cols, fr, fc = rows[inside], cols[inside], fr[inside], fc[inside]
        vx, vy = vectors[fr, fc, 0], vectors[fr, fc, 1]
        moving = (np.hypot(vx, vy) > 1e-6) & (chars[rows, cols] == SPACE)
        rows, cols, vx, vy = rows[moving], cols[moving], vx[moving], vy[moving]
        octant = np.round(np.arctan2(vy, vx) / (math.pi / 4)).astype(np.int64) % 8
        chars[rows, cols] = np.array([ord(a) for a in ARROWS], dtype=np.uint32)[octant]
        styles[rows, cols] = FIELD


@dataclass(frozen=True)
class AgentCells:
    """Agents rasterised to cells: flat cell indexes with their braille code and style."""

    rows: np.ndarray
    cols: np.ndarray
    chars: np.ndarray
    styles: np.ndarray

    def by_row(self) -> dict[int, tuple[np.ndarray, np.ndarray, np.ndarray]]:
        out: dict[int, tuple[np.ndarray, np.ndarray, np.ndarray]] = {}
        if len(self.rows) == 0:
            return out
        order = np.argsort(self.rows, kind="stable")
        rows = self.rows[order]
        bounds = np.flatnonzero(np.diff(rows)) + 1
        for chunk in np.split(np.arange(len(rows)), bounds):
            index = order[chunk]
            out[int(rows[chunk[0]])] = (self.cols[index], self.chars[index], self.styles[index])
        return out


def rasterise_agents(
    raster: MapRaster,
    positions: np.ndarray,
    colour_index: np.ndarray,
    selected: int = -1,
    robot: tuple[float, float, float] | None = None,
) -> AgentCells:
    """Each agent is a 2x2 dot blob; the robot is an arrow glyph pointing along its heading."""
    positions = np.asarray(positions, dtype=np.float64).reshape(-1, 2)
    dx, dy = raster.to_dots(positions)
    dx = np.concatenate([dx, dx + 1, dx, dx + 1])
    dy = np.concatenate([dy, dy, dy + 1, dy + 1])
    styles_per_agent = GROUP_BASE + (np.asarray(colour_index, dtype=np.int64) % GROUP_COLOURS)
    if 0 <= selected < len(positions):
        styles_per_agent = styles_per_agent.copy()
        styles_per_agent[selected] = SELECTED
    style_of_dot = np.tile(styles_per_agent, 4)
    keep = (dx >= 0) & (dy >= 0) & (dx < raster.width * 2) & (dy < raster.height * 4)
    dx, dy, style_of_dot = dx[keep], dy[keep], style_of_dot[keep]
    flat = (dy // 4) * raster.width + dx // 2
    bits = BRAILLE_BITS[dy % 4, dx % 2]
    cells, inverse = np.unique(flat, return_inverse=True)
    merged = np.zeros(len(cells), dtype=np.uint8)
    np.bitwise_or.at(merged, inverse, bits)
    cell_style = np.zeros(len(cells), dtype=np.uint8)
    # The selected agent wins its cells; otherwise the last agent drawn there gives the colour.
    order = np.argsort(style_of_dot == SELECTED, kind="stable")
    cell_style[inverse[order]] = style_of_dot[order]
    chars = (BRAILLE_BASE + merged.astype(np.uint32)).astype(np.uint32)
    rows, cols = cells // raster.width, cells % raster.width
    if robot is not None:
        rrow, rcol = raster.to_cells(np.array([[robot[0], robot[1]]]))
        if 0 <= rrow[0] < raster.height and 0 <= rcol[0] < raster.width:
            octant = int(round(robot[2] / (math.pi / 4))) % 8
            rows = np.append(rows, rrow[0])
            cols = np.append(cols, rcol[0])
            chars = np.append(chars, np.uint32(ord(ARROWS[octant])))
            cell_style = np.append(cell_style, np.uint8(ROBOT))
    return AgentCells(rows.astype(np.int64), cols.astype(np.int64), chars.astype(np.uint32), cell_style.astype(np.uint8))


def row_text(chars_row: np.ndarray) -> str:
    return np.ascontiguousarray(chars_row, dtype="<u4").tobytes().decode("utf-32-le")


def row_runs(styles_row: np.ndarray) -> list[tuple[int, int, int]]:
    """(start, end, style) runs of equal style along a row."""
    return list(zip(*row_run_lists(styles_row)))


def row_run_lists(styles_row: np.ndarray) -> tuple[list[int], list[int], list[int]]:
    """The runs of `row_runs` as three plain lists (starts, ends, styles): one numpy pass, no per-run numpy."""
    if len(styles_row) == 0:
        return [], [], []
    change = (np.flatnonzero(styles_row[1:] != styles_row[:-1]) + 1).tolist()
    starts = [0, *change]
    return starts, [*change, len(styles_row)], styles_row[starts].tolist()


BLANK_BRAILLE = BRAILLE_BASE  # a braille cell with no dots: as blank as a space


def merge_blank_cells(chars_row: np.ndarray, styles_row: np.ndarray, blank_safe: np.ndarray) -> np.ndarray:
    """The row's styles with every blank cell restyled like the cell before it, where nobody can tell.

    A space (or an empty braille cell) shows only its background, so when its style and the style
    before it differ only in what a blank does not show (colour, bold, italic: `blank_safe[style]`,
    the styles whose background and lines are the map's own), it can join the run before it. On a
    map of scattered agents that halves the segments of a row: `floor agent floor agent ...` becomes
    `agent+floor agent+floor ...`, and every stage after this one (strips, crops, the colour filter,
    the compositor's cuts, the terminal encoding) costs per segment. What the terminal shows is
    identical (tests/tui/test_map_view_frames.py compares them cell by cell).
    """
    n = len(styles_row)
    if n == 0:
        return styles_row
    blank = ((chars_row == SPACE) | (chars_row == BLANK_BRAILLE)) & blank_safe[styles_row]
    # Index of the last cell at or before each one that is not a mergeable blank.
    source = np.where(blank, 0, np.arange(n))
    np.maximum.accumulate(source, out=source)
    donor = styles_row[source]
    # A blank takes its donor's style only if that style is itself one a blank may wear, and a
    # blank run at the start of the row (no donor before it) keeps its own.
    take = blank & blank_safe[donor] & ~blank[source]
    if not take.any():
        return styles_row
    merged = styles_row.copy()
    merged[take] = donor[take]
    return merged


def _centroid_xy(zone: Zone) -> tuple[float, float]:
    x, y = zone.centroid  # world.Zone.centroid: the polygon's centroid as a point (x, y)
    return float(x), float(y)


MIN_LABEL_ROOM = 8  # cells a label may always take, however narrow the map
MIN_LABEL_CELLS = 4  # a gap narrower than this gets no label: "w." would tell nobody anything
ABBREVIATION_MARK = "."  # ends every word the map shortens


def label_words(name: str) -> str:
    return " ".join(name.replace("_", " ").split())


def abbreviate(name: str, room: int) -> str:
    """A zone name in `room` cells, by one rule the map legend explains ("ab. = shortened name"): whole
    if it fits, else shortened with every cut marked by a "." at its end. Each word longer than k
    letters keeps its first k ("intensive care" -> "inten. care", "int. car."), k the largest that fits;
    words shorter than three letters only when nothing else fits; last words go first when even that is
    too long ("main waiting" -> "main."). "" when not even one letter and its mark fit.
    """
    words = label_words(name).split(" ")
    if not words or not words[0]:
        return ""
    full = " ".join(words)
    if len(full) <= room:
        return full
    for shortest in (3, 1):
        for kept in range(len(words), 0, -1):
            head = words[:kept]
            for k in range(max(len(w) for w in head), shortest - 1, -1):
                cut = [w if len(w) <= k else w[:k] + ABBREVIATION_MARK for w in head]
                if kept < len(words) and not cut[-1].endswith(ABBREVIATION_MARK):
                    cut[-1] += ABBREVIATION_MARK  # the words after it were dropped
                label = " ".join(cut)
                if len(label) <= room:
                    return label
    return ""
