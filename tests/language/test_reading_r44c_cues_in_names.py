"""An evacuation cue word that is part of a place's name ("the drill yard", "the alarm screens", "the drill
display") is the place, not an evacuation: people going there walk. A drill or an alarm said as such
still evacuates. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt", [
    ("fire_station", "Two recruits in BA sets jog from the kit room out to the smoke house in the drill yard."),
    ("fire_station", "Three firefighters stroll from the mess room to the drill yard."),
    ("data_centre", "Two engineers wander from the break room over to the alarm screens."),
    ("diy_store", "A customer strolls from the paint aisle to the drill display."),
])
def test_a_cue_in_a_place_name_is_no_evacuation(read, world, prompt):
    assert read(world, prompt).groups[0].intent == "walk"


@pytest.mark.parametrize("world, prompt", [
    ("fire_station", "During a fire drill the crew walk from the mess room to the muster area."),
    ("fire_station", "The alarm goes off and the crew run from the mess room to the appliance bay."),
])
def test_a_drill_or_alarm_said_as_such_still_evacuates(read, world, prompt):
    assert read(world, prompt).groups[0].intent == "evacuate"
