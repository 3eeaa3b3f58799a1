"""A headless "where" clause names a room by what is done there: a fixture people only use in it (the
café tables, the lunch tables) is not the place meant unless people are served or queue at it."""

import pytest


@pytest.mark.parametrize("world,prompt,place", [
    ("city_farm", "A family wanders off to where people have their picnics.", "cafe"),
    ("care_home", "Two residents shuffle over to where everybody has their dinner.", "dining_room"),
    ("call_centre", "Three agents drift over to where everyone eats their lunch.", "break_room"),
])
def test_where_people_do_it_is_the_room(read, world, prompt, place):
    (g,) = read(world, prompt).groups
    assert g.destination == place


@pytest.mark.parametrize("world,prompt,place", [
    ("cruise_ship", "A dozen retirees amble off the lido deck to where you book trips ashore.", "shore_excursions_desk"),
])
def test_where_people_are_served_is_the_desk(read, world, prompt, place):
    g = read(world, prompt).groups[0]
    assert g.destination == place
