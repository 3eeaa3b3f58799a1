"""An outing people are on ("on a geography trip", "back from a skiing holiday") is no place: nothing is
refused for it, and the people still go where the sentence says. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, destination", [
    ("airport", "Back from a skiing holiday, a family of four walk from baggage claim to the arrivals hall.",
     "baggage_claim", "arrivals_hall"),
    ("hospital", "A group of nursing students on a field trip walk from the entrance lobby to radiology.",
     "entrance_lobby", "radiology"),
    ("museum", "Fresh off the coach, a busload of sixth-formers on a geography trip make a beeline from the foyer "
               "to the fossil gallery.", "entrance_hall", "dinosaur_gallery"),
])
def test_an_outing_is_no_place(read, world, prompt, start, destination):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    group = reading.groups[0]
    assert (group.start, group.destination) == (start, destination)


def test_a_real_place_after_on_is_still_read(read):
    group = read("station", "A class of pupils on a school trip wait on platform 2 for the train.").groups[0]
    assert group.location == "platform_2"
