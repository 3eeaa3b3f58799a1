"""A place's whole name said exactly beats reading it as a room's name then a kind of thing of that
room: "the hall entrance" of a porch so called is the porch, not the hall's opening."""

import pytest


@pytest.mark.parametrize("world,prompt,role,place", [
    ("food_bank", "Two volunteers carry crates from the hall entrance to the kitchen.", "start", "porch"),
    ("register_office", "A couple walks from the front entrance to the waiting area.", "start", "front_entrance"),
    ("opera_house", "A tenor hurries from the backstage entrance to the dressing rooms.", "start", "stage_door"),
    ("opera_house", "A violinist wanders over to the stage door after the interval.", "destination", "stage_door"),
])
def test_a_place_named_whole_is_that_place(read, world, prompt, role, place):
    (g,) = read(world, prompt).groups
    assert getattr(g, role) == place
