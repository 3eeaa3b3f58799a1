"""A rough number said with "-ish" ("the 200-ish fans", "fortyish", "a hundred-ish") is about so many,
after a determiner as well as alone, not a vague few."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("stadium", "The whistle goes, so the 300-ish fans at the gate walk to the exit.", 300),
    ("zoo", "Rain starts, so the fortyish visitors by the penguin pool head for the cafe.", 40),
    ("ice_rink", "a hundred-ish skaters wait at the rink entrance", 100),
    ("cinema", "After the film the 60ish viewers in screen 1 leave through the foyer.", 60),
])
def test_an_ish_count_is_about_so_many(read, world, prompt, value):
    groups = read(world, prompt).groups
    assert len(groups) == 1, groups
    count = groups[0].count
    assert count.kind == "approximate" and count.value == value, count
    assert count.low < value < count.high, count
