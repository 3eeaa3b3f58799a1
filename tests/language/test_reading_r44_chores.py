"""Round 44: people who come somewhere and then do a chore there ("come in through the back door and mop
the corridor") walk there; the chore alone ("a cleaner mops the kitchen") is going about the room."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("office", "Two porters come in through the main entrance and sweep the reception area.", "main_entrance",
     "reception"),
    ("hospital", "A cleaner walks over from the lifts and mops the main corridor.", "elevator_hall", "main_corridor"),
    ("community_centre", "Early on the caretaker comes in by the back door and hoovers the corridor.",
     "kitchen_back_door", "corridor"),
])
def test_coming_to_do_a_chore_is_walking_there(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


@pytest.mark.parametrize("world,prompt,where", [
    ("office", "A cleaner mops the kitchen.", "kitchen"),
    ("hospital", "Two cleaners sweep the main corridor.", "main_corridor"),
])
def test_a_chore_alone_is_going_about_the_room(read, world, prompt, where):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.location) == ("wander", where)
