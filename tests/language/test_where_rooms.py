"""Round 54 (r54b): a headless "where" clause names a room by what is done there ("to where people drop
their coats off", "where they paint the flats"); the thing handled is often a fixture's name, but the
room whose description or names say the clause's words is the place (language/where_rooms.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination", [
    ("nightclub", "A couple stroll from the bar to where people drop their coats off.", "cloakroom"),
    ("playhouse", "Two stagehands walk over to where they paint the flats.", "scene_dock"),
    ("brewery", "A brewer wanders over to where they rack the casks.", "cask_cellar"),
])
def test_a_where_clause_names_the_room_not_the_thing_handled(read, world, prompt, destination):
    (group,) = read(world, prompt).groups
    assert group.destination == destination
