"""Round 49 (r49b): an adverb and a participle between a count and its people ("six newly jabbed
nurses", "seven freshly showered guests") keep the count exact, however the participle is tagged
(language/adverbed_participles.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("hospital", "Six newly jabbed nurses wait in the canteen.", 6),
    ("hotel", "Seven freshly showered guests wait at the bar.", 7),
    ("hotel", "Four freshly tattooed guests wait at the bar.", 4),
    ("vaccination_centre", "Eight freshly jabbed pensioners shuffle out of the booths into the obs area.", 8),
])
def test_a_count_before_an_adverb_and_participle_is_exact(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "exact" and group.count.value == value
