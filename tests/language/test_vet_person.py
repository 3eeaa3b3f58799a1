"""Round 70 (r70a): "the vet" is a person, also in a world whose rooms are named after vets ("vet
room", "vet clinic"): a fronted while-clause's vet stays a group (language/lexicon.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("animal_shelter", "The vet waits in the treatment room."),
    ("animal_shelter",
     "While the vet looks over a kitten in the vet room, three volunteers walk from the cattery to the paddock."),
    ("pet_superstore", "The vet lingers by the tills."),
])
def test_the_vet_is_a_person(read, world, prompt):
    groups = read(world, prompt).groups
    assert any(g.label == "vet" and g.count.value == 1 for g in groups)
