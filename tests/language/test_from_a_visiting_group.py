"""People "from a visiting rally" / "from a travelling theatre company" say who they are, even when a
participle describes the noun and the verb is "are lining up" (language/who_from.py): nothing to refuse."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count,intent,place", [
    ("hospital", "Three students from a travelling theatre company are lining up at reception.", 3, "queue",
     "reception_desk"),
    ("museum", "A dozen pupils from a visiting school are waiting in the cafe.", 12, "wait", "cafe"),
])
def test_people_from_a_described_group_are_not_refused(read, world, prompt, count, intent, place):
    reading = read(world, prompt)
    (g,) = reading.groups
    assert reading.unknown_places == ()
    assert (g.count.value, g.intent) == (count, intent)
    assert (reading.places, g.location) == ((place,), place)
