"""Place classes the seventh fresh set found, each with sentences of its own over at least two worlds
(none from the understanding sets): chat shortenings of a place word ("plat 1", "rm 2", "the recep
desk") and of "for" and "to" ("4 the", "2 the"); a fixture inside a named room; a name said with its
parts in another order ("the B1 desk", "the 2 platform")."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.language.spelling import shortens
from grove_tui.language.text import normalise


def read(worlds, world, prompt):
    reading = read_prompt(prompt, worlds[world])
    assert reading.unknown_places == (), reading.unknown_places
    return reading


def place_of(group):
    return group.destination or group.location or group.start


# ---- 1. chat shortenings of a place word, and of "for" and "to" ---------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("station", "3 kids wait on plat 2 with their gran", "platform_2"),
    ("station", "a busker plays on the plat 1 bench", "platform_1_bench"),
    ("hospital", "2 porters wait in exam rm 1 with a trolley", "exam_room_1"),
    ("office", "4 devs chat in meeting rm 2", "meeting_room_2"),
    ("office", "two interns hurry to mtg room 1", "meeting_room_1"),
    ("airport", "5 ppl queue at check-in ctr b", "check_in_counter_b"),
    ("hospital", "a visitor asks for directions at the pharm", "pharmacy"),
])
def test_a_shortened_place_word_is_the_word_it_shortens(worlds, world, prompt, place):
    g = read(worlds, world, prompt).groups[0]
    assert place_of(g) == place


@pytest.mark.parametrize("short,word,fits", [
    ("plat", "platform", True), ("rm", "room", True), ("dept", "department", True), ("recep", "reception", True),
    ("bldg", "building", True), ("caf", "cafe", True),
    ("car", "cardiology", False),  # a whole word, far shorter than the name
    ("rm", "rum", False),  # a shortening is shorter by more than a letter
    ("room", "room", False), ("pt", "platform", False), ("big", "booking", False), ("lot", "lift", False),
])
def test_what_counts_as_a_shortening(short, word, fits):
    assert shortens(short, word) is fits


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "Dr Jones walks to the pharmacy."),
    ("museum", "A man parks his car and walks to the café."),
])
def test_a_title_or_a_whole_word_is_not_shortened_into_a_place(worlds, world, prompt):
    r = read_prompt(prompt, worlds[world])
    assert r.corrections == ()


@pytest.mark.parametrize("text,written", [
    ("6 ppl queuing 4 the printers", "6 people queuing for the printers"),
    ("two kids run 2 the toilets", "two kids run to the toilets"),
    ("a man waits 4 his wife", "a man waits for his wife"),
    ("at 4 the doors open", "at 4 the doors open"),  # a time
    ("from 2 the queue grows", "from 2 the queue grows"),
    ("4 nurses and 2 porters", "4 nurses and 2 porters"),  # counts
])
def test_four_and_two_before_a_determiner_are_for_and_to(text, written):
    assert normalise(text) == written


@pytest.mark.parametrize("world,prompt,field,place", [
    ("mall", "3 teens walk 2 the food court", "destination", "food_court"),
    ("museum", "a guide waits 4 the group in the foyer", "location", "entrance_hall"),
    ("station", "approx 20 ppl on plat 2 waiting 4 the 18:05", "location", "platform_2"),
])
def test_a_place_after_a_chat_for_or_to(worlds, world, prompt, field, place):
    g = read(worlds, world, prompt).groups[0]
    assert getattr(g, field) == place


# ---- 2. a fixture inside a named room is that fixture, not the room -----------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("station", "a man sits on the bench on platform 2", "platform_2_bench"),
    ("station", "12 ppl queuing for the ticket machines in the ticket hall", "ticket_machines"),
    ("hospital", "a doctor naps on the sofa in the break room", "staff_sofa"),
    ("hospital", "3 nurses queue for the coffee machine in the staff room", "staff_coffee_machine"),
    ("museum", "a guard naps on the couch in the staff room", "staff_sofa"),
    ("museum", "6 visitors queue 4 the lockers in the cloakroom", "lockers"),
    ("airport", "a family sits at the tables in the café", "cafe_tables"),
])
def test_a_fixture_in_a_named_room_is_the_fixture(worlds, world, prompt, place):
    g = read(worlds, world, prompt).groups[0]
    assert g.location == place


# ---- 3. a name said with its parts in another order ---------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("airport", "two agents chat at the B1 desk", "gate_b1_desk"),
    ("airport", "a man queues at the B check-in counter", "check_in_counter_b"),
    ("station", "3 men wait on the 2 platform", "platform_2"),
    ("hospital", "a nurse walks to the 1 exam room", "exam_room_1"),
    ("hospital", "a man sits on the 2 lobby bench", "lobby_bench_2"),
    ("office", "4 devs go to the 2 meeting room", "meeting_room_2"),
])
def test_a_name_with_its_number_or_letter_elsewhere_is_that_name(worlds, world, prompt, place):
    g = read(worlds, world, prompt).groups[0]
    assert place_of(g) == place


def test_a_number_before_people_is_still_their_count(worlds):
    g, = read(worlds, "airport", "the 3 families wait at gate A1").groups
    assert g.location == "gate_a1" and g.count.value >= 3


# ---- 4. a place described by a passive clause --------------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("office", "two devs go to the room where the servers are kept", "server_room"),
    ("hospital", "a porter goes to the room where the linen is stored", "supply_room"),
    ("hospital", "two men go to the counter where prescriptions are collected", "pharmacy_counter"),
    ("airport", "a man goes to the desk where lost bags are reported", "lost_luggage_desk"),
    ("museum", "a woman goes to the room where coats and bags are left", "cloakroom"),
])
def test_a_place_described_by_what_is_done_to_things_there(worlds, world, prompt, place):
    g = read(worlds, world, prompt).groups[0]
    assert place_of(g) == place


def test_a_passive_clause_is_read_as_what_people_do_there(worlds):
    from grove_tui.language.people import People
    from grove_tui.language.place_phrases import PlacePhrases
    from grove_tui.language.parser import parse
    from grove_tui.language.places import place_index
    from grove_tui.language.sentence import Sentence

    text = "the desk where books are borrowed and returned"
    s = Sentence(text, parse(text), place_index(worlds["office"]), 0)
    phrases = PlacePhrases(s, People(s))
    assert phrases._active(3, s.n) == "you borrow and return books"


def test_a_new_clause_after_a_described_place_is_its_own(worlds):
    r = read(worlds, "office", "two devs go to the room where the servers are kept and 3 managers sit in the boardroom")
    assert [place_of(g) for g in r.groups] == ["server_room", "boardroom"]


# ---- 5. a purpose that names a thing the place gives ------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("hospital", "a woman walks in to take a number", "ticket_machine"),
    ("airport", "a man hurries to get a boarding pass", "check_in_kiosks"),
    ("hospital", "a man goes to pick up a prescription", "pharmacy_counter"),
    ("museum", "a kid runs off to leave his coat", "cloakroom"),
    ("mall", "a man goes to withdraw some cash", "cash_machine"),
])
def test_a_purpose_finds_the_place_by_what_it_is_for(worlds, world, prompt, place):
    reading = read(worlds, world, prompt)
    g, = reading.groups
    assert g.destination == place


def test_what_a_place_is_for_is_ranked_by_meaning(worlds):
    from grove_tui.language.places import place_index

    ranked = place_index(worlds["hospital"]).by_description("to take a queue number")
    assert ranked and ranked[0].entry.name == "ticket_machine" and "dispenser" in ranked[0].nearest


# ---- 6. a thing the world lacks is refused, though its head is a word the world has -------------------

@pytest.mark.parametrize("world,prompt,refused", [
    ("mall", "two teens go to the vending machines", "vending machines"),
    ("station", "two men walk to the vending machines", "vending machines"),
    ("airport", "two men walk to the vending machines", "vending machines"),
    ("office", "two devs go to the vending machine", "vending machine"),
])
def test_a_machine_of_a_kind_the_world_lacks_is_refused(worlds, world, prompt, refused):
    assert read_prompt(prompt, worlds[world]).unknown_places == (refused,)


@pytest.mark.parametrize("world,prompt,place", [
    ("hospital", "two men walk to the vending machines", "vending_machine"),
    ("hospital", "two men walk to the snack machine", "vending_machine"),
    ("station", "two men walk to the booking office", "ticket_office"),
    ("mall", "a couple walks to the dining area", "food_court"),
    ("hospital", "Ten people leave the eating area.", "cafeteria"),
    ("airport", "5 travellers queue at the chek in hall", "check_in_hall"),
])
def test_a_synonym_or_the_world_s_own_kind_still_resolves(worlds, world, prompt, place):
    g = read(worlds, world, prompt).groups[0]
    assert place_of(g) == place


# ---- 7. a misspelling two edits from the word that completes a name -----------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("hospital", "Three relatives hurry to intensive cair.", "intensive_care"),
    ("airport", "a woman waits at the bagage carusel 1", "carousel_1"),
    ("office", "two devs sit in the meating rom 1", "meeting_room_1"),
])
def test_a_word_two_edits_from_a_name_word_that_completes_the_name(worlds, world, prompt, place):
    g = read(worlds, world, prompt).groups[0]
    assert place_of(g) == place


# ---- 7. a verbless group's place is its own, not the next group's -------------------------------------

@pytest.mark.parametrize("world,prompt,places", [
    ("station", "6 people in line at the ticket office, 2 more at the ticket machines",
     ["ticket_office", "ticket_machines"]),
    ("hospital", "Ten patients in the waiting room, three more by the pharmacy", ["main_waiting_room", "pharmacy"]),
    ("museum", "5 kids in line at the ticket desk, 3 more at the cloakroom", ["ticket_desk", "cloakroom"]),
])
def test_a_place_right_after_a_group_is_that_group_s(worlds, world, prompt, places):
    r = read(worlds, world, prompt)
    assert [g.location for g in r.groups] == places
