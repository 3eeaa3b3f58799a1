"""A place word in a relative clause about a person ("who slipped on the wet tiles") is no place of the
scene and nothing to refuse (person_relatives.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, sentence, start, destination", [
    ("emergency_department", "A porter pushes an old man who fell on the icy steps from the ambulance bay to the resus room.",
     "ambulance_bay", "resus"),
    ("community_centre", "A volunteer helps a boy who'd tripped in the back garden from the foyer into the kitchen.",
     "foyer", "kitchen"),
    ("hotel", "A porter helps a guest who slipped in the wet courtyard from the lobby to the lift.", "lobby", "lift_lobby"),
    ("water_park", "A lifeguard wheels a teenager who slipped on the wet tiles out of the lazy river and into the first aid room.",
     "lazy_river", "first_aid_room"),
])
def test_relative_clause_place_is_not_refused(read, world, sentence, start, destination):
    r = read(world, sentence)
    assert r.unknown_places == ()
    assert (r.groups[0].start, r.groups[0].destination) == (start, destination)
