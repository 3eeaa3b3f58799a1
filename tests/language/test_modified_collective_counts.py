"""A collective said with a word before it ("the night shift", "the day shift") and then a count set off
by commas ("eleven officers in all", "nine nurses all told") is one group of that many
(language/collectives.py: members_named), not the collective and its members as two groups."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count,destination", [
    ("hospital", "The day shift, nine nurses all told, walks from the ward to the cafeteria.", 9, "cafeteria"),
    ("airport", "The evening shift, a dozen guards in all, walks to the security checkpoint.", 12,
     "security_checkpoint"),
    ("police_station", "The night shift, eleven officers in all, files out of the parade room into the corridor.",
     11, "corridor"),
])
def test_modified_collective_with_apposed_count(read, world, prompt, count, destination):
    reading = read(world, prompt)
    assert len(reading.groups) == 1
    g = reading.groups[0]
    assert g.count.kind == "exact" and g.count.value == count and g.destination == destination
