"""Round 59 (r59a): a counted school year typed as chat ("9 yr 5 kids in the hall, teacher at door") is one
group of that count, and the bare role after a comma another; chat's "yr" before anything but a year's
figure is left alone (language/chat_years.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts", [
    ("primary_school", "9 yr 5 kids in the hall, teacher at door", [9, 1]),
    ("museum", "15 yr 8 pupils @ the whale, guide by t rex", [15, 1]),
    ("primary_school", "six yr 2 children in the hall", [6]),
])
def test_a_counted_school_year_in_chat_is_its_own_group(read, world, prompt, counts):
    reading = read(world, prompt)
    assert [g.count.value for g in reading.groups] == counts


def test_chat_years_writes_out_only_years():
    from grove_tui.language.chat_years import chat_years

    assert chat_years("12 yr 6 kids") == "12 year 6 kids"
    assert chat_years("tell yr mum") == "tell yr mum"
    assert chat_years("12 yr7s in the hall") == "12 yr7s in the hall"
    assert chat_years("a 5 yr old") == "a 5 year old"
