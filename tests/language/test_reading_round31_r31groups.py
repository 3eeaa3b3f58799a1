"""Group classes of round 31, each with sentences of its own over at least two worlds (none from the
understanding sets): a middle item of a list whose people push something ("a few porters wheel beds");
an order to set someone to work at a post ("Have Janet man the desk"); a gathering named as the time of
the rest ("when the chess club is over"); a thing of someone's in a describing clause with its verb
left out ("and his photo taken")."""

from __future__ import annotations

import pytest


# ---- 1. a list's middle item whose people push something ------------------------------------------------

@pytest.mark.parametrize("world,prompt,who,start,destination", [
    ("mall", "A guard lingers at the ATM, a few mums wheel prams from the atrium into the toy shop, and a teenager "
     "sits on the benches.", "a few mums", "main_atrium", "toy_store"),
    ("hospital", "A nurse waits at the pharmacy, a few porters wheel beds from the lobby to radiology, and a visitor "
     "sits in the cafeteria.", "a few porters", "entrance_lobby", "radiology"),
    ("hospital", "A nurse waits at the pharmacy, two tired porters wheel beds from the lobby to radiology, and a "
     "visitor sits in the cafeteria.", "two tired porters", "entrance_lobby", "radiology"),
    ("airport", "A pilot waits at gate A1, a few travellers wheel cases from check-in to security, and a cleaner "
     "mops the lounge.", "a few travellers", "check_in_hall", "security_checkpoint"),
])
def test_a_middle_item_pushing_something_is_its_own_group(read, world, prompt, who, start, destination):
    groups = read(world, prompt).groups
    assert len(groups) == 3
    g = groups[1]
    assert (g.who, g.intent, g.start, g.destination) == (who, "walk", start, destination)
    assert groups[0].destination is None


@pytest.mark.parametrize("world,prompt,who", [
    ("hospital", "A nurse waits at the pharmacy, two porters wheel beds from the lobby to radiology, and a visitor "
     "sits in the cafeteria.", "two porters"),
    ("airport", "A pilot waits at gate A1, two young travellers drag suitcases from check-in to security, and a "
     "cleaner mops the lounge.", "two young travellers"),
    ("supermarket", "A cashier waits at the tills, a few shoppers steer trolleys from the entrance to the bakery, "
     "and a child sits on the bench.", "a few shoppers"),
    ("supermarket", "A cashier waits at the tills, a couple of young dads wheel buggies from the entrance to the "
     "bakery, and a child sits on the bench.", "a couple of young dads"),
])
def test_a_middle_item_already_read_keeps_its_group(read, world, prompt, who):
    groups = read(world, prompt).groups
    assert len(groups) == 3 and groups[1].who == who and groups[1].intent == "walk"


# ---- 2. an order to set someone to work at a post --------------------------------------------------------

@pytest.mark.parametrize("world,prompt,who,location,others", [
    ("hotel", "Have Janet man the front desk while two contractors perch on the waiting sofa.", "Janet",
     "reception_desk", 1),
    ("library", "Get Sam to staff the issue desk while three students browse the shelves.", "Sam", "issue_desk", 1),
    ("mall", "Have Dave mind the information desk while some shoppers browse the food court.", "Dave",
     "information_desk", 1),
    ("hospital", "Get Tom to cover the pharmacy counter, and a porter wheels a bed to radiology.", "Tom",
     "pharmacy_counter", 1),
    ("supermarket", "Get Priya to staff the tills.", "Priya", "checkouts", 0),
])
def test_an_order_to_work_a_post_puts_the_worker_there(read, world, prompt, who, location, others):
    groups = read(world, prompt).groups
    assert len(groups) == 1 + others
    assert (groups[0].who, groups[0].count.value, groups[0].location) == (who, 1, location)


