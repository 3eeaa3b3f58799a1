"""The map: a Line API ScrollView over a MapRaster, with agents drawn on top of cached static strips."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from rich.segment import Segment
from rich.style import Style
from textual.binding import Binding
from textual.cache import LRUCache
from textual.geometry import Size
from textual.scroll_view import ScrollView
from textual.strip import Strip

from grove_tui.tui.widgets import map_raster as mr
from grove_tui.tui.widgets import map_styles as ms

if TYPE_CHECKING:
    import numpy as np

    from grove_tui.services.domain import World
    from grove_tui.tui.widgets.map_legend import MapLegend

STYLE_CLASSES = {
    ms.FLOOR: "map--floor",
    ms.WALL: "map--wall",
    ms.ZONE_LABEL: "map--zone-label",
    ms.DOOR: "map--door",
    ms.ENTITY: "map--entity",
    ms.SPAWN: "map--spawn",
    ms.GOAL: "map--goal",
    ms.WAYPOINT: "map--waypoint",
    ms.FIELD: "map--field",
    ms.HIGHLIGHT: "map--highlight",
    ms.ROBOT: "map--robot",
    ms.ROBOT_PATH: "map--robot-path",
    ms.SELECTED: "map--selected",
    **{ms.GROUP_BASE + i: f"map--group-{i}" for i in range(ms.GROUP_COLOURS)},
}

ZOOM_STEP = 1.5
MAX_ZOOM = 16.0


class MapView(ScrollView, can_focus=True):
    """World map: walls (braille), zone labels, doors ▒, spawns ○, goals ◎, waypoints ·, field arrows."""

    HELP = """\
## Map

Walls and entity outlines are drawn with braille dots, zones are labelled, doors are `▒`. A zone name
with no room for all of it is shortened, and every cut ends with a dot: each long word keeps its first
letters (`int. care` for intensive care), and the last words go when even that is too long (`main.`
for main waiting); the legend then shows `ab.=shortened`. Zoom in (**+**) to read them whole.
Scenario overlays: spawns `○`, goals `◎`, injected waypoints `·`, velocity-field arrows, the robot's
path, and the selection highlighted with `◆`.

