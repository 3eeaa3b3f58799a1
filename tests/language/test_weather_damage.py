"""Strong wind or a storm that damages the place people are in is a hazard: people who hurry or run out
after it evacuate. Wind that only picks up damages nothing: people who leave then walk (the labels of the
earlier sets). Real spaCy, real worlds and the eval worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start", [
    ("tennis_club", "A squall blows the awning down over the indoor courts and the ten players there hurry out "
     "through the west exit.", "indoor_courts"),
    ("county_show", "A gale rips the roof of the craft tent and the twenty people in it run out onto the avenue.",
     "craft_tent"),
    ("county_show", "A gale tears the side of the craft tent and the twenty people inside run out onto the avenue.",
     "craft_tent"),
    ("mall", "A storm tears part of the roof off the food court and the thirty diners there run outside.", "food_court"),
])
def test_people_leaving_a_place_the_weather_damages_evacuate(read, world, prompt, start):
    group = read(world, prompt).groups[0]
    assert group.intent == "evacuate"
    assert group.start == start


def test_wind_that_only_picks_up_is_no_hazard(read):
    group = read("tennis_club", "With the wind picking up, the ten players on the indoor courts walk out through "
                 "the west exit.").groups[0]
    assert group.intent == "walk"


def test_the_damaging_weather_is_nobody(read):
    groups = read("county_show", "The wind tears the side of the craft tent and the twenty people inside run out "
                  "onto the avenue.").groups
    assert [g.count.value for g in groups] == [20]
