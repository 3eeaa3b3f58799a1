"""Round 44: a place whose name is itself a list, written with commas ("births, deaths and marriages" where
the world says "births deaths and marriages"), is that one place, not the first word refused as a place
the world lacks; a list of several places keeps each of them. (The alias is only in the town hall's world,
so that world is loaded for every sentence here.)"""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("prompt,start,destination", [
    ("An engaged couple walk from the foyer to births, deaths, and marriages to give notice.", "foyer",
     "register_office"),
    ("A clerk hurries out of births, deaths and marriages towards the council chamber.", "register_office",
     "council_chamber"),
])
def test_a_name_written_as_a_list_is_one_place(read, prompt, start, destination):
    reading = read("town_hall", prompt)
    assert reading.unknown_places == ()
    (g,) = reading.groups
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


def test_a_list_of_places_keeps_each(read):
    groups = read("town_hall", "Two residents walk from the foyer to the council chamber, and a clerk waits in the "
                               "register office.").groups
    assert [(g.start, g.destination, g.location) for g in groups] == [
        ("foyer", "council_chamber", None), (None, None, "register_office")]