- **+ / -** zoom in and out, centred on the selection (or the queue), **0** fit the whole world
- **arrows** or **h j k l** pan
"""

    BINDINGS = [
        Binding("plus,equals_sign", "zoom(1)", "Zoom in", show=False, id="map.zoom_in", tooltip="Zoom in on the map"),
        Binding("minus", "zoom(-1)", "Zoom out", show=False, id="map.zoom_out", tooltip="Zoom out"),
        Binding("0", "fit", "Fit", show=False, id="map.fit", tooltip="Fit the whole world in view"),
        Binding("h", "scroll_left", "Pan left", show=False, id="map.pan_left"),
        Binding("l", "scroll_right", "Pan right", show=False, id="map.pan_right"),
        Binding("k", "scroll_up", "Pan up", show=False, id="map.pan_up"),
        Binding("j", "scroll_down", "Pan down", show=False, id="map.pan_down"),
    ]

    COMPONENT_CLASSES = set(STYLE_CLASSES.values())

    DEFAULT_CSS = """
    MapView { scrollbar-size: 1 1; }
    MapView > .map--floor { color: $foreground-muted; }
    MapView > .map--wall { color: $foreground; }
    MapView > .map--zone-label { color: $secondary; text-style: italic; }
    MapView > .map--door { color: $warning; }
    MapView > .map--entity { color: $accent-muted; }
    MapView > .map--spawn { color: $success; text-style: bold; }
    MapView > .map--goal { color: $error; text-style: bold; }
    MapView > .map--waypoint { color: $warning; }
    MapView > .map--field { color: $primary-muted; }
    MapView > .map--highlight { color: $accent; text-style: bold; }
    MapView > .map--robot { color: $text-error; background: $error-muted; text-style: bold; }
    MapView > .map--robot-path { color: $error-muted; }
    MapView > .map--selected { color: $text-accent; background: $accent-muted; text-style: bold; }
    MapView > .map--group-0 { color: $primary; }
    MapView > .map--group-1 { color: $success; }
    MapView > .map--group-2 { color: $warning; }
    MapView > .map--group-3 { color: $secondary; }
    MapView > .map--group-4 { color: $accent; }
    MapView > .map--group-5 { color: $error; }
    MapView > .map--group-6 { color: $text-primary; }
    MapView > .map--group-7 { color: $text-success; }
    """

    def __init__(self, *, name: str | None = None, id: str | None = None, classes: str | None = None) -> None:
        super().__init__(name=name, id=id, classes=classes)
        self._world: World | None = None
        self._overlay: mr.Overlay | None = None
        self._zoom = 1.0  # multiple of the fit scale
        self._raster: mr.MapRaster | None = None
        self._chars: np.ndarray | None = None
        self._styles: np.ndarray | None = None
        self._strip_cache: LRUCache[int, Strip] = LRUCache(512)
        self._palette: list[Style] | None = None
        self._blank_safe: np.ndarray | None = None  # per style: a blank cell in it looks like the floor
        self._base_style: Style | None = None
        self._agent_rows: dict[int, tuple[np.ndarray, np.ndarray, np.ndarray]] = {}
        # Per map row: the bytes of its agents' cells, and the strip last built for them. A frame
        # repaints only rows whose key changed, and re-rendering an unchanged row reuses its strip.
        self._agent_keys: dict[int, bytes] = {}
        self._agent_strips: dict[int, tuple[bytes, Strip]] = {}
        self._fit_for: tuple[int, int] | None = None
        # The world point zoom centres on (the screen's selection or queue); None: the view's middle.
        self.zoom_target: Callable[[], tuple[float, float] | None] | None = None
        # The MapLegend under the map: told when the map is drawn again (zoom, size), since whether a zone
        # name had to be shortened (and the legend says how) depends on the scale.
        self.legend: MapLegend | None = None

    # public API --------------------------------------------------------------------------------------
    @property
    def raster(self) -> mr.MapRaster | None:
        return self._raster

    @property
    def world(self) -> World | None:
        return self._world

    def set_world(self, world: World | None) -> None:
        self._world = world
        self._overlay = None
        self._agent_rows = {}
        self._agent_keys = {}
        self._zoom = 1.0
        self._rebuild()

    def set_overlay(self, overlay: mr.Overlay | None) -> None:
        self._overlay = overlay
        self._recompose()

    def set_agents(self, cells: mr.AgentCells | None) -> int:
        """Swap the dynamic layer and repaint only the visible rows whose cells changed; returns how many."""
        new_rows = {} if cells is None else cells.by_row()
        new_keys = {row: agent_row_key(*cells_of_row) for row, cells_of_row in new_rows.items()}
        old_keys = self._agent_keys
        self._agent_rows, self._agent_keys = new_rows, new_keys
        top = int(self.scroll_offset.y)
        bottom = top + self.size.height
        repainted = 0
        for row in old_keys.keys() | new_keys.keys():
            if top <= row < bottom and old_keys.get(row) != new_keys.get(row):
                self.refresh_line(row - top)
                repainted += 1
        return repainted

    def centre_on(self, x: float, y: float) -> None:
        import numpy as np

        if self._raster is None:
            return
        rows, cols = self._raster.to_cells(np.array([[x, y]]))
        self.scroll_to(
            max(0, int(cols[0]) - self.size.width // 2), max(0, int(rows[0]) - self.size.height // 2), animate=False
        )

    # actions -----------------------------------------------------------------------------------------
    def view_centre(self) -> tuple[float, float] | None:
        """The world point at the middle of what the map shows now."""
        if self._raster is None:
            return None
        row = int(self.scroll_offset.y) + self.size.height // 2
        col = int(self.scroll_offset.x) + self.size.width // 2
        return self._raster.cell_centre(row, col)

    def action_zoom(self, direction: int) -> None:
        # Centre on what the screen is about (the selected agent, the queue), else keep the view's middle.
        target = self.zoom_target() if self.zoom_target is not None else None
        if target is None:
            target = self.view_centre()
        zoom = self._zoom * (ZOOM_STEP if direction > 0 else 1 / ZOOM_STEP)
        self._zoom = min(MAX_ZOOM, max(1.0, zoom))
        self._rebuild()
        if target is not None:
            x, y = target
            self.call_after_refresh(self.centre_on, x, y)

    def action_fit(self) -> None:
        self._zoom = 1.0
        self._rebuild()

    # rendering ---------------------------------------------------------------------------------------
    def on_resize(self) -> None:
        if self._world is not None and self._fit_for != (self.size.width, self.size.height):
            self._rebuild()

    def notify_style_update(self) -> None:
        super().notify_style_update()
        self._palette = None
        self._base_style = None
        self._strip_cache.clear()
        self._agent_strips.clear()

    def _rebuild(self) -> None:
        if self._world is None:
            self._raster = None
            self._chars = self._styles = None
            self.virtual_size = Size(0, 0)
            self._strip_cache.clear()
            self._agent_strips.clear()
            self.refresh()
            return
        cols = max(10, self.size.width or 40)
        rows = max(5, self.size.height or 20)
        self._fit_for = (self.size.width, self.size.height)
        scale = mr.MapRaster.fit_scale(self._world, cols - 1, rows)
        self._raster = mr.MapRaster(self._world, scale * self._zoom)
        self._recompose()

    def _recompose(self) -> None:
        if self._raster is None:
            return
        self._chars, self._styles = self._raster.compose(self._overlay)
        self._strip_cache.clear()
        self._agent_strips.clear()
        self.virtual_size = Size(self._raster.width, self._raster.height)
        self.refresh()
        if self.legend is not None:
            self.legend.map_changed(self)

    @property
    def labels_abbreviated(self) -> bool:
        """Whether a zone name on the map is shortened (the legend then explains the rule)."""
        return self._raster is not None and self._raster.labels_abbreviated

    def _styles_palette(self) -> list[Style]:
        if self._palette is None:
            import numpy as np

            base = self._rich_base_style()
            self._palette = [base + self.get_component_rich_style(STYLE_CLASSES[i]) for i in range(ms.STYLE_COUNT)]
            self._blank_safe = np.array([blank_looks_alike(style, base) for style in self._palette], dtype=bool)
        return self._palette

    def _rich_base_style(self) -> Style:
        # `rich_style` walks the DOM for the inherited background on every call (about 0.1 ms);
        # render_line needs it for every row of every frame, and it changes only with the CSS.
        if self._base_style is None:
            self._base_style = self.rich_style
        return self._base_style

    def _strip_for(self, chars_row: np.ndarray, styles_row: np.ndarray) -> Strip:
        # (map_raster is imported with the module: an import statement per row cost as much as the row's numpy.)
        palette = self._styles_palette()
        assert self._blank_safe is not None  # set with the palette
        text = mr.row_text(chars_row)
        starts, ends, styles = mr.row_run_lists(mr.merge_blank_cells(chars_row, styles_row, self._blank_safe))
        # tuple.__new__ skips Segment's Python-level constructor (defaults), the costliest call here.
        new, segment = tuple.__new__, Segment
        return Strip([new(segment, (text[s:e], palette[k], None)) for s, e, k in zip(starts, ends, styles)], len(text))

    def _static_strip(self, row: int) -> Strip:
        strip = self._strip_cache.get(row)
        if strip is None:
            assert self._chars is not None and self._styles is not None
            strip = self._strip_for(self._chars[row], self._styles[row])
            self._strip_cache[row] = strip
        return strip

    def _agent_strip(self, row: int, agents: tuple[np.ndarray, np.ndarray, np.ndarray]) -> Strip:
        assert self._chars is not None and self._styles is not None
        key = self._agent_keys.get(row, b"")
        cached = self._agent_strips.get(row)
        if cached is not None and cached[0] == key:
            return cached[1]
        cols, chars, styles = agents
        chars_row = self._chars[row].copy()
        styles_row = self._styles[row].copy()
        if len(cols) and int(cols.max()) >= len(chars_row):
            # agents placed on the raster before a resize (a side panel opened): drawn again next frame
            inside = cols < len(chars_row)
            cols, chars, styles = cols[inside], chars[inside], styles[inside]
        chars_row[cols] = chars
        styles_row[cols] = styles
        strip = self._strip_for(chars_row, styles_row)
        self._agent_strips[row] = (key, strip)
        return strip

    def render_line(self, y: int) -> Strip:
        scroll_x, scroll_y = self.scroll_offset
        row = scroll_y + y
        width = self.size.width
        base = self._rich_base_style()
        if self._chars is None or self._styles is None or row >= len(self._chars):
            return Strip.blank(width, base)
        agents = self._agent_rows.get(row)
        strip = self._static_strip(row) if agents is None else self._agent_strip(row, agents)
        return strip.crop_extend(scroll_x, scroll_x + width, base)


def blank_looks_alike(style: Style, base: Style) -> bool:
    """Whether a blank cell in `style` looks exactly like one in `base`: same background, no lines."""
    return (style.bgcolor == base.bgcolor and not style.reverse and not style.underline and not style.underline2
            and not style.strike and not style.overline and not style.blink and not style.blink2
            and not style.frame and not style.encircle and style.link is None)


def agent_row_key(cols: np.ndarray, chars: np.ndarray, styles: np.ndarray) -> bytes:
    """What one map row's agents look like, as bytes: equal keys draw the same row."""
    return cols.tobytes() + chars.tobytes() + styles.tobytes()
