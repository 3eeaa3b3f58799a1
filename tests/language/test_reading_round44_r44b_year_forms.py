"""Round 44 (r44b): a school year said with a word for its class after the number ("the Year 4 form",
"the year 6 group", "the Year 5 set"): the class itself, read as "Year 4" is, so a count set off by
commas after it ("..., twenty-six youngsters all told, ...") says how many it is (one group), and the
year's number is no count of its own (language/school_classes.py, mentions.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count,start,destination", [
    ("primary_school", "The Year 2 form, twenty-eight children all told, walks from the hall to the playground.", 28,
     "school_hall", "playground"),
    ("museum", "The Year 6 group, thirty pupils in all, troops from the cloakroom to the dinosaur gallery.", 30,
     "cloakroom", "dinosaur_gallery"),
    ("primary_school", "The Year 5 set, twelve pupils altogether, heads from the playground to the library.", 12,
     "playground", "library"),
])
def test_a_year_said_with_its_class_word_takes_the_count_in_apposition(read, world, prompt, count, start, destination):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("exact", count)
    assert (group.start, group.destination) == (start, destination)


def test_a_year_form_alone_is_a_whole_class(read):
    (group,) = read("museum", "The Year 9 form walks to the cafe.").groups
    assert group.count.kind == "vague" and group.count.value >= 20
