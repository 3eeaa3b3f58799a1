"""Round 54 (r54a): in a chat list of counted people ("approx N <people> @ X, M <doers> in Y rm"), a word
for a doer the reader otherwise takes for a thing ("speakers": loudspeakers) is people too
(language/chat_list_items.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts", [
    ("hotel", "about 20 guests in the bar, 2 speakers by the lifts", [20, 2]),
    ("convention_centre", "approx 80 delegates @ plenary hall, 3 speakers in green rm", [80, 3]),
    ("hospital", "approx 30 visitors in the canteen, 2 presenters at reception", [30, 2]),
])
def test_a_doer_counted_in_a_list_of_people_is_a_group(read, world, prompt, counts):
    assert [g.count.value for g in read(world, prompt).groups] == counts
