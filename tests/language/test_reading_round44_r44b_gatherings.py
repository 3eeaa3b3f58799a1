"""Round 44 (r44b): a party said by an everyday word for it ("at a birthday bash", "at the office
shindig", "back from a beano"): people at an event, no place the world lacks to refuse
(language/event_names.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("bowling_alley", "Ten kids at a birthday bash wait by the shoe counter."),
    ("hotel", "A dozen guests at the office shindig drink at the bar."),
    ("brewery", "Eight pensioners at a beano sing in the tap room."),
    ("bowling_alley", "Twelve kids at a birthday bash bowl on the bumper lanes."),
])
def test_a_party_by_an_everyday_word_is_no_unknown_place(read, world, prompt):
    reading = read(world, prompt)
    assert reading.unknown_places == () and len(reading.groups) == 1