def test_an_order_without_a_work_verb_is_left_alone(read):
    groups = read("supermarket", "Have two cashiers staff the tills while a shopper waits at customer service.").groups
    assert [(g.who, g.location) for g in groups] == [("two cashiers", "checkouts"), ("a shopper", "customer_service")]
    groups = read("supermarket", "Have the robot watch the tills while two shoppers queue at customer service.").groups
    assert [g.who for g in groups] == ["two shoppers"]


# ---- 3. a gathering named as the time of the rest -------------------------------------------------------

@pytest.mark.parametrize("world,prompt,who", [
    ("community_centre", "After the toddler group, a cleaner mops the main hall.", "a cleaner"),
    ("library", "Once the chess club is over, a student heads to the issue desk.", "a student"),
    ("hospital", "When the support group ends, two visitors walk to the cafeteria.", "two visitors"),
    ("mall", "After the kids club, a dad walks to the food court.", "a dad"),
    ("community_centre", "When the youth club finishes, a caretaker strolls into the main hall.", "a caretaker"),
])
def test_a_gathering_that_ends_is_no_group(read, world, prompt, who):
    assert [g.who for g in read(world, prompt).groups] == [who]


def test_a_gathering_that_does_something_is_still_a_group(read):
    groups = read("library", "A reading group meets in the reading room while a librarian waits at the issue desk.").groups
    assert [g.who for g in groups] == ["A reading group", "a librarian"]
    groups = read("library", "When the book club members leave, a librarian tidies the reading room.").groups
    assert len(groups) == 2


# ---- 4. a thing of someone's in a describing clause with its verb left out --------------------------------

@pytest.mark.parametrize("world,prompt,who", [
    ("consulate", "A student heads for the room where her fingerprints are scanned and her picture taken.",
     "A student"),
    ("consulate", "A student heads for the room where her bags are scanned and her coat taken.", "A student"),
    ("hospital", "A patient walks to the room where his blood is taken and his photo taken.", "A patient"),
    ("hospital", "A patient walks to the room where his arm is bandaged and his temperature taken.", "A patient"),
])
def test_a_thing_done_to_someone_is_no_group(read, world, prompt, who):
    assert [g.who for g in read(world, prompt).groups] == [who]


def test_a_person_done_to_in_such_a_clause_is_kept(read):
    groups = read("hospital", "A nurse waits at the pharmacy, and his son taken to the cafeteria by a porter.").groups
    assert any("son" in g.who for g in groups)


# ---- 5. a person typed bare as an item of a chat list ---------------------------------------------------

@pytest.mark.parametrize("world,prompt,whos,places", [
    ("car_showroom", "couple checking out the hatchback, sales guy hovering nr the brochure stand",
     ["a couple", "a sales guy"], [None, "brochure_stand"]),
    ("hospital", "nurse at pharmacy, two visitors sitting in the cafeteria", ["a nurse", "two visitors"],
     ["pharmacy", "cafeteria"]),
    ("hospital", "couple waiting at pharmacy, porter hovering near the lifts", ["a couple", "a porter"],
     ["pharmacy", "elevator_hall"]),
    ("mall", "guard by the fountain, 3 teens loitering at the food court", ["a guard", "3 teens"],
     ["fountain", "food_court"]),
    ("mall", "two teens at the fountain, guard watching nr the info desk", ["two teens", "a guard"],
     ["fountain", "information_desk"]),
])
def test_a_bare_person_in_a_chat_list_is_a_group(read, world, prompt, whos, places):
    groups = read(world, prompt).groups
    assert [g.who for g in groups] == whos
    assert [g.location for g in groups][1:] == places[1:]


def test_people_written_out_keep_their_reading(read):
    groups = read("hospital", "A nurse waits at the pharmacy, and two visitors sit in the cafeteria.").groups
    assert [g.who for g in groups] == ["A nurse", "two visitors"]
    groups = read("hospital", "staff at the pharmacy, two visitors sitting in the cafeteria").groups
    assert groups[-1].who == "two visitors"
    groups = read("mall", "Nurse Patel waits by the fountain, and 3 teens loiter at the food court.").groups
    assert [g.who for g in groups] == ["Nurse Patel", "3 teens"]
