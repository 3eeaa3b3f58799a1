"""Group classes of round 32, each with sentences of its own over at least two worlds (none from the
understanding sets): a fronted participle that moves someone ("Wheeling his gran out, a man ..."); a
gathering that ends before the people said after it ("When the reading group finishes, three ...");
work at a post said with a progressive or with "run" ("Janet is manning the desk")."""

from __future__ import annotations

import pytest


# ---- 1. a fronted participle that moves someone -----------------------------------------------------

@pytest.mark.parametrize("world,prompt,who,moved,start,destination", [
    ("hospital", "Pushing his gran's wheelchair, a teenager brings her from the lobby to the cafeteria.",
     "A teenager", "his gran", "entrance_lobby", "cafeteria"),
    ("hospital", "Wheeling a patient out, a porter walks from the lobby to radiology.", "A porter", "a patient",
     "entrance_lobby", "radiology"),
    ("mall", "Pushing her son's buggy, a mum walks from the atrium to the food court.", "A mum", "her son",
     "main_atrium", "food_court"),
    ("museum", "Guiding an elderly visitor, a volunteer walks from the entrance to the cafe.", "A volunteer",
     "an elderly visitor", None, "cafe"),
    ("art_gallery", "Escorting a school group, two teachers take them from the cloakroom to the Impressionist "
     "gallery.", "Two teachers", "a school group", "cloakroom_counter", "impressionist_gallery"),
    ("airport", "Helping an old man, a steward walks from check-in to security.", "A steward", "an old man",
     "check_in_hall", "security_checkpoint"),
])
def test_the_person_moved_by_a_fronted_participle_goes_along(read, world, prompt, who, moved, start,
                                                             destination):
    groups = read(world, prompt).groups
    assert [g.who for g in groups] == [who, moved]
    assert (groups[0].intent, groups[1].intent) == ("walk", "follow")
    assert groups[1].destination == groups[0].destination == destination
    if start is not None:
        assert groups[0].start == start


@pytest.mark.parametrize("world,prompt,who", [
    ("hospital", "Pushing a trolley, a porter walks from the lobby to radiology.", "A porter"),
    ("hospital", "Leading the way, a nurse walks to radiology.", "a nurse"),
    ("airport", "Pulling a suitcase, a traveller walks from check-in to security.", "A traveller"),
    ("mall", "Pushing an empty pram, a dad strolls to the food court.", "A dad"),
])
def test_a_thing_moved_by_a_fronted_participle_is_no_group(read, world, prompt, who):
    groups = read(world, prompt).groups
    assert len(groups) == 1 and groups[0].who.lower() == who.lower() and groups[0].intent == "walk"


# ---- 2. a gathering that ends before the people said after it -----------------------------------------

@pytest.mark.parametrize("world,prompt,who,destination", [
    ("library", "When the reading group finishes, two pensioners walk to the cafe.", "two pensioners", "cafe"),
    ("library", "Once the chess club finishes, a student heads to the issue desk.", "a student", "issue_desk"),
    ("hospital", "When the reading group finishes, three patients walk to the cafeteria.", "three patients",
     "cafeteria"),
    ("mall", "When the chess club finishes, two dads walk to the food court.", "two dads", "food_court"),
])
def test_the_people_after_an_ending_gathering_are_the_group(read, world, prompt, who, destination):
    groups = read(world, prompt).groups
    assert [(g.who, g.destination) for g in groups] == [(who, destination)]


def test_a_gathering_with_its_count_said_is_still_a_group(read):
    groups = read("library", "The reading group, three pensioners, walk to the cafe.").groups
    assert [(g.who, g.count.value) for g in groups] == [("The reading group", 3)]
    groups = read("library", "A reading group meets in the reading room while a librarian waits at the issue desk.").groups
    assert [g.who for g in groups] == ["A reading group", "a librarian"]


# ---- 3. work at a post said with a progressive or with "run" -----------------------------------------

@pytest.mark.parametrize("world,prompt,who,location,others", [
    ("hotel", "Janet is manning the front desk.", "Janet", "reception_desk", 0),
    ("library", "Maria's covering the issue desk while three students browse the shelves.", "Maria", "issue_desk",
     1),
    ("supermarket", "Priya is working the tills.", "Priya", "checkouts", 0),
    ("mall", "Dave is running the information desk.", "Dave", "information_desk", 0),
    ("library", "Have Tom run the issue desk while a student reads in the reading room.", "Tom", "issue_desk", 1),
    ("mall", "Sam runs the information desk.", "Sam", "information_desk", 0),
])
def test_a_worker_said_with_a_progressive_or_run_stays_at_the_post(read, world, prompt, who, location, others):
    groups = read(world, prompt).groups
    assert len(groups) == 1 + others
    assert (groups[0].who, groups[0].intent, groups[0].location) == (who, "wait", location)


