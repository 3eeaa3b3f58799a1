"""Pupils named by their school year in words ("Year Sixes", "year tens", "the Year Elevens") are that
many pupils: the year is no multiplier of the count before it."""

import pytest


@pytest.mark.parametrize("world,prompt,kind,value", [
    ("primary_school", "Twenty Year Tens walk from the hall to the library.", "exact", 20),
    ("primary_school", "A handful of year twos wait outside the hall.", "vague", None),
    ("library", "Twelve Year Sevens shuffle in and sit down in the reading room.", "exact", 12),
])
def test_a_year_in_words_names_pupils(read, world, prompt, kind, value):
    (group,) = read(world, prompt).groups
    assert group.count.kind == kind and group.label == "pupil"
    if value is not None:
        assert group.count.value == value
