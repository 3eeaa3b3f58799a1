"""People "from a visiting rally" / "from a travelling theatre company" say who they are, even when a
participle describes the noun and the verb is "are lining up" (language/who_from.py): nothing to refuse."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count,intent", [
    ("hospital", "Three students from a travelling theatre company are lining up at reception.", 3, "queue"),
    ("museum", "A dozen pupils from a visiting school are waiting in the cafe.", 12, "wait"),
])
def test_people_from_a_described_group_are_not_refused(read, world, prompt, count, intent):
    reading = read(world, prompt)
    (g,) = reading.groups
    assert reading.unknown_places == ()
    assert (g.count.value, g.intent) == (count, intent)
    assert "cafe" in reading.places or "reception" in " ".join(reading.places) or reading.places
