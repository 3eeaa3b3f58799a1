"""What a hazard comes from that is no place of the building: a source outside it ("from a bonfire next
door", "from the chip shop across the road"), and the flames a thing bursts into ("bursts into flames").
Nobody goes there or comes from there, so nothing is refused. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start", [
    ("city_farm", "Smoke blows in from a bonfire next door and the thirty-odd visitors at the pig pens get out by the lane gate.",
     "pig_pens"),
    ("hotel", "Smoke drifts in from the chip shop across the road and the guests in the bar head out.", "bar"),
    ("zoo", "Smoke billows over from a barn next door and the families at the penguin pool hurry to the main gate.",
     "penguin_pool_rail"),
    ("library", "Acrid fumes waft in from a garage next door and the readers in the reading room leave.", "reading_room"),
])
def test_a_source_outside_the_building_is_not_refused(read, world, prompt, start):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    assert reading.groups[0].intent == "evacuate"
    assert reading.groups[0].start == start


@pytest.mark.parametrize("world, prompt", [
    ("food_court", "The deep-fat fryer at the noodle bar bursts into flames and the fifty or so diners in the seating "
                   "hall abandon their trays and flee."),
    ("cinema", "A popcorn machine bursts into flame and the twenty people in the foyer leave by the main doors."),
    ("hotel", "A toaster in the kitchen goes up in flames and the guests in the restaurant hurry out."),
])
def test_flames_are_no_place(read, world, prompt):
    assert read(world, prompt).unknown_places == ()


def test_a_room_of_the_building_a_hazard_comes_from_is_still_read(read):
    reading = read("museum", "Smoke pours out of the gift shop and the visitors in the great hall leave.")
    assert reading.unknown_places == ()
