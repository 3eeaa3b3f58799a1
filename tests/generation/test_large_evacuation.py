"""Large evacuations (issue 17): a crowd the sentence places nowhere starts spread over the building,
up to grove_tui/limits.py MAX_GROUP_COUNT people per group; beyond it, one clear refusal naming the limit."""

from __future__ import annotations

import math

import pytest
import shapely

from grove_tui.errors import PromptError
from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.generation.postprocess import SPAWN_SPACING, FreeSpace, check_population, postprocess
from grove_tui.generation.presets import load_preset
from grove_tui.generation.rois import select_rois
from grove_tui.language.reading import read_prompt
from grove_tui.limits import MAX_GROUP_COUNT
from grove_tui.navigation.grid import build_grid

LEAVE = DraftNode("Sequence", {}, (DraftNode("FollowVelocityField", {"exit": "main_entrance"}),))


@pytest.fixture(scope="module")
def hospital_grid(hospital):
    """The hospital's planning grid at the default 10 cm cells."""
    return build_grid(hospital, resolution=0.1, inflation=0.35)


def generate(hospital, hospital_grid, prompt, count, spawn="entrance_lobby"):
    """The post-processing stage as the pipeline runs it: the reading, the RoI selection, a draft."""
    preset = load_preset("emergency")
    reading = read_prompt(prompt, hospital)
    selection = select_rois(hospital, preset, reading)
    check_population(hospital, hospital_grid, preset, selection, reading)
    draft = Draft((DraftGroup("people", count, spawn, LEAVE),))
    return postprocess(hospital, hospital_grid, preset, draft, selection, 0, reading,
                       ("Sequence", "FollowVelocityField", "JoinGroup", "Wait"))


def test_the_emergency_preset_allows_the_documented_limit():
    assert load_preset("emergency").limits.max_count == MAX_GROUP_COUNT == 500


def test_500_people_placed_nowhere_start_across_the_building_each_to_the_nearest_exit(hospital, hospital_grid):
    out = generate(hospital, hospital_grid, "500 people evacuate the hospital", 40)
    assert len(out.agents) == 500 and [g.count for g in out.groups] == [500]
    zones = {a.spawn_zone for a in out.agents}
    assert len(zones) >= 15  # the hospital's rooms with free floor, not the lobby alone
    space = FreeSpace(hospital, hospital_grid)
    for zone in zones:
        members = sum(a.spawn_zone == zone for a in out.agents)
        assert members <= space.capacity(zone)
    for a in out.agents:
        assert hospital_grid.is_free(*a.start)
        assert hospital.zone(a.spawn_zone).polygon.contains(shapely.Point(a.start))
    starts = [a.start for a in out.agents]
    tree = shapely.STRtree([shapely.Point(p) for p in starts])
    for i, j in zip(*tree.query([shapely.Point(p) for p in starts], predicate="dwithin", distance=SPAWN_SPACING - 1e-6)):
        assert i == j or math.dist(starts[i], starts[j]) >= SPAWN_SPACING - 1e-9
    assert len({a.exit for a in out.agents}) >= 2  # every exit is allowed: each person its nearest
    assert any("start across the building" in note for note in out.notes)
    from grove_tui.generation.reconcile import grounding_report

    report = grounding_report(read_prompt("500 people evacuate the hospital", hospital), out.groups, out.agents,
                              hospital, out.notes)
    kinds = [c.kind for c in report.groups[0].claims]
    assert "start" not in kinds and "evacuate" in kinds  # the sentence names no start: nothing to claim there
    assert report.groups[0].status == "planned"
    # Deterministic: the same seed spreads them the same way.
    again = generate(hospital, hospital_grid, "500 people evacuate the hospital", 40)
    assert [a.start for a in again.agents] == starts


def test_a_crowd_the_sentence_places_in_a_room_too_small_is_refused_there(hospital, hospital_grid):
    with pytest.raises(PromptError, match=r"do not fit in cafeteria.*at most 259"):
        generate(hospital, hospital_grid, "300 people evacuate the cafeteria", 40, spawn="cafeteria")


def test_a_crowd_that_fits_its_zone_stays_there(hospital, hospital_grid):
    out = generate(hospital, hospital_grid, "30 people evacuate the hospital", 30)
    assert len({a.spawn_zone for a in out.agents}) == 1
    assert not any("start across the building" in note for note in out.notes)


def test_over_the_limit_is_one_refusal_naming_it(hospital, hospital_grid):
    with pytest.raises(PromptError, match=rf"asks for 501 people in one group; preset 'emergency' allows at most "
                                          rf"{MAX_GROUP_COUNT} per group"):
        generate(hospital, hospital_grid, "501 people evacuate the hospital", 40)


def test_grove_generate_says_a_spread_crowd_starts_across_the_building(hospital, hospital_grid, tmp_path):
    from types import SimpleNamespace

    from grove_tui.cli.generate import summary_lines

    out = generate(hospital, hospital_grid, "500 people evacuate the hospital", 40)
    (group,) = out.groups
    report = {"stages": {}, "zones": [group.spawn], "prompt_tokens": 0, "completion_tokens": 0, "total_seconds": 0.0,
              "groups": [{"label": group.label, "count": group.count, "spawn": group.spawn,
                          "spawn_zones": dict(group.spawn_zones)}]}
    lines = summary_lines(SimpleNamespace(scenario=SimpleNamespace(agents=out.agents, robot=None, seed=0),
                                          report=report), tmp_path)
    assert f"agents: 500 (500 {group.label} across {len(group.spawn_zones)} zones)" in lines
