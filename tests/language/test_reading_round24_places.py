"""Round 24 of the reader's places and clauses: a stay said before the sentence's people ("After
twenty minutes minding the cloakroom, ..."), a chat length ("like 15 min", "b4 goin in2 the
boardroom"), and a destination said by "bound for"."""

import pytest


@pytest.mark.parametrize("world,prompt,seconds,destination", [
    ("museum", "After twenty minutes minding the cloakroom, two volunteers wander off to the cafe.", 1200, "cafe"),
    ("office", "After ten minutes waiting in reception, a courier walks to the kitchen.", 600, "kitchen"),
    ("mall", "After half an hour browsing the bookshop, three teenagers head for the fountain.", 1800, "fountain"),
    ("hospital", "After an hour sitting in the waiting room, an old man shuffles off to the pharmacy.", 3600,
     "pharmacy"),
])
def test_a_length_before_the_people_is_a_stay_before_they_go(read, world, prompt, seconds, destination):
    (g,) = read(world, prompt).groups
    assert g.wait_seconds == seconds and g.destination == destination


@pytest.mark.parametrize("world,prompt,seconds,location", [
    ("office", "2 interns chillin in the kitchen like 15 min", 900, "kitchen"),
    ("mall", "3 kids hangin round the fountain like half an hour", 1800, "fountain"),
    ("museum", "couple sittin in the cafe around 20 mins", 1200, "cafe"),
    ("station", "lad waitin @ the departure board like 10 min", 600, "departure_board"),
])
def test_a_chat_length_after_the_place_is_a_stay(read, world, prompt, seconds, location):
    (g,) = read(world, prompt).groups
    assert g.wait_seconds == seconds and g.location == location


@pytest.mark.parametrize("world,prompt,seconds,destination", [
    ("office", "guy sat in reception for 10 mins b4 goin in2 the boardroom", 600, "boardroom"),
    ("mall", "couple sat by the fountain for 5 mins b4 goin in2 the bookshop", 300, "bookshop"),
    ("museum", "2 kids sat in the cafe for 10 mins b4 goin in2 the gift shop", 600, "gift_shop"),
])
def test_chat_into_after_a_stay_is_where_they_go(read, world, prompt, seconds, destination):
    (g,) = read(world, prompt).groups
    assert g.wait_seconds == seconds and g.destination == destination


@pytest.mark.parametrize("world,prompt", [
    ("office", "After the meeting, two managers walk to the kitchen."),
    ("mall", "Two shoppers walk about 5 minutes from the fountain to the bookshop and browse."),
    ("office", "A courier walks to the kitchen after ten minutes."),
])
def test_no_stay_where_none_is_said_before_the_people(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.wait_seconds is None


@pytest.mark.parametrize("world,prompt,destination", [
    ("airport", "A porter pushes a wheelchair through security, bound for gate A1.", "gate_a1"),
    ("airport", "A steward wheels an old man through the concourse, bound for A2.", "gate_a2"),
    ("station", "Two commuters bound for platform 2 hurry across the concourse.", "platform_2"),
])
def test_bound_for_a_place_is_going_to_its_zone(read, world, prompt, destination):
    g = read(world, prompt).groups[0]
    assert g.destination == destination


@pytest.mark.parametrize("world,prompt,location", [
    ("airport", "Three backpackers bound for Paris queue at the check-in desk.", "check_in_hall"),
    ("station", "Five students bound for Leeds queue at the ticket office.", "ticket_office"),
    ("mall", "Four friends bound for Scarborough queue at the cinema.", "cinema_lobby"),
    ("bus_station", "Twelve pensioners bound for Whitby queue at stand A.", "bay_1"),
])
def test_bound_for_a_town_then_a_queue_is_a_queue(read, world, prompt, location):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.intent == "queue" and g.location == location and not r.unknown_places


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("office", "Two cleaners quit the kitchen and retire to the boardroom.", "kitchen", "boardroom"),
    ("museum", "The conductor quits the auditorium and retires to the staff room.", "auditorium", "staff_room"),
    ("hospital", "A porter quits the pharmacy and retires to the main corridor.", "pharmacy", "main_corridor"),
    ("museum", "Two guides quit the cafe and retire to the education room.", "cafe", "education_room"),
])
def test_quitting_a_place_is_leaving_it(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert g.intent == "walk" and g.start == start and g.destination == destination
