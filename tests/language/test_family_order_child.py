"""One child of a family said by their place among them ("our littlest", "My youngest", "their
smallest"), also at the start of a sentence: one person."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("zoo", "Giggling, my littlest runs after the robot past the penguins."),
    ("museum", "My youngest wanders off into the dinosaur gallery."),
    ("aquarium", "Their smallest presses her nose to the glass by the shark tunnel."),
    ("residential", "Our eldest waits in the hallway."),
])
def test_a_family_s_youngest_is_one_person(read, world, prompt):
    groups = read(world, prompt).groups
    assert len(groups) == 1, groups
    assert groups[0].count.value == 1 and groups[0].count.kind in ("exact", "implied"), groups[0]
