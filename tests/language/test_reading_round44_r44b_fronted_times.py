"""Round 44 (r44b): a time said first with no comma before the subject ("After lunch an elderly couple
walk ...", "Before the match a few fans gather ..."): the subject is its own phrase, counted as said,
not run into the time phrase and lost (language/fronted_time_commas.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,kind,value", [
    ("hotel", "After lunch an elderly couple walk to the spa.", "implied", 2),
    ("museum", "Before closing a young couple wander from the cafe to the gift shop.", "implied", 2),
    ("stadium", "Before the match a few fans gather at the turnstiles.", "vague", None),
    ("hotel", "At teatime the two guests wander over to the bar.", "exact", 2),
])
def test_a_subject_after_a_fronted_time_keeps_its_count(read, world, prompt, kind, value):
    (group,) = read(world, prompt).groups
    assert group.count.kind == kind and (value is None or group.count.value == value)
    assert group.who.split()[0].lower() in ("a", "an", "the")


def test_a_place_said_first_is_no_time(read):
    (group,) = read("hospital", "At the service desk a porter waits.").groups
    assert group.count.value == 1
