"""Round 50 (r50b): a room a named person shuts or tidies before going somewhere in a manner ("hobbles
down to", "plods over to") is where they start; the room is theirs by the world's description
(described_owners.py) and the manner verbs are verbs of walking (manner_walks.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("consulate", "Ingrid Halvorsen shuts her office and hobbles down to the waiting room.",
     "consul_office", "waiting_hall"),
    ("tennis_club", "Alan Reeve tidies his room and plods over to the bar.", "committee_room", "bar_lounge"),
    ("cookery_school", "The head tutor locks the staff office and scurries over to the pastry room.",
     "staff_office", "pastry_room"),
])
def test_own_room_left_in_a_manner_is_where_they_start(read, world, prompt, start, destination):
    (group,) = read(world, prompt).groups
    assert (group.intent, group.start, group.destination) == ("walk", start, destination)
