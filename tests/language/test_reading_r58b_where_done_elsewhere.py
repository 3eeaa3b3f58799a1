"""A place said by what people do there ("to where members hit buckets of practice balls") is a place,
and its people are no group; gone to *from* a room, it is another room when the clause names that
other place's fixture outright (language/where_elsewhere.py). Held collectives ("with hired clubs",
"his clubs") are things, no second group (language/held_collectives.py). Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, count, start, destination", [
    ("golf_club", "Two juniors with borrowed clubs stroll from the spike bar to where members buy balls and gloves.",
     2, "spike_bar", "pro_shop"),
    ("golf_club", "Two juniors wander from the pro shop to where people grab buckets of range balls and hit them.",
     2, "pro_shop", "driving_range"),
    ("ski_lodge", "Four skiers walk from the boot room to where instructors teach beginners to ski.",
     4, "boot_room", "ski_school"),
])
def test_one_group_to_the_place_described(read, world, prompt, count, start, destination):
    groups = read(world, prompt).groups
    assert [(g.count.value, g.start, g.destination) for g in groups] == [(count, start, destination)]


@pytest.mark.parametrize("world, prompt", [
    ("station", "A golfer with his clubs waits on platform 2."),
    ("campsite", "Two hikers with heavy packs walk from the car park to the shower block."),
])
def test_held_collectives_are_no_group(read, world, prompt):
    assert len(read(world, prompt).groups) == 1


def test_a_club_of_people_is_still_people(read):
    assert read("golf_club", "The golf club meets in the spike bar.").groups[0].count.value > 1
