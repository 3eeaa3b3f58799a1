"""A treatment someone is on ("patients on dialysis", "a man on therapy") is no place, though a room
of the world shares the word; "on the dialysis ward" still is (treatments)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, location", [
    (W + "hospice.yaml", "Two residents on therapy doze in the family lounge.", "family_lounge"),
    (W + "physio_clinic.yaml", "An old boy on physio sits in the waiting room with his paper.", None),
    (W + "dialysis_unit.yaml", "After lunch, four patients on haemodialysis wait in the waiting room.", "waiting_room"),
])
def test_a_treatment_one_is_on_is_no_place(world, sentence, location):
    reading = read_prompt(sentence, load_world(world))
    group = reading.groups[0]
    assert reading.unknown_places == ()
    if location is not None:
        assert group.location == location
    else:
        assert group.location is not None and "gym" not in group.location
