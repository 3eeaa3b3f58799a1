"""Round 50 (r50b): a place said by what is done there whose words one room's names say together ("to
where the records get filed": the "records room", the "filing room") is that room, before a thing
elsewhere only near it in meaning (names_say_it.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

_WORLDS = Path(__file__).resolve().parents[2] / "eval" / "understanding" / "worlds"


@pytest.mark.parametrize("world,prompt,destination", [
    ("consulate", "A clerk carries a box of folders from the visa office to where the records get filed.", "records_room"),
    ("data_centre", "An engineer hurries from the loading bay to where the operations get monitored.", "noc"),
    ("library", "A porter wheels a cart of books over to where returns are processed.", "sorting_room"),
])
def test_a_place_said_by_what_is_done_there_in_its_names_words(read, world, prompt, destination):
    (group,) = read(world, prompt).groups
    assert group.destination == destination


@pytest.mark.parametrize("world,activity,zone", [
    ("library", "where you process the returns", "sorting_room"),
    ("consulate", "where they file the records", "records_room"),
    ("parcel_depot", "where the drivers get briefed", "drivers_room"),
])
def test_the_one_zone_whose_names_hold_every_word(world, activity, zone):
    from grove_tui.language.names_say_it import named_by_its_words
    from grove_tui.language.places import place_index
    from grove_tui.world import load_world

    found = named_by_its_words(place_index(load_world(_WORLDS / f"{world}.yaml")), activity)
    assert found is not None and found[0].name == zone


def test_one_word_alone_decides_nothing():
    from grove_tui.language.names_say_it import named_by_its_words
    from grove_tui.language.places import place_index
    from grove_tui.world import load_world

    assert named_by_its_words(place_index(load_world(_WORLDS / "library.yaml")), "where you sort") is None
