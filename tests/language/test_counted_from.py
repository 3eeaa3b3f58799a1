"""Round 58 (r58c): a count with an article and no noun before "from" ("the four from accounts",
"those two from the day ward") counts people, as the bare "three from sales" does
(language/chat_fragments.with_counted_from)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts,places", [
    ("office", "The four from accounts chat in the kitchen.", [4], ["kitchen"]),
    ("office", "While the three from sales queue at the reception desk, the robot fetches the post.", [3],
     ["reception_desk"]),
    ("hospital", "Those two from the day ward wait at the pharmacy and a porter mops the main corridor.", [2, 1],
     ["pharmacy", "main_corridor"]),
    ("library", "The two from the chess club argue in the reading room.", [2], ["reading_room"]),
])
def test_a_count_with_an_article_before_from_counts_people(read, world, prompt, counts, places):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == counts
    assert [g.location for g in groups] == places
