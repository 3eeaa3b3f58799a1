"""Round 58 (r58c): a titled person's "-s" verb the parser takes for a plural noun before a gerund
("while the senior curator practises sketching in ...") is the person's verb: one person there, not
an unnamed crowd (language/gerund_verbs.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts,places", [
    ("museum", "While the senior curator practises sketching in the cafe, the robot fetches the post.",
     [1], ["cafe"]),
    ("hospital", "While the head porter practises whistling in the canteen, the robot takes the post to the "
                 "pharmacy.", [1], ["cafeteria"]),
    ("golf_club", "While the junior captain practises chipping on the putting green, three members wait at "
                  "the first tee.", [1, 3], ["putting_green", "first_tee"]),
])
def test_a_titled_persons_verb_before_a_gerund_is_a_verb(read, world, prompt, counts, places):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == counts
    assert [g.location for g in groups] == places
