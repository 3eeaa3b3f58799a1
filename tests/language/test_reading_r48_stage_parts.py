"""The wings (the flies, stage left) of a stage are part of the stage: a world with a stage and no such
alias reads them as the stage, never refuses them (stage_parts.py); a building's wing is no stage part."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world", ["community_centre", "student_union", "cruise_ship"])
def test_the_wings_are_the_stage(read, world):
    r = read(world, "Smoke drifts from the wings and twenty people leave by the main entrance.")
    assert r.unknown_places == ()
    assert "stage" in r.places


def test_stage_left_is_the_stage(read):
    r = read("student_union", "Three roadies wait stage left while a crowd gathers.")
    assert "wings" not in " ".join(r.unknown_places)


def test_a_wing_of_a_building_is_no_stage(read):
    r = read("hospital", "Two nurses walk to the east wing.")
    assert all("stage" not in p for p in r.places)
