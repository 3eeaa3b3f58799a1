"""A count written in words ("a dozen", "half a dozen") after a fronted phrase of time is the subject's
count, as digits and "twelve" already are."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt


@pytest.mark.parametrize("world,prompt,kind,value", [
    ("airport", "At noon a dozen pilots walk from gate A1 to the café.", "exact", 12),
    ("hospital", "At visiting time half a dozen relatives head from the lobby to ward C.", "exact", 6),
    ("office", "In the morning a dozen devs walk from reception to the kitchen.", "exact", 12),
    ("mall", "After lunch a dozen shoppers queue at the pharmacy.", "exact", 12),
    ("station", "At midnight about a dozen students wait on platform 1.", "approximate", 12),
])
def test_a_worded_count_after_a_fronted_time_phrase_is_kept(worlds, world, prompt, kind, value):
    (group,) = read_prompt(prompt, worlds[world]).groups
    assert (group.count.kind, group.count.value) == (kind, value)
