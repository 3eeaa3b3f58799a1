"""A place set apart by whose it is ("the X' lounge") where the world's place of that kind belongs to
others is refused, not read as that place by its head or by meaning; the place's own possessor, or a
synonym of it, still names it."""

import pytest


@pytest.mark.parametrize("world,prompt,refused", [
    ("town_hall", "A clerk walks from the council chamber to the visitors' lounge.", "visitors lounge"),
    ("courthouse", "An usher walks from the jury room to the witnesses' chambers.", "witnesses chambers"),
    ("concert_venue", "Two fans wander from the bar to the guests' lounge.", "guests lounge"),
])
def test_another_possessor_is_refused(read, world, prompt, refused):
    reading = read(world, prompt)
    assert refused in reading.unknown_places
    assert all(g.destination is None for g in reading.groups)


@pytest.mark.parametrize("world,prompt,place", [
    ("town_hall", "A clerk walks from the council chamber to the members' lounge.", "members_room"),
    ("courthouse", "The judge walks from the jury room to the judge's chambers.", "judges_chambers"),
    ("hotel", "A guest walks from the lobby to the residents' bar.", "bar"),
])
def test_the_place_own_possessor_still_names_it(read, world, prompt, place):
    reading = read(world, prompt)
    assert not reading.unknown_places
    assert reading.groups[0].destination == place
