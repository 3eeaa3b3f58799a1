"""Clause classes of round 32, each with sentences of its own over at least two worlds (none from the
understanding sets): a purpose with its place said after going off; surprise at the robot said after a
comma, with the occasion; an errand with a thing carried from one place to another; a counted group's
stay in chat shorthand (counted_chat_waits.py)."""

from __future__ import annotations

import pytest


# ---- 1. a purpose with its place, said after going off -------------------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("hospital", "Two nurses sneak off for a coffee in the cafeteria.", "cafeteria"),
    ("mall", "Three shop workers pop out for a smoke by the fountain.", "fountain"),
    ("station", "A guard goes for lunch in the cafe.", "cafe"),
    ("library", "Of six students at the reading tables, two slip off for a snack in the cafe.", "cafe"),
    ("post_office", "Two clerks nip off for a brew in the canteen.", "canteen"),
])
def test_a_purpose_had_at_a_place_is_where_they_go(read, world, prompt, destination):
    g = read(world, prompt).groups[-1]
    assert (g.intent, g.destination) == ("walk", destination)
    assert g.start != destination


def test_waiting_for_something_at_a_place_stays_there(read):
    (g,) = read("hospital", "Two nurses wait for a coffee in the cafeteria.").groups
    assert (g.intent, g.location) == ("wait", "cafeteria")
    (g,) = read("mall", "A boy queues for an ice cream at the food court.").groups
    assert g.destination != "food_court" or g.intent == "queue"


# ---- 2. surprise at the robot after a comma, with its occasion -----------------------------------------

@pytest.mark.parametrize("world,prompt,interaction", [
    ("mall", "Two teens by the fountain walk up to the robot, surprised to see it at a wedding.", "approach"),
    ("hospital", "A visitor near the pharmacy edges towards the robot, amazed to find one at the match.", "approach"),
    ("stadium", "A steward at the turnstiles wanders over to the robot, astonished to see it at a game.", "approach"),
    ("concert_venue", "Three fans by the bar run up to the robot, surprised to spot it at a concert.", "approach"),
])
def test_surprise_after_a_comma_reads_surprised(read, world, prompt, interaction):
    r = read(world, prompt)
    (g,) = r.groups
    assert (g.robot_interaction, g.robot_reaction) == (interaction, "Surprised")
    assert r.unknown_places == ()


@pytest.mark.parametrize("world,prompt,unknown", [
    ("mall", "A man at the fountain stops by the robot, surprised to see it at a wedding.", "wedding"),
    ("station", "Three lads at the newsagent gawp at the robot, surprised to see it at a gig.", "gig"),
    ("airport", "A boy at gate A1 walks up to the robot, amazed to see one at a gig.", "gig"),
    ("hospital", "A nurse by the pharmacy looks at the robot, shocked to find it at a wedding.", "wedding"),
])
def test_the_occasion_of_a_surprise_is_no_unknown_place(read, world, prompt, unknown):
    assert unknown not in read(world, prompt).unknown_places


def test_a_place_or_an_occasion_said_elsewhere_keeps_its_reading(read):
    assert "show" not in read("station", "Two girls by the newsagent stare at the robot, startled to see it during "
                                         "the show.").unknown_places
    assert "wedding" in read("mall", "A man walks from the fountain to the wedding.").unknown_places


def test_a_curious_approach_stays_curious(read):
    (g,) = read("mall", "Two teens walk up to the robot at the fountain.").groups
    assert g.robot_reaction == "Curious"
    (g,) = read("station", "A kid runs over to the robot, keen to see it.").groups
    assert g.robot_reaction == "Curious"


# ---- 3. an errand with a thing carried from one place to another ----------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("post_office", "The manager takes the cash bags from the strong room through to the counter.",
     "strong_room", "post_office_counter"),
    ("library", "A librarian takes the post from the issue desk across to the cafe.", "issue_desk", "cafe"),
    ("post_office", "A clerk takes the parcels from the sorting office through to the collection counter.",
     "sorting_office", "collection_counter"),
    ("mall", "A cleaner takes the post from the food court across to the fountain.", "food_court", "fountain"),
])
def test_a_thing_carried_from_place_to_place_is_a_walk(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


def test_carried_errands_already_read_keep_their_reading(read):
    (g,) = read("library", "A volunteer brings the post over from the issue desk to the cafe.").groups
    assert (g.intent, g.start, g.destination) == ("walk", "issue_desk", "cafe")
    (g,) = read("hospital", "A porter takes the notes from the pharmacy through to the cafeteria.").groups
    assert (g.intent, g.start, g.destination) == ("walk", "pharmacy", "cafeteria")
    (g,) = read("station", "A guard takes the keys over to the ticket office from the waiting room.").groups
    assert (g.intent, g.start, g.destination) == ("walk", "waiting_room", "ticket_office")


# ---- 4. a counted group's stay in chat shorthand, its time and its place ----------------------------------

@pytest.mark.parametrize("world,prompt,start,seconds,destination", [
    ("mall", "2 teens @ fountain 5 mins then off to food court", "fountain", 300.0, "food_court"),
    ("station", "4 ppl browsing newsagent 3 mins then off to platform 1", "newsagent", 180.0, "platform_1"),
    ("hospital", "two nurses chattin at pharmacy 10 mins then back to cafeteria", "pharmacy", 600.0, "cafeteria"),
    ("garden_centre", "5 ppl lookin at orchids 4 mins then off to tills", "orchid_table", 240.0, "tills"),
])
def test_a_counted_chat_stay_starts_there_waits_then_goes(read, world, prompt, start, seconds, destination):
    g = read(world, prompt).groups[0]
    assert (g.start, g.wait_seconds, g.destination) == (start, seconds, destination)


def test_one_persons_chat_wait_keeps_its_reading(read):
    (g,) = read("library", "guard @ issue desk 2 mins then off to cafe").groups
    assert (g.start, g.wait_seconds, g.destination) == ("issue_desk", 120.0, "cafe")
