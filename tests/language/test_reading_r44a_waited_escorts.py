"""Someone who waits, then takes another along ("a guide waits in the entrance hall for ten minutes and
then takes six tourists to the cafe"): the taker waits where they are for the time said, then goes from
there to the place, and the taken follow them (language/waited_escorts.py). Said as chat too: a short
role typed bare at the start ("receptionist", "gp", language/role_words.py) and a wait said by a
phrasal verb with its time right after ("hangs on 10 mins", language/stay_particles.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,place,destination,seconds", [
    ("museum", "A guide waits in the entrance hall for ten minutes and then takes six tourists to the cafe.",
     "entrance_hall", "cafe", 600.0),
    ("hotel", "A porter hangs around 5 minutes by the lifts, then wheels a guest to the bar.", "lift_lobby", "bar",
     300.0),
    ("office", "receptionist hangs on 10 mins at reception then takes a visitor to the boardroom", "reception",
     "boardroom", 600.0),
])
def test_the_taken_follow_the_one_who_waited_first(read, world, prompt, place, destination, seconds):
    taker, taken = read(world, prompt).groups
    assert (taker.start, taker.destination, taker.wait_seconds) == (place, destination, seconds)
    assert (taken.intent, taken.follows, taken.destination) == ("follow", taker.who, destination)


@pytest.mark.parametrize("world,prompt,label", [
    ("hospital", "gp waits in the cafeteria", "gp"),
    ("police_station", "pcso hangs on at the front desk", "pcso"),
])
def test_a_short_role_typed_bare_at_the_start_is_a_person(read, world, prompt, label):
    (g,) = read(world, prompt).groups
    assert (g.label, g.count.value, g.intent) == (label, 1, "wait")


def test_a_walk_about_some_minutes_is_no_stay(read):
    (g,) = read("mall", "Two shoppers walk about 5 minutes from the fountain to the bookshop and browse.").groups
    assert g.wait_seconds is None
