"""An unknown place whose head is also a verb word ("trail", "run") is refused whole, head included
(issue 29): "towards the road bike trail" refuses "road bike trail", not "road bike", and is not read as
a loosely matching bike place. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, refused, start", [
    ("velodrome", "Two coaches stroll out of the cafe towards the road bike trail.", "road bike trail", "cafe"),
    ("hall_of_residence", "Two students wheel their bikes out of the common room towards the bike trail.",
     "bike trail", "common_room"),
])
def test_an_unknown_phrase_is_refused_with_its_head(read, world, prompt, refused, start):
    reading = read(world, prompt)
    assert refused in reading.unknown_places
    group = reading.groups[0]
    assert group.start == start
    assert group.destination is None


def test_a_known_name_then_a_verb_keeps_its_reading(read):
    group = read("airport", "Two passengers walk from the check-in hall to the security queue and wait there."
                 ).groups[0]
    assert group.start == "check_in_hall"
