"""People "there" where they stay (standing there, the people there) start at the place said just before."""

from __future__ import annotations


def test_sitting_there_after_along_is_the_start(read):
    g = read("mall", "Water leaks along the food court, so the shoppers sitting there are sent out to the car park.").groups
    assert len(g) == 1
    assert g[0].start == "food_court" and "food_court" not in g[0].via


def test_the_people_there_start_there(read):
    g = read("marina", "A rope snaps along pontoon A, so the sailors there are moved to the car park.").groups
    assert len(g) == 1
    assert (g[0].start, g[0].destination) == ("pontoon_a", "car_park")


def test_standing_there_in_the_station(read):
    g = read("station", "A bin catches fire halfway along platform one, so the forty-odd commuters standing there "
                        "are moved back into the booking hall.").groups
    assert len(g) == 1
    assert (g[0].start, g[0].destination, g[0].via) == ("platform_1", "ticket_hall", ())
