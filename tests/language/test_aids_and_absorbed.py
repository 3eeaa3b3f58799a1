"""A walking aid someone goes on or sits in is no place, read or refused (language/walking_aids.py), and
what someone is absorbed in is no place to refuse (language/absorbed_in.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

REHAB = "eval/understanding/worlds/rehab_centre.yaml"
AIDED = [
    ("hospital", "An old man on a zimmer frame shuffles from the ward to the cafeteria.", "start", "ward_a"),
    (REHAB, "A frail lady on her frame totters across to the plinths.", "destination", "plinths"),
    (REHAB, "Two patients in wheelchairs wait at the hatch.", "location", "serving_hatch"),
    (REHAB, "A man on crutches hobbles to the tilt table.", "destination", "tilt_table"),
    ("airport", "A pensioner on a mobility scooter rolls to the check-in desks.", "destination", "check_in_hall"),
    ("residential", "Gran, with her walking stick, waits in the kitchen.", "location", "kitchen"),
]
ABSORBED = [
    ("residential", "Grandad is glued to the cricket in the living room.", "living_room"),
    ("residential", "Both boys sit in the kitchen, engrossed in the snooker.", "kitchen"),
    ("hospital", "Three visitors glued to the news wait in the lobby.", "entrance_lobby"),
    ("airport", "Two pilots hooked on the rugby wait at gate B2.", "gate_b2"),
]


@pytest.mark.parametrize("world, sentence, role, place", AIDED)
def test_a_walking_aid_is_no_place(world, sentence, role, place):
    reading = read_prompt(sentence, load_world(world))
    assert not reading.unknown_places
    assert getattr(reading.groups[0], role) == place


def test_a_climbing_frame_is_still_a_place():
    reading = read_prompt("Three toddlers play on the climbing frame.",
                          load_world("eval/understanding/worlds/day_nursery.yaml"))
    assert reading.groups[0].location == "climbing_frame"


@pytest.mark.parametrize("world, sentence, place", ABSORBED)
def test_what_holds_someone_is_no_unknown_place(world, sentence, place):
    reading = read_prompt(sentence, load_world(world))
    assert not reading.unknown_places
    assert reading.groups[0].location == place
