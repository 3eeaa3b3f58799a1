"""The one-line legend under a map: each symbol in the map's own style, then what the colours mean."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from rich.text import Text
from textual.widgets import Static

from grove_tui.tui.widgets import map_styles as ms
from grove_tui.tui.widgets.map_view import STYLE_CLASSES, MapView

# (glyph, style, meaning) of the inspect map's overlays, in the order the legend lists them.
INSPECT_SYMBOLS = (
    ("○", ms.SPAWN, "spawn"),
    ("◎", ms.GOAL, "goal"),
    ("·", ms.WAYPOINT, "waypoint"),
    ("▒", ms.DOOR, "door"),
    ("◆", ms.SELECTED, "selected"),
)
WORLD_SYMBOLS = (("▒", ms.DOOR, "door"),)
ROBOT_PATH = ("⣀", ms.ROBOT_PATH, "robot path")
FIELD = ("→", ms.FIELD, "field")


ABBREVIATED = ("ab.", ms.ZONE_LABEL, "=shortened")  # zone names cut to fit, by map_raster.abbreviate's rule


class MapLegend(Static):
    """Rebuilt by its screen with `show_symbols` / `show_colours`; it takes the map's styles. The map
    tells it when it is drawn again (`map_changed`): the zone-name rule shows only while a name is cut."""

    DEFAULT_CSS = """
    MapLegend { height: 1; padding: 0 1; text-wrap: nowrap; text-overflow: ellipsis; }
    """

    def __init__(self, content: str = "", *, name: str | None = None, id: str | None = None,
                 classes: str | None = None) -> None:
        super().__init__(content, name=name, id=id, classes=classes)
        self._shown: Callable[[MapView], None] | None = None  # shows the last legend again, on a redrawn map

    def map_changed(self, world_map: MapView) -> None:
        if self._shown is not None:
            self._shown(world_map)

    def show_symbols(self, world_map: MapView, symbols: Sequence[tuple[str, int, str]]) -> None:
        self._shown = lambda redrawn: self.show_symbols(redrawn, symbols)
        entries = list(symbols)
        if world_map.labels_abbreviated:
            # After the markers a scenario draws, before those of a selection or the robot.
            at = next((i for i, (_g, style, _m) in enumerate(entries) if style in (ms.SELECTED, ms.ROBOT_PATH, ms.FIELD)),
                      len(entries))
            entries.insert(at, ABBREVIATED)
        legend = Text(no_wrap=True, overflow="ellipsis")
        for glyph, style, meaning in entries:
            legend.append(glyph, world_map.get_component_rich_style(STYLE_CLASSES[style]))
            legend.append(f"{meaning} ")
        legend.rstrip()  # in place (rich's Text.rstrip returns None)
        self.update(legend)
        self.tooltip = "  ".join(f"{glyph}{meaning}" for glyph, _style, meaning in entries)

    def show_colours(self, world_map: MapView, mode: str, names: Sequence[str],
                     symbols: Sequence[tuple[str, int, str]] = ()) -> None:
        """People coloured by `mode` (group or behavior): one coloured dot per name, then the symbols."""
        self._shown = lambda redrawn: self.show_colours(redrawn, mode, names, symbols)
        legend = Text(no_wrap=True, overflow="ellipsis")
        legend.append(f"{mode}: ")
        for index, name in enumerate(names):
            if not name:  # a colour no one in this scenario has
                continue
            style = STYLE_CLASSES[ms.GROUP_BASE + index % ms.GROUP_COLOURS]
            legend.append("⣿", world_map.get_component_rich_style(style))
            legend.append(f"{name} ")
        if world_map.labels_abbreviated:
            glyph, style_index, meaning = ABBREVIATED
            legend.append(f" {glyph}", world_map.get_component_rich_style(STYLE_CLASSES[style_index]))
            legend.append(meaning)
        for glyph, style_index, meaning in symbols:
            legend.append(f" {glyph}", world_map.get_component_rich_style(STYLE_CLASSES[style_index]))
            legend.append(meaning)
        self.update(legend)
        self.tooltip = f"people coloured by {mode}: " + ", ".join(names)
