""""Something like forty", "smth like 6", "somewhere around 30", "in the region of 80" (round 71): an
approximate count, as "about" is."""

from __future__ import annotations

import pytest

CASES = [
    ("airport", "Something like forty backpackers queue at security.", 40),
    ("museum", "smth like 6 kids in the cafe", 6),
    ("hospital", "In the region of 80 visitors wait in the lobby.", 80),
    ("library", "Somewhere around 30 students study in the reading room.", 30),
]


@pytest.mark.parametrize(("world", "prompt", "value"), CASES)
def test_an_approximate_count(read, world, prompt, value):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert groups[0].count.kind == "approximate" and groups[0].count.value == value
