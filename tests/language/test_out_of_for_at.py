"""Going out of a place for something at another ("duck out of X for Y at Z", issue 29): they walk from
X to Z, where the purpose is had; "duck" with a particle is going, not dodging. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, goal", [
    ("hospital", "Two porters pop out of the ward for a smoke at the main entrance.", "main_entrance"),
    ("library", "Three students nip out of the reading room for a bite at the café.", "cafe"),
    ("hospital", "A couple of nurses duck out of the ward for a sandwich at the cafeteria.", "cafeteria"),
])
def test_out_of_a_place_for_something_at_another_goes_there(read, world, prompt, goal):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.destination) == ("walk", goal)
