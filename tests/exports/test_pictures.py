"""Pictures of scenarios: PNG and SVG files for papers, and the terminal rendering."""

from __future__ import annotations

import pytest

from grove_tui.exports.pictures import PictureError, draw_scenario, render_scenario_text
from grove_tui.scenario.model import Scenario
from grove_tui.world import load_world

pytest.importorskip("matplotlib")


@pytest.mark.slow
def test_png_and_svg_pictures_are_written(bundle, tmp_path):
    world = load_world("hospital")
    scenario = Scenario.load(bundle / "scenario.yaml")
    png = draw_scenario(world, scenario, bundle, tmp_path / "scenario.png")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    svg = draw_scenario(world, scenario, bundle, tmp_path / "scenario.svg")
    text = svg.read_text()
    assert text.lstrip().startswith("<?xml") and "<svg" in text
    # deterministic: the same scenario gives the same SVG bytes
    again = draw_scenario(world, scenario, bundle, tmp_path / "again.svg")
    assert again.read_bytes() == svg.read_bytes()


def test_unknown_picture_format_is_refused(bundle, tmp_path):
    world = load_world("hospital")
    scenario = Scenario.load(bundle / "scenario.yaml")
    with pytest.raises(PictureError, match=r"\.gif: picture format"):
        draw_scenario(world, scenario, bundle, tmp_path / "scenario.gif")
    assert not (tmp_path / "scenario.gif").exists()


def test_terminal_rendering_marks_spawns_goals_and_robot(bundle):
    world = load_world("hospital")
    scenario = Scenario.load(bundle / "scenario.yaml")
    text = render_scenario_text(world, scenario, width=100).plain
    assert "R" in text and "G" in text
    assert text.count("o") >= 3  # spawns (some may share a cell at this scale)
    assert "x" in text
