"""Issue 21 item 7: a legend under the map, zoom that centres on the selection, and colour-mode names."""

from __future__ import annotations

import numpy as np
import pytest
from helpers.app import generate_to_inspect, generate_to_simulation
from helpers.app import (
    fake_llm_session,
    map_laid_out,
    test_settings,
    wait_until,
)

from grove_tui.tui.app import GroveApp
from grove_tui.tui.widgets.map_legend import MapLegend
from grove_tui.tui.widgets.map_view import MapView

pytestmark = pytest.mark.anyio


def cell_in_view(world_map: MapView, x: float, y: float) -> tuple[int, int]:
    """(column, row) of a world point relative to the map's visible region."""
    rows, cols = world_map.raster.to_cells(np.array([[x, y]]))
    return int(cols[0]) - int(world_map.scroll_offset.x), int(rows[0]) - int(world_map.scroll_offset.y)


@pytest.mark.slow
async def test_zoom_centres_on_the_selected_agent_and_the_legend_names_the_symbols(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        inspect = await generate_to_inspect(pilot, app)
        await wait_until(pilot, lambda: inspect._selected_node is not None, what="agent selected")
        world_map = inspect.query_one("#inspect-map", MapView)
        await map_laid_out(pilot, world_map)
        legend = str(inspect.query_one("#inspect-legend", MapLegend).render())
        assert all(word in legend for word in ("○spawn", "◎goal", "◆selected"))
        agent = inspect.generated.scenario.agents[0]
        await pilot.press("m", "plus", "plus", "plus")
        await pilot.pause(0.2)
        assert world_map._zoom > 3
        width, height = world_map.size.width, world_map.size.height
        col, row = cell_in_view(world_map, *agent.start)
        assert 0 <= col < width and 0 <= row < height, "the selected agent is off screen after zooming"
        assert abs(col - width // 2) <= 2 and abs(row - height // 2) <= 2, (col, row, width, height)
        await pilot.press("0")
        assert world_map._zoom == 1.0


@pytest.mark.slow
async def test_simulation_legend_names_the_colours_of_each_mode(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        sim = await generate_to_simulation(pilot, app)
        legend = sim.query_one("#sim-legend", MapLegend)
        label = sim.generated.scenario.agents[0].label
        assert str(legend.render()).startswith("group: ") and f"⣿{label}" in str(legend.render())
        await pilot.press("c")
        text = str(legend.render())
        assert text.startswith("behavior: ") and "⣿Regular" in text and "Scared" not in text
