"""A verb of idling the parser takes for a noun after a collective of people ("a pair of teens mess about
on X") is their verb, and where they idle is the thing named (language/idle_idioms.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

IDLING = [
    ("mall", "A couple of teens mess about by the fountain.", 2, "fountain"),
    ("airport", "A trio of students mess around by the departures board.", 3, "departure_board"),
    ("eval/understanding/worlds/physio_clinic.yaml", "A couple of kids mess about on the treadmills.", 2, "treadmills"),
    ("eval/understanding/worlds/day_nursery.yaml", "A pair of toddlers muck around by the climbing frame.", 2,
     "climbing_frame"),
    ("residential", "The twins muck about on the sofa.", 2, "sofa"),
]


@pytest.mark.parametrize("world, sentence, count, place", IDLING)
def test_people_idling_by_a_thing_are_there(world, sentence, count, place):
    reading = read_prompt(sentence, load_world(world))
    assert len(reading.groups) == 1
    group = reading.groups[0]
    assert (group.count.value, group.intent, group.location, group.start) == (count, "wait", place, None)
    assert not reading.unknown_places
