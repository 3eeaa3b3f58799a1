"""A thing said with a word only one room is called by ("the banqueting tables" of the banqueting suite,
"the function tables" of the function room, "the education tables" of the education centre), as the
object of a verb of work no list has ("lay", "wipe down", "set up"): that room's thing is where the
work is done, though another room's things are called "the tables". A room's plural things alike are
its own kind only ("the tables" of a ballroom whose stage is also its "top table"). Real spaCy, real
worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, location", [
    ("hotel", "A porter pushes a cart of suitcases from the bell desk to the lifts, two waiters lay the banqueting "
              "tables, and a bride sits nervously in the honeymoon suite.", "banquet_tables"),
    ("bowling_alley", "Two staff lay the function tables.", "party_tables"),
    ("bowling_alley", "A waitress wipes down the lounge tables.", "high_tables"),
    ("art_gallery", "Two assistants set up the learning tables.", "activity_tables"),
])
def test_the_rooms_thing_is_worked_at(read, world, prompt, location):
    groups = read(world, prompt).groups
    assert any(g.location == location for g in groups)


def test_a_rooms_tables_are_not_its_stage(read):
    assert read("hotel", "Two waiters sit at the banqueting tables.").groups[0].location == "banquet_tables"
