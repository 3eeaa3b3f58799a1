"""Round 44 (r44b): a place whose name is a list, said with its commas ("through to births, deaths and
marriages", "to Births, Deaths & Marriages"): one of the world's names once its commas are left out, so
the place is read, not its first word refused (language/comma_names.py). Of the understanding worlds only
the town hall has such a name (its register office); other worlds' names stay as they are."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("prompt,intent", [
    ("Two couples wander from the main entrance over to births, deaths and marriages.", "walk"),
    ("A young dad heads to Births, Deaths & Marriages with his paperwork.", "walk"),
    ("An usher waits at births, deaths and marriages for the wedding party.", "wait"),
])
def test_a_listed_name_said_with_commas_is_the_place(read, prompt, intent):
    reading = read("town_hall", prompt)
    assert reading.unknown_places == ()
    group = reading.groups[0]
    assert group.intent == intent and "register_office" in (group.destination, group.location)


def test_a_list_of_people_keeps_its_commas(read):
    reading = read("mall", "A dad, a mum and a kid sit in the food court.")
    assert len(reading.groups) == 3