def test_running_somewhere_is_still_a_run(read):
    groups = read("mall", "A boy runs to the information desk.").groups
    assert groups[0].intent == "walk" and groups[0].destination == "information_desk"
    groups = read("library", "Two volunteers are manning the issue desk.").groups
    assert (groups[0].who, groups[0].location) == ("Two volunteers", "issue_desk")


# ---- 4. a child named by "youngest" or "little one" with a describing word before it -------------------

@pytest.mark.parametrize("world,prompt,moved", [
    ("residential", "Dad carries his sleepy little one from the lounge to the bedroom.", "little child"),
    ("hospital", "A nurse walks our poorly youngest from the lobby to radiology.", "youngest child"),
    ("mall", "Mum steers her grumpy eldest from the atrium to the food court.", "eldest child"),
    ("residential", "Gran leads her drowsy youngest from the kitchen to the bathroom.", "youngest child"),
])
def test_a_described_youngest_is_a_child_moved(read, world, prompt, moved):
    groups = read(world, prompt).groups
    assert len(groups) == 2 and groups[1].who.endswith(moved)
    assert (groups[1].intent, groups[1].count.value) == ("follow", 1)
    assert groups[1].destination == groups[0].destination is not None


def test_youngest_before_a_noun_keeps_its_reading(read):
    groups = read("hospital", "Two nurses walk the youngest patients to radiology.").groups
    assert [g.who for g in groups] == ["Two nurses", "the youngest patients"]
    groups = read("mall", "The youngest waits at the fountain.").groups
    assert [(g.who, g.location) for g in groups] == [("The youngest", "fountain")]


# ---- 5. a scale word alone as a rough count ----------------------------------------------------------

@pytest.mark.parametrize("world,prompt,value,low,high", [
    ("station", "The hundred-odd travellers on platform 2 wait for the train.", 100, 80, 120),
    ("mall", "Some hundred-odd shoppers wait in the food court.", 100, 80, 120),
    ("stadium", "The thousand or so fans in the north stand head to the exits.", 1000, 800, 1200),
    ("hospital", "The hundred or so visitors in the lobby walk to the cafeteria.", 100, 80, 120),
])
def test_a_scale_word_alone_is_a_rough_count(read, world, prompt, value, low, high):
    count = read(world, prompt).groups[0].count
    assert (count.kind, count.value, count.low, count.high) == ("approximate", value, low, high)


def test_a_scale_with_its_number_keeps_its_count(read):
    count = read("station", "A hundred travellers wait on platform 2.").groups[0].count
    assert (count.kind, count.value) == ("exact", 100)
    count = read("stadium", "Two hundred fans head to the exits.").groups[0].count
    assert (count.kind, count.value) == ("exact", 200)


# ---- 6. two bare people joined by "+" or "&" as an item of a chat list -----------------------------------

@pytest.mark.parametrize("world,prompt,whos", [
    ("hospital", "pt in bed 3, nurse + doctor w/ him, 2 visitors in the cafeteria",
     ["a patient", "a nurse", "a doctor", "2 visitors"]),
    ("mall", "guard + cleaner by the fountain, 3 teens at the food court", ["a guard", "a cleaner", "3 teens"]),
    ("airport", "pilot & steward at gate A1, 2 cleaners in the lounge", ["a pilot", "a steward", "2 cleaners"]),
    ("supermarket", "3 shoppers at the bakery, cashier + guard at the tills", ["3 shoppers", "a cashier", "a guard"]),
])
def test_two_people_joined_by_a_sign_are_two_groups(read, world, prompt, whos):
    groups = read(world, prompt).groups
    assert [g.who for g in groups] == whos
    assert all(g.count.value == 1 for g in groups if g.who.startswith("a "))


def test_people_joined_by_a_sign_already_read_keep_their_groups(read):
    groups = read("hospital", "nurses + porters at the lifts, 1 visitor in the cafeteria").groups
    assert [g.who for g in groups] == ["nurses", "porters", "1 visitor"]
    groups = read("mall", "a guard and a cleaner by the fountain, 3 teens at the food court").groups
    assert [g.who for g in groups] == ["a guard", "a cleaner", "3 teens"]
