"""Round 44: the object of a phrasal verb of purpose after its particle is part of the purpose ("to stock
up on nappies", "to read up on Tudor history"); a place of the world there is still a place."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination,said", [
    ("mall", "Two mums head to the supermarket to stock up on nappies.", "supermarket", "nappies"),
    ("library", "A student hurries to the reading room to read up on Tudor history.", "reading_room", "tudor"),
    ("hospital", "A nurse pops into the staff room to catch up with her friend.", "staff_room", "friend"),
])
def test_the_object_after_a_particle_is_the_purpose(read, world, prompt, destination, said):
    g = read(world, prompt).groups[0]
    assert g.destination == destination
    assert said in (g.purpose or "").lower()
