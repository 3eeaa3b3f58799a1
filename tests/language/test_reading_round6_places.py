"""Place classes the sixth fresh set found, each with sentences of its own over at least two worlds
(none from the understanding sets): a place described by what is done there, an informal name or
idiom for a place, chat words after a place phrase, a place said again ("the same exit", "there"), a
purpose whose object is the place, a modifier that rules a place out, and a fronted frame ("At gate
B2, ... the desk") that decides which fixture."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt


def read(worlds, world, prompt):
    reading = read_prompt(prompt, worlds[world])
    assert reading.unknown_places == (), reading.unknown_places
    return reading


def place_of(group):
    return group.destination or group.location or group.start


# ---- 1. a place described by what is done there -----------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("airport", "Two women walk to the desk where you rent a car.", "car_rental_desk"),
    ("airport", "A pilot walks to the place you buy tickets.", "check_in_hall"),
    ("hospital", "Two patients walk to the room where they take X-rays.", "radiology"),
    ("hospital", "A nurse goes to the place where you get your medicine.", "pharmacy"),
    ("hospital", "A porter goes to the room they keep the supplies in.", "supply_room"),
    ("station", "A man walks to the place you buy tickets.", "ticket_office"),
    ("station", "A boy walks to the spot where people drop their bags.", "left_luggage"),
    ("museum", "Two kids go to the spot where people drop their bags.", "cloakroom"),
    ("museum", "A teacher goes to the room where children paint.", "education_room"),
    ("mall", "A man walks to the place where you get cash.", "cash_machine"),
    ("mall", "A couple walk to the place you try on clothes.", "clothing_store"),
    ("office", "A woman walks to the machine that makes coffee.", "coffee_machine"),
    ("office", "Two developers go to the room where the servers are.", "server_room"),
])
def test_a_place_described_by_what_is_done_there(worlds, world, prompt, place):
    g, = read(worlds, world, prompt).groups
    assert place_of(g) == place


@pytest.mark.parametrize("world,prompt,place", [
    ("airport", "A businessman hurries to the counter where you hire a car.", "car_rental_desk"),
    ("mall", "Two girls queue at the counter where you buy cinema tickets.", "ticket_counter"),
    ("station", "Two women go to the counter where you leave your luggage.", "left_luggage_counter"),
])
def test_the_head_of_a_described_place_limits_what_it_can_be(worlds, world, prompt, place):
    """"the counter where ...": a counter, desk or till, chosen by the clause, not by "counter"."""
    g, = read(worlds, world, prompt).groups
    assert place_of(g) == place


# ---- 3. chat words and times after a place phrase ----------------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("museum", "8 ppl queue @ the ticket desk b4 opening", "ticket_desk"),
    ("museum", "2 guards chat in the great hall till closing time", "great_hall"),
    ("mall", "5 teens hang out at the food court 2nite lol", "food_court"),
    ("mall", "a man waits at the toy till til 6", "toy_till"),
    ("hospital", "3 ppl wait @ the pharmacy counter asap", "pharmacy_counter"),
    ("station", "10 ppl queue at the ticket office b4 the 8am train", "ticket_office"),
])
def test_a_place_phrase_ends_where_a_time_or_chat_word_starts(worlds, world, prompt, location):
    g, = read(worlds, world, prompt).groups
    assert g.location == location


def test_a_till_the_world_has_is_still_a_place(worlds):
    g, = read(worlds, "mall", "3 ppl queue at the book till").groups
    assert g.location == "book_till"


# ---- 2. informal names and idioms for a place -------------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("mall", "A man gets money from the hole in the wall.", "cash_machine"),
    ("mall", "Three girls wait by the bogs.", "restrooms"),
    ("mall", "Two dads go to the gents.", "restrooms"),
    ("hospital", "A patient goes to the caff.", "cafeteria"),
    ("hospital", "A man walks to the lift lobby.", "elevator_hall"),
    ("station", "A man goes to the caff.", "cafe"),
    ("station", "A woman buys a paper at the newsie.", "newsagent"),
    ("office", "A woman goes to the little girls' room.", "restroom_women"),
])
def test_an_informal_name_is_read_as_what_it_means(worlds, world, prompt, place):
    g, = read(worlds, world, prompt).groups
    assert place_of(g) == place


def test_an_informal_name_is_read_less_than_surely(worlds):
    g, = read(worlds, "mall", "A man gets money from the hole-in-the-wall.").groups
    sure = {c.field: c for c in g.confidence}
    assert g.location == "cash_machine" and 0.6 <= sure["location"].score < 1.0


def test_an_idiom_the_world_lacks_is_refused_whole(worlds):
    """Never as the unknown places its words would be ("hole", "wall")."""
    reading = read_prompt("A man gets cash from the hole in the wall.", worlds["residential"])
    assert reading.unknown_places == ("hole in the wall",)


# ---- 6. a word that says what kind of place rules out a place of another kind -------------------------

@pytest.mark.parametrize("world,prompt,refused", [
    ("mall", "Two kids queue at the ice-cream stand.", "ice cream stand"),
    ("mall", "Two teens go to the sports shop.", "sports shop"),
    ("office", "A clerk walks to the stockroom.", "stockroom"),
    ("office", "Two interns go to the mailroom.", "mailroom"),
    ("hospital", "Three visitors go to the maternity ward.", "maternity ward"),
    ("hospital", "A man gets cash from the hole in the wall.", "hole in the wall"),
])
def test_a_place_of_another_kind_is_refused_not_taken(worlds, world, prompt, refused):
    assert read_prompt(prompt, worlds[world]).unknown_places == (refused,)


@pytest.mark.parametrize("world,prompt,field,place", [
    ("office", "Four people meet in the main meeting room.", "location", "boardroom"),
    ("office", "Two devs chat in the big meeting room.", "location", "boardroom"),
    ("hospital", "A porter pushes a trolley from the stockroom to the ICU.", "start", "supply_room"),
    ("mall", "Two teens wait at the phone stand.", "location", "phone_kiosk"),
    ("airport", "Ten passengers wait in the vast hall.", "location", "check_in_hall"),
])
def test_synonyms_and_looks_still_find_the_place(worlds, world, prompt, field, place):
    g, = read(worlds, world, prompt).groups
    assert getattr(g, field) == place


# ---- 7. a fronted frame decides which fixture ---------------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("airport", "At gate A1, ten passengers sit waiting to board while two agents chat behind the desk.",
     "gate_a1_desk"),
    ("airport", "At gate A2 two agents chat at the desk.", "gate_a2_desk"),
    ("airport", "At gate B2, ten passengers look at the departures board while two agents chat behind the desk.",
     "gate_b2_desk"),
    ("hospital", "In exam room 2, a nurse checks the medication cart while a doctor sits at the desk.", "exam_desk_2"),
    ("hospital", "In exam room 1, a nurse waits while a doctor sits at the desk.", "exam_desk_1"),
    ("station", "On platform 2, a woman waits while a man sits on the bench.", "platform_2_bench"),
    ("museum", "In the café, a family sits down while a barista stands at the counter.", "cafe_counter"),
])
def test_the_zone_a_sentence_opens_in_decides_its_fixtures(worlds, world, prompt, place):
    groups = read(worlds, world, prompt).groups
    assert groups[-1].location == place


@pytest.mark.parametrize("world,prompt,place", [
    ("airport", "At gate B1 two agents chat behind the desk.", "gate_b1"),
    ("station", "On platform 1 a man sits on the bench.", "platform_1"),
])
def test_a_count_after_a_numbered_place_starts_the_people(worlds, world, prompt, place):
    reading = read(worlds, world, prompt)
    assert place in reading.places and reading.groups[0].location.startswith(place)


def test_to_and_a_verb_is_no_place(worlds):
    """"waiting to board": boarding, not the departures board."""
    g, = read(worlds, "airport", "Forty passengers sit at gate B2 waiting to board.").groups
    assert g.location == "gate_b2" and g.destination is None


# ---- 4. a place said again ------------------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("airport", "Ten passengers walk to the west fire exit and five staff follow them out through that exit.",
     "emergency_exit_west"),
    ("airport", "Thirty passengers hurry to the east fire exit, and the 4 people in the lounge leave by the "
                "same exit.", "emergency_exit_east"),
    ("hospital", "Five patients go to the east exit; the nurses follow through the same exit.", "east_emergency_exit"),
    ("museum", "Six tourists leave by the garden door, then four more leave by the same door.", "garden_door"),
])
def test_the_same_place_is_the_one_said_before(worlds, world, prompt, place):
    groups = read(worlds, world, prompt).groups
    assert groups[-1].destination == place


@pytest.mark.parametrize("world,prompt,place", [
    ("hospital", "Two visitors walk to the pharmacy and three more wait there.", "pharmacy"),
    ("hospital", "Five nurses go to the ICU; two doctors are already there.", "intensive_care"),
    ("mall", "Four shoppers queue at the cash machine while two friends wait there too.", "cash_machine"),
    ("museum", "A teacher brings ten kids to the dinosaur gallery and two parents wait for them there.",
     "dinosaur_gallery"),
])
def test_there_is_the_place_said_before(worlds, world, prompt, place):
    groups = read(worlds, world, prompt).groups
    assert groups[-1].location == place


def test_an_existential_there_points_at_no_place(worlds):
    g, = read(worlds, "station", "There are ten commuters in the waiting room.").groups
    assert g.location == "waiting_room"


# ---- 5. a purpose whose object is the place ----------------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("hospital", "Two porters go to collect a prescription.", "pharmacy_counter"),
    ("hospital", "A patient walks from ward A to get an x-ray.", "xray_machine"),
    ("museum", "Two kids run off to buy a souvenir.", "gift_shop"),
    ("museum", "A painter crosses the great hall to sketch the whale.", "whale_skeleton"),
    ("office", "Two devs head off to grab a coffee.", "coffee_machine"),
    ("station", "A woman walks over to buy a newspaper.", "magazine_racks"),
    ("airport", "Two pilots leave the lounge to grab a coffee.", "cafe_counter"),  # the café's coffee counter
])
def test_a_purpose_names_the_place_people_go_to(worlds, world, prompt, place):
    reading = read(worlds, world, prompt)
    g, = reading.groups
    sure = {c.field: c.score for c in g.confidence}
    assert g.destination == place and place in reading.places and sure["destination"] < 0.7


@pytest.mark.parametrize("world,prompt,place", [
    ("airport", "Two pilots walk to the lounge to grab a coffee.", "airline_lounge"),
    ("office", "A developer walks to the kitchen to print something.", "kitchen"),
])
def test_a_purpose_never_overrides_a_place_said(worlds, world, prompt, place):
    g, = read(worlds, world, prompt).groups
    assert g.destination == place


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "A visitor walks out to get some fresh air."),
    ("office", "Two managers walk off to meet a friend."),
])
def test_a_purpose_no_place_serves_names_none(worlds, world, prompt):
    g, = read(worlds, world, prompt).groups
    assert g.destination is None


@pytest.mark.parametrize("world,prompt,place", [
    ("airport", "A pilot walks off to board his plane.", None),
    ("airport", "Two women hurry to check in.", "check_in_hall"),
    ("hospital", "Two patients walk off to check in.", "checkin_kiosk"),
])
def test_a_purpose_verb_that_is_only_a_word_of_a_name_names_no_place(worlds, world, prompt, place):
    """"to board" is no departures board; "to check in" is the check-in hall or kiosk."""
    g, = read(worlds, world, prompt).groups
    assert g.destination == place


def test_a_new_clause_after_a_place_is_no_relative_clause(worlds):
    """"In the hall people wait": the people of a new clause, not "the hall where people wait"."""
    g, = read(worlds, "museum", "In the great hall people wait and chat.").groups
    assert g.location == "great_hall"


@pytest.mark.parametrize("world,prompt,start", [
    ("office", "A leak starts above the kitchen and everyone in there walks out to the corridor.", "kitchen"),
    ("hospital", "A fire starts in the pharmacy and everyone in there runs to the main entrance.", "pharmacy"),
    ("mall", "Smoke fills the bookshop and the people inside there hurry to the west exit.", "bookshop"),
])
def test_in_there_is_where_movers_start(worlds, world, prompt, start):
    g, = read(worlds, world, prompt).groups
    assert g.start == start


@pytest.mark.parametrize("world,prompt,refused", [
    ("station", "Two guards wait by the hole in the wall.", "hole in the wall"),
    ("residential", "Grandpa naps in the caff.", "caff"),
])
def test_an_informal_name_only_shares_a_word_with_no_place(worlds, world, prompt, refused):
    """"the hole in the wall" is a cash machine, not the ticket machines that share "machine"."""
    assert read_prompt(prompt, worlds[world]).unknown_places == (refused,)


@pytest.mark.parametrize("world,prompt,place", [
    ("mall", "Two teens wait at the fountain and their friends meet them at the same spot.", "fountain"),
    ("mall", "Four women shop in the bookshop and two men wait in the same place.", "bookshop"),
])
def test_the_same_place_of_no_kind_is_the_place_said_last(worlds, world, prompt, place):
    assert read(worlds, world, prompt).groups[-1].location == place


def test_the_same_time_is_no_place(worlds):
    reading = read(worlds, "hospital", "Two nurses walk to the ICU at the same time as a doctor leaves ward B.")
    assert [g.destination for g in reading.groups] == ["intensive_care", None]


@pytest.mark.parametrize("world,prompt,place", [
    ("residential", "The kids run to the room they sleep in.", "child_bedroom"),
    ("residential", "Mum goes to the room where she sleeps.", "master_bedroom"),
])
def test_a_described_room_of_the_people_themselves(worlds, world, prompt, place):
    g, = read(worlds, world, prompt).groups
    assert g.destination == place


@pytest.mark.parametrize("world,prompt,place", [
    ("airport", "A man walks to the desk for car hire.", "car_rental_desk"),
    ("hospital", "Two patients go to the room for x-rays.", "radiology"),
    ("hospital", "Five patients queue at the counter for their prescriptions.", "pharmacy_counter"),
])
def test_a_place_described_by_what_it_is_for(worlds, world, prompt, place):
    g, = read(worlds, world, prompt).groups
    assert place_of(g) == place


def test_a_duration_after_a_place_describes_nothing(worlds):
    g, = read(worlds, "station", "A woman waits at the counter for ten minutes.").groups
    assert g.wait_seconds == 600


def test_a_word_for_what_the_building_is_about_rules_nothing_out(worlds):
    """"the train platform" of a station is a place of the station, not a kind of place it lacks."""
    reading = read_prompt("Ten commuters wait on the train platform.", worlds["station"])
    assert reading.unknown_places == () and reading.groups[0].location is not None


def test_a_number_word_after_a_series_word_is_still_the_place(worlds):
    g, = read(worlds, "station", "On platform two passengers wait.").groups
    assert g.location == "platform_2"
