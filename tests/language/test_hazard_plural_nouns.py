"""Round 52 (r52c): a verb of a thing on fire that the parser reads as a plural noun ("Wiring
smoulders behind the desk": "smoulders" a noun, its "-er" like an agent's) names nobody
(hazard_subjects.hazard_word)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,label", [
    ("climbing_centre", "Wiring smoulders behind the shoe hire counter while eight visitors walk out.", "visitor"),
    ("data_centre", "Wiring smoulders behind the operator desks while eight visitors walk out.", "visitor"),
])
def test_a_smouldering_thing_is_nobody(read, world, prompt, label):
    assert [g.label for g in read(world, prompt).groups] == [label]
