"""Round 70 (r70a): a state word before someone wheeled or pushed ("wheels a dozing patient", "pushes
her grizzling toddler in a buggy") keeps that person as a second group that follows
(language/wheeled_states.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "A nurse wheels a dozing patient from ward C to radiology."),
    ("hospital", "Mum pushes her grizzling toddler in a buggy from the cafeteria to the pharmacy."),
    ("mall", "A nanny pushes a sleeping baby in a pram from the food court to the fountain."),
])
def test_the_wheeled_person_follows(read, world, prompt):
    pusher, pushed = read(world, prompt).groups
    assert pusher.intent == "walk" and pushed.intent == "follow" and pushed.count.value == 1
