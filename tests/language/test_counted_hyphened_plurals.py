"""Round 52 (r52a): a day or time word between a count and a hyphened plural ("fifty Saturday
bargain-hunters", "some twenty evening dog-walkers") keeps the count on the plural
(language/counted_compounds.py `kind_before_hyphened`)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("mall", "About thirty Sunday day-trippers stroll from the atrium to the food hall.", 30),
    ("mall", "Some twenty evening dog-walkers cross from the atrium to the food hall.", 20),
    ("station", "Around forty Friday fun-seekers wander from platform one to the café.", 40),
])
def test_a_day_word_before_a_hyphened_plural_keeps_the_count(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "approximate" and group.count.value == value
