"""A family said by its surname, then how many it is set off by commas ("the Xs, a family of N,"): one group."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("aquarium", "The Kowalskis, a family of four, drift from the shark tunnel to the gift shop.", 4),
    ("botanic_garden", "The Abernathys, a family of six, amble across to the glasshouse cafe.", 6),
    ("museum", "The Fernandes, a family of three, stroll into the dinosaur gallery.", 3),
])
def test_a_surname_family_with_its_size_is_one_group(read, world, prompt, value):
    groups = read(world, prompt).groups
    assert len(groups) == 1, groups
    assert groups[0].count.value == value, groups[0]
