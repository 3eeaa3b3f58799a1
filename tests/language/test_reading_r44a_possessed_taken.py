"""Someone's own person taken along ("pushes the patient's mum in her wheelchair", "wheels Tom's grandad
from ..."): the person after "'s" is the one taken, a second group that follows the taker
(language/possessed_people.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,label,start,destination", [
    ("hotel", "The groom pushes his bride's nan in her wheelchair from the bar to the lobby.", "nan", "bar", "lobby"),
    ("hospital", "A porter pushes the patient's mum in her wheelchair from the cafeteria to ward B.", "mum",
     "cafeteria", "ward_b"),
    ("station", "A guard wheels Tom's grandad from the cafe to platform 2.", "grandad", "cafe", "platform_2"),
])
def test_a_possessed_person_taken_along_follows(read, world, prompt, label, start, destination):
    taker, taken = read(world, prompt).groups
    assert (taker.start, taker.destination) == (start, destination)
    assert (taken.label, taken.count.value, taken.intent, taken.follows) == (label, 1, "follow", taker.who)
    assert (taken.start, taken.destination) == (start, destination)
