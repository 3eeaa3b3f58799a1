"""School years said in chat as the pupils themselves ("12 yr7s", "Y9s", "year 10s") are people, even
in a list of fragments with no verb (language/chat_school_years.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.chat_school_years import with_school_year_pupils
from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

CASES = [
    ("museum", "12 Y9s in the cafe + 2 teachers in the shop", [12, 2]),
    ("museum", "8 year 10s by the shop, 3 parents in the cafe", [8, 3]),
    ("mall", "15 yr8s at the food court + 1 teacher by the fountain", [15, 1]),
]


@pytest.mark.parametrize("world, sentence, counts", CASES)
def test_chat_school_years_are_counted_people(world, sentence, counts):
    reading = read_prompt(sentence, load_world(world))
    assert [g.count.value for g in reading.groups] == counts


@pytest.mark.parametrize("text", ["in the 1990s", "Year 4 walks to the hall", "two years later", "ys"])
def test_other_years_are_left_alone(text):
    assert with_school_year_pupils(text) == text
