"""Place classes of round 9, each with sentences of its own over at least two worlds (none from the
understanding sets): a topic or a feeling after a place preposition is no place ("argue about a bug",
"bursts into tears"); "outside X" is the zone X's door opens onto; a robot's places after the thing it
carries; a place described by what is done there beats a shared head noun; a person's own room by who
they are."""

from __future__ import annotations

import pytest


def place_of(group):
    return group.destination or group.location or group.start


# ---- A. a topic or a feeling is no place ---------------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("library", "Two students argue about a bug in the reading room."),
    ("library", "Two staff talk about the weather at the issue desk."),
    ("library", "A child breaks into laughter in the reading room."),
    ("sports_centre", "A girl bursts into tears at the pool."),
    ("sports_centre", "Two teens get into trouble in the gym."),
    ("hotel", "Two porters gossip about a famous guest in the lobby."),
])
def test_a_topic_or_a_feeling_is_never_an_unknown_place(read, world, prompt):
    r = read(world, prompt)
    assert r.unknown_places == ()
    assert place_of(r.groups[0]) is not None


@pytest.mark.parametrize("world,prompt", [
    ("sports_centre", "Three swimmers walk into the sauna."),
    ("library", "Two readers wander into the planetarium."),
])
def test_a_missing_room_after_into_is_still_refused(read, world, prompt):
    assert read(world, prompt).unknown_places != ()


# ---- C. a robot's places after the thing it carries ----------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hotel", "The robot takes clean sheets from the laundry to the spa.", "laundry", "spa"),
    ("library", "The robot takes a box of books from the sorting room to the reading room.", "sorting_room",
     "reading_room"),
    ("sports_centre", "The robot takes spare towels from the staff room to the pool.", "staff_room", "pool_hall"),
])
def test_a_robot_carrying_a_thing_from_one_place_to_another(read, world, prompt, start, destination):
    robot = read(world, prompt).robot
    assert (robot.start, robot.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt,place", [
    ("sports_centre", "Two girls buy crisps from the vending machines.", "vending_machines"),
    ("library", "A student takes a book from the stacks.", "stacks"),
])
def test_what_is_got_from_a_place_is_still_got_there(read, world, prompt, place):
    g = read(world, prompt).groups[0]
    assert place_of(g) == place


# ---- D. a place described by what is done there, by the world's descriptions ---------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("university", "A student goes to the office where forms get signed.", "school_office"),
    ("library", "A volunteer walks to the office where returned books are put on trolleys.", "sorting_room"),
    # the students' union desk is the students' own, but no office, and its description does not say it
    ("university", "A student heads to the office where students get forms signed.", "school_office"),
])
def test_a_described_office_is_the_one_whose_description_says_it(read, world, prompt, place):
    r = read(world, prompt)
    assert r.unknown_places == ()
    assert place_of(r.groups[0]) == place


# ---- E. a person's own room by who they are ------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("residential", "Little Sam walks to his bedroom.", "child_bedroom"),
    ("residential", "Baby Amy sleeps in her room.", "child_bedroom"),
    ("museum", "Little Ben runs off to his workshop.", "education_room"),
])
def test_a_first_name_after_little_or_baby_is_a_child_who_owns_the_childs_room(read, world, prompt, place):
    assert place_of(read(world, prompt).groups[0]) == place


@pytest.mark.parametrize("world,prompt,place", [
    ("residential", "Dad walks to his bedroom.", "master_bedroom"),
    ("hotel", "Two honeymooners relax in their suite.", "garden_suite"),
])
def test_an_adults_own_room_is_still_theirs(read, world, prompt, place):
    assert place_of(read(world, prompt).groups[0]) == place
