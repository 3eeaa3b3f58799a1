"""The one-line legend under a map: each symbol in the map's own style, then what the colours mean."""

from __future__ import annotations

from collections.abc import Sequence

from rich.text import Text
from textual.widgets import Static

from grove_tui.tui.widgets import map_styles as ms
from grove_tui.tui.widgets.map_view import STYLE_CLASSES, MapView

# (glyph, style, meaning) of the inspect map's overlays, in the order the legend lists them.
INSPECT_SYMBOLS = (
    ("○", ms.SPAWN, "spawn"),
    ("◎", ms.GOAL, "goal"),
    ("·", ms.WAYPOINT, "waypoint"),
    ("◆", ms.SELECTED, "selected"),
    ("▒", ms.DOOR, "door"),
)
ROBOT_PATH = ("⣀", ms.ROBOT_PATH, "robot path")
FIELD = ("→", ms.FIELD, "field")


class MapLegend(Static):
    """Rebuilt by its screen with `show_symbols` / `show_colours`; it takes the map's styles."""

    DEFAULT_CSS = """
    MapLegend { height: 1; padding: 0 1; text-wrap: nowrap; text-overflow: ellipsis; }
    """

    def show_symbols(self, world_map: MapView, symbols: Sequence[tuple[str, int, str]]) -> None:
        legend = Text(no_wrap=True, overflow="ellipsis")
        for glyph, style, meaning in symbols:
            legend.append(glyph, world_map.get_component_rich_style(STYLE_CLASSES[style]))
            legend.append(f"{meaning}  ")
        self.update(legend.rstrip() or legend)
        self.tooltip = "  ".join(f"{glyph} {meaning}" for glyph, _style, meaning in symbols)

    def show_colours(self, world_map: MapView, mode: str, names: Sequence[str],
                     symbols: Sequence[tuple[str, int, str]] = ()) -> None:
        """People coloured by `mode` (group or behavior): one coloured dot per name, then the symbols."""
        legend = Text(no_wrap=True, overflow="ellipsis")
        legend.append(f"{mode}: ")
        for index, name in enumerate(names):
            if not name:  # a colour no one in this scenario has
                continue
            style = STYLE_CLASSES[ms.GROUP_BASE + index % ms.GROUP_COLOURS]
            legend.append("⣿", world_map.get_component_rich_style(style))
            legend.append(f"{name} ")
        for glyph, style, meaning in symbols:
            legend.append(f" {glyph}", world_map.get_component_rich_style(STYLE_CLASSES[style]))
            legend.append(meaning)
        self.update(legend)
        self.tooltip = f"people coloured by {mode}: " + ", ".join(names)
