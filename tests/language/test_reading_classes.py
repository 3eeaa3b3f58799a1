"""The reader on the classes of English that the hand-written held-out set (eval/understanding/
heldout.yaml) found it getting wrong: a handful of sentences per class, none of them a held-out
sentence, each asserting the reading. Real spaCy, shipped worlds.
"""

from __future__ import annotations

import pytest

from grove_tui.language.reading import GroupReading, PromptReading, read_prompt


def one(reading: PromptReading) -> GroupReading:
    assert len(reading.groups) == 1, [g.who for g in reading.groups]
    assert not reading.unknown_places, reading.unknown_places
    return reading.groups[0]


def read(worlds, world: str, prompt: str) -> PromptReading:
    return read_prompt(prompt, worlds[world], seed=0)


@pytest.mark.parametrize("prompt, count, label", [
    ("Four nurzes walk to the pharmacy.", 4, "nurse"),
    ("Two visiters wait in the lobby.", 2, "visitor"),
    ("Three chidlren run to the cafeteria.", 3, "child"),
    ("Five paramedics hurry to the main entrance.", 5, "paramedic"),
])
def test_misspelt_people_are_still_people(worlds, prompt, count, label):
    group = one(read(worlds, "hospital", prompt))
    assert (group.count.value, group.label) == (count, label)


@pytest.mark.parametrize("prompt, destination", [
    ("At noon the nurses walk to the cafeteria.", "cafeteria"),
    ("After lunch two doctors head to ward B.", "ward_b"),
    ("In the evening the visitors go to the main entrance.", "main_entrance"),
])
def test_the_subject_after_a_fronted_phrase_without_a_comma(worlds, prompt, destination):
    group = one(read(worlds, "hospital", prompt))
    assert (group.intent, group.destination) == ("walk", destination)


@pytest.mark.parametrize("world, prompt, count, role, place", [
    ("hospital", "The cafeteria is visited by three nurses.", 3, "destination", "cafeteria"),
    ("residential", "The lounge is used by two teenagers.", 2, "location", "living_room"),
    ("office", "The kitchen is occupied by a cleaner.", 1, "location", "kitchen"),
])
def test_the_doer_of_a_passive_is_the_group_and_its_subject_the_place(worlds, world, prompt, count, role, place):
    group = one(read(worlds, world, prompt))
    assert group.count.value == count
    assert getattr(group, role) == place


@pytest.mark.parametrize("prompt, interaction", [
    ("The robot is followed by two children.", "follow"),
    ("A porter keeps well clear of the robot.", "avoid"),
    ("An old man gives the robot a wide berth.", "avoid"),
    ("Two kids take pictures of the robot.", "look"),
    ("Frightened by the robot, a visitor backs into the lobby.", "avoid"),
    ("A visitor stops dead at the sight of the robot.", "look"),
])
def test_robot_reactions_in_idioms_and_fronted_phrases(worlds, prompt, interaction):
    group = one(read(worlds, "hospital", prompt))
    assert (group.intent, group.robot_interaction) == ("robot", interaction)


@pytest.mark.parametrize("prompt", [
    "A child in the lobby stares at the robot.",
    "In the lobby, three visitors point at the robot.",
])
def test_someone_who_only_looks_at_the_robot_is_where_they_are(worlds, prompt):
    group = one(read(worlds, "hospital", prompt))
    assert (group.robot_interaction, group.location, group.start) == ("look", "entrance_lobby", None)


@pytest.mark.parametrize("world, prompt, destination", [
    ("hospital", "A visitor makes a beeline for the pharmacy.", "pharmacy"),
    ("airport", "Two late passengers make a dash for gate A2.", "gate_a2"),
    ("office", "The cleaners leave out the back door.", "back_exit"),
    ("residential", "Two friends slip out the back.", "back_door"),
    ("office", "Three engineers head out the back.", "back_exit"),
])
def test_idioms_of_going_somewhere(worlds, world, prompt, destination):
    group = one(read(worlds, world, prompt))
    assert (group.intent, group.destination) == ("walk", destination)


@pytest.mark.parametrize("world, prompt, purpose", [
    ("hospital", "Two nurses head out for lunch.", "lunch"),
    ("residential", "Dad heads out the back for a smoke.", "smoke"),
    ("hospital", "Some patients go to the lobby to pick up wheelchairs.", "wheelchair"),
])
def test_a_purpose_is_never_an_unknown_place(worlds, world, prompt, purpose):
    group = one(read(worlds, world, prompt))
    assert purpose in (group.purpose or "")


@pytest.mark.parametrize("world, prompt, location", [
    ("hospital", "A visitor buys a snack from the vending machine.", "vending_machine"),
    ("station", "Two tourists buy tickets from the ticket machines.", "ticket_machines"),
    ("office", "A designer grabs a coffee from the coffee machine.", "coffee_machine"),
])
def test_getting_something_from_a_place_is_being_there(worlds, world, prompt, location):
    group = one(read(worlds, world, prompt))
    assert (group.location, group.start) == (location, None)


@pytest.mark.parametrize("world, prompt, location, intent", [
    ("hospital", "Ward A: three nurses chatting.", "ward_a", "converse"),
    ("office", "Kitchen: two people waiting.", "kitchen", "wait"),
    ("airport", "Gate B2: forty passengers seated.", "gate_b2", "wait"),
])
def test_a_place_before_a_colon_is_where_the_people_are(worlds, world, prompt, location, intent):
    group = one(read(worlds, world, prompt))
    assert (group.location, group.intent) == (location, intent)


@pytest.mark.parametrize("world, prompt, zone", [
    ("hospital", "The pharmacy is evacuated.", "pharmacy"),
    ("office", "Evacuate the boardroom through the fire exit.", "boardroom"),
    ("station", "The waiting room is being evacuated.", "waiting_room"),
])
def test_a_zone_evacuated_with_nobody_named_is_emptied_and_the_reading_says_so(worlds, world, prompt, zone):
    reading = read(worlds, world, prompt)
    group = one(reading)
    assert (group.count.kind, group.intent, group.start) == ("whole_zone", "evacuate", zone)
    assert any("no people are named" in note for note in reading.notes)


@pytest.mark.parametrize("prompt, count", [
    ("A line of ten patients forms at the pharmacy counter.", 10),
    ("A queue of six visitors builds up at the pharmacy counter.", 6),
])
def test_a_queue_named_by_its_collective_is_a_queue(worlds, prompt, count):
    group = one(read(worlds, "hospital", prompt))
    assert (group.count.value, group.intent, group.location) == (count, "queue", "pharmacy_counter")


@pytest.mark.parametrize("world, prompt", [
    ("hospital", "Two visitors wait in the lobby until a nurse calls them."),
    ("hospital", "When the outpatient clinic opens, twelve patients walk to the outpatient waiting room."),
    ("office", "The manager's office is occupied by two directors."),
    ("airport", "Security alert: everyone in the concourse leaves through the east fire exit."),
])
def test_people_who_are_not_a_group(worlds, world, prompt):
    one(read(worlds, world, prompt))


@pytest.mark.parametrize("world, prompt, count", [
    ("office", "The team meeting of eight people ends and they walk to the kitchen.", 8),
    ("hospital", "The ward round of five doctors moves on to ward C.", 5),
])
def test_people_counted_inside_an_event(worlds, world, prompt, count):
    group = one(read(worlds, world, prompt))
    assert group.count.value == count


@pytest.mark.parametrize("world, prompt, value", [
    ("station", "Evacuate the café: its twenty-odd customers leave by the side entrance.", 20),
    ("hospital", "Evacuate ward B: its six patients leave by the east exit.", 6),
])
def test_counts_after_a_possessive_and_odd_counts(worlds, world, prompt, value):
    group = one(read(worlds, world, prompt))
    assert (group.count.value, group.intent) == (value, "evacuate")


# ---- round 2: the classes heldout_fresh.yaml found (none of its sentences, none of heldout_fresh2's) ----


@pytest.mark.parametrize("world, prompt, start, destination", [
    ("office", "Smoke in the boardroom! Six staff get out through the fire exit.", None, "fire_exit"),
    ("hospital", "Ward C has to be emptied: eight patients leave by the east exit.", "ward_c", "east_emergency_exit"),
    ("office", "Clear the kitchen: five employees go out by the back door.", "kitchen", "back_exit"),
    ("station", "Everyone in the waiting room must get out through the ticket hall now.", "waiting_room", None),
    ("airport", "A bomb scare at the cafe: twelve travellers empty out into the concourse.", None, "concourse"),
])
def test_evacuation_idioms_hazards_and_cleared_zones(worlds, world, prompt, start, destination):
    group = one(read(worlds, world, prompt))
    assert group.intent == "evacuate"
    if start is not None:
        assert group.start == start
    if destination is not None:
        assert group.destination == destination


@pytest.mark.parametrize("world, prompt", [
    ("office", "Two managers walk to the fire exit."),
    ("hospital", "Two visitors get out of the lift and walk to the cafeteria."),
    ("residential", "Dad checks the smoke detector in the hallway and then goes to the kitchen."),
])
def test_leaving_without_an_emergency_is_a_walk(worlds, world, prompt):
    assert one(read(worlds, world, prompt)).intent == "walk"


@pytest.mark.parametrize("world, prompt, interaction", [
    ("airport", "A traveller recoils whenever the robot beeps at gate A1.", "avoid"),
    ("station", "Commuters cower behind the benches when the robot rolls by.", "avoid"),
    ("office", "An intern parks himself in front of the robot in the corridor.", "block"),
    ("hospital", "A porter jumps back as the robot turns into the main corridor.", "avoid"),
])
def test_robot_postures_avoid_and_block(worlds, world, prompt, interaction):
    group = one(read(worlds, world, prompt))
    assert (group.intent, group.robot_interaction) == ("robot", interaction)


@pytest.mark.parametrize("world, prompt, label", [
    ("office", "An applicant waits at the front desk.", "applicant"),
    ("airport", "Two pursers walk to gate B2.", "purser"),
    ("hospital", "A phlebotomist goes to ward A.", "phlebotomist"),
    ("station", "A ticket inspector stands at the gates.", "inspector"),
])
def test_occupations_and_roles_are_people(worlds, world, prompt, label):
    assert one(read(worlds, world, prompt)).label == label


def test_a_real_word_one_edit_from_a_person_is_no_typo(worlds):
    reading = read(worlds, "hospital", "Posters hang in the lobby while three porters walk to the pharmacy.")
    group = one(reading)
    assert (group.label, group.count.value, group.destination) == ("porter", 3, "pharmacy")
    assert one(read(worlds, "hospital", "Three passangers walk to the pharmacy.")).label == "passenger"


@pytest.mark.parametrize("world, prompt, location, low, high", [
    ("station", "There's a queue of people at the ticket office, about fifteen.", "ticket_office", 12, 18),
    ("airport", "There is a line of travellers at the cafe counter.", "cafe_counter", 4, 8),
])
def test_existential_lines_are_queues_with_their_apposed_count(worlds, world, prompt, location, low, high):
    group = one(read(worlds, world, prompt))
    assert (group.intent, group.location) == ("queue", location)
    assert low <= group.count.value <= high


@pytest.mark.parametrize("world, prompt, places", [
    ("office", "A cleaner dusts the boardroom.", ["boardroom"]),
    ("station", "A porter sweeps near the toilets while two commuters wait on platform 2.", ["toilets", "platform_2"]),
])
def test_a_verb_the_parser_tags_as_a_noun_after_a_person(worlds, world, prompt, places):
    reading = read(worlds, world, prompt)
    assert [g.location for g in reading.groups] == places


def test_a_single_conversation_partner_is_no_group_but_a_counted_one_is(worlds):
    one(read(worlds, "hospital", "A nurse chats with the receptionist in the lobby."))
    reading = read(worlds, "hospital", "A nurse chats with two visitors in the lobby.")
    assert [g.count.value for g in reading.groups] == [1, 2]


@pytest.mark.parametrize("world, prompt, label", [
    ("office", "A sommelier chats with the manager in the kitchen.", "sommelier"),
    ("office", "Two botanists stroll to the boardroom.", "botanist"),
    ("station", "A locksmith browses in the newsagent.", "locksmith"),
])
def test_the_subject_of_a_verb_only_people_do_is_a_person(worlds, world, prompt, label):
    assert one(read(worlds, world, prompt)).label == label


def nobody_named(reading):
    """A sentence that names no people is one group the model fills, marked as assumed."""
    (group,) = reading.groups
    conf = group.confidence_of("group")
    return conf is not None and conf.unsure and group.label == "person"


def test_a_thing_doing_a_thing_is_nobody(worlds):
    assert nobody_named(read(worlds, "office", "The new printer whirs in the open office."))


@pytest.mark.parametrize("prompt, counts", [
    ("Two posters hang in the lobby while three porters walk to the pharmacy.", [3]),
    ("Four screens flash in the lobby. Ten zombies shamble to the pharmacy.", [10]),
])
def test_a_counted_thing_that_only_does_what_things_do_is_nobody(worlds, prompt, counts):
    assert [g.count.value for g in read(worlds, "hospital", prompt).groups] == counts


@pytest.mark.parametrize("world, prompt, count", [
    ("hospital", "500 people across the hospital evacuate", 500),
    ("office", "120 staff throughout the office evacuate", 120),
    ("hospital", "Two hundred visitors across the building leave in a hurry", 200),
])
def test_a_verb_after_the_building_is_not_part_of_a_place(worlds, world, prompt, count):
    reading = read(worlds, world, prompt)
    group = one(reading)
    assert group.count.value == count and group.start is None
    assert not reading.unknown_places


# ---- round 3: classes found by eval/understanding/heldout_fresh3.yaml ----------------------------


@pytest.mark.parametrize("world, prompt, role, place, corrected", [
    ("hospital", "Two nurses walk from the radiolgy to the pharmacy.", "start", "radiology", "radiolgy"),
    ("office", "Six engineers head to the conferance room.", "destination", "boardroom", "conferance"),
    ("residential", "Mum goes from the hallway to the bathrom.", "destination", "bathroom", "bathrom"),
    ("station", "A porter waits in the waiting roon.", "location", "waiting_room", "roon"),
    ("airport", "Some tourists stroll to the arivals hall.", "destination", "arrivals_hall", "arivals"),
    ("residential", "Two guests walk from the kitchen to the diningroom.", "destination", "kitchen", "diningroom"),
])
def test_misspelt_places_are_corrected_and_the_correction_reported(worlds, world, prompt, role, place, corrected):
    reading = read(worlds, world, prompt)
    group = one(reading)
    assert getattr(group, role) == place
    assert any(f"'{corrected}'" in c for c in reading.corrections), reading.corrections
    assert reading.to_dict()["corrections"] == list(reading.corrections)


@pytest.mark.parametrize("world, prompt", [
    ("hospital", "Three visitors turn left at the lift lobby and walk to ward B."),  # "left" is no "lift"
    ("office", "Two colleagues walk to the kitchen."),
    # words the parser's training text never used are still English: "fright" is no misspelt "flight"
    ("airport", "A child hides behind her mother in fright when the robot comes near."),
    ("museum", "A guard stands frozen in fright by the main entrance as the robot rolls up."),
])
def test_real_words_are_not_corrected_into_places(worlds, world, prompt):
    reading = read(worlds, world, prompt)
    assert reading.corrections == ()
    assert not reading.unknown_places


@pytest.mark.parametrize("world, prompt, unknown", [
    ("airport", "Four passengers walk to gate D7.", "gate d7"),
    ("station", "Nine commuters wait on platform 5.", "platform 5"),
    ("hospital", "Two porters walk to the helipad.", "helipad"),
])
def test_a_place_one_edit_from_nothing_or_with_a_foreign_number_is_still_refused(worlds, world, prompt, unknown):
    reading = read(worlds, world, prompt)
    assert unknown in reading.unknown_places, reading.unknown_places
    assert reading.corrections == ()


@pytest.mark.parametrize("world, prompt, start, destination", [
    ("hospital", "The pharmacy empties out into the main corridor when the alarm sounds.", "pharmacy", "main_corridor"),
    ("office", "Smoke everywhere: the kitchen clears out through the fire exit.", "kitchen", "fire_exit"),
    ("station", "Within a minute the whole waiting room empties.", "waiting_room", None),
    ("airport", "When the alarm goes off, gate A2 clears out; its passengers run to the west fire exit.", "gate_a2",
     "emergency_exit_west"),
])
def test_a_zone_that_empties_is_where_everyone_leaves_from(worlds, world, prompt, start, destination):
    group = one(read(worlds, world, prompt))
    assert (group.intent, group.start, group.destination) == ("evacuate", start, destination)


def test_clearing_an_object_or_a_clear_room_is_no_evacuation(worlds):
    group = one(read(worlds, "office", "A cleaner clears the tables in the kitchen."))
    assert group.intent != "evacuate"
    reading = read(worlds, "office", "The kitchen is clear and quiet.")
    assert nobody_named(reading) and reading.groups[0].intent != "evacuate"


@pytest.mark.parametrize("world, prompt, rest, exception", [
    ("hospital", "Everyone in the cafeteria walks to ward A except two cooks, who stay put.",
     ("walk", "cafeteria", "ward_a"), (2, "wait", "cafeteria")),
    ("office", "Everybody except the manager leaves through the back door.",
     ("walk", None, "back_exit"), (1, "wait", None)),
    ("residential", "Everyone in the kitchen goes to the balcony except dad.",
     ("walk", "kitchen", "balcony"), (1, "wait", "kitchen")),
    ("station", "Everyone on platform 1 gets on the train apart from a guard.",
     ("walk", "platform_1", None), (1, "wait", "platform_1")),
])
def test_everyone_except_some_is_two_groups(worlds, world, prompt, rest, exception):
    reading = read(worlds, world, prompt)
    assert len(reading.groups) == 2, [g.who for g in reading.groups]
    everyone, excepted = reading.groups
    assert (everyone.intent, everyone.start, everyone.destination) == rest
    assert (excepted.count.value, excepted.intent, excepted.location) == exception


def test_everyone_who_has_already_left_is_not_in_the_scenario(worlds):
    reading = read(worlds, "hospital", "Everybody has left the ward except one nurse at the nurse station.")
    group = one(reading)
    assert (group.count.value, group.location) == (1, "nurse_station")
    assert any("already left" in n for n in reading.notes)


@pytest.mark.parametrize("world, prompt, intent, place", [
    ("airport", "Everyone at gate A1 boards the plane.", "walk", ("start", "gate_a1")),
    ("airport", "Twelve travellers in the baggage hall queue at the lost and found.", "queue",
     ("location", "lost_luggage_desk")),
])
def test_a_verb_that_is_also_a_place_word_ends_the_place_before_it(worlds, world, prompt, intent, place):
    group = one(read(worlds, world, prompt))
    assert group.intent == intent and getattr(group, place[0]) == place[1]


@pytest.mark.parametrize("world, prompt, kind, low, high, location", [
    ("hospital", "A long line of roughly twenty visitors stretches back from the reception desk.", "approximate",
     16, 24, "reception_desk"),
    ("station", "A queue of around ten commuters winds out of the newsagent.", "approximate", 8, 12, "newsagent"),
    ("office", "A short queue of four people waiting for the coffee machine.", "exact", 4, 4, "coffee_machine"),
])
def test_a_queue_noun_counts_the_people_inside_it_and_stands_at_its_head(worlds, world, prompt, kind, low, high,
                                                                        location):
    group = one(read(worlds, world, prompt))
    assert (group.intent, group.count.kind, group.location) == ("queue", kind, location)
    assert low <= group.count.value <= high and group.start is None


@pytest.mark.parametrize("world, prompt, low, high", [
    ("airport", "A couple of dozen passengers wait at gate A2.", 20, 28),
    ("station", "A crowd of about sixty fans waits on the concourse.", 48, 72),
])
def test_loose_counts_inside_collectives_and_dozens(worlds, world, prompt, low, high):
    group = one(read(worlds, world, prompt))
    assert low <= group.count.value <= high and group.count.kind == "approximate"


@pytest.mark.parametrize("world, prompt, counts, label", [
    ("residential", "An au pair walks from the kitchen to the hallway.", [1], "au pair"),
    ("station", "The station master waits on platform 2.", [1], "station master"),
    ("airport", "A tour guide and nine tourists wait at the meeting point.", [1, 9], "tour guide"),
])
def test_people_named_by_two_words_are_one_person(worlds, world, prompt, counts, label):
    reading = read(worlds, world, prompt)
    assert [g.count.value for g in reading.groups] == counts
    assert reading.groups[0].label == label


@pytest.mark.parametrize("world, prompt, who", [
    ("residential", "Three dogs sleep in the hallway while two children play in the kids room.", ["two children"]),
    ("office", "Four fans hum in the server room while an engineer waits there.", ["an engineer"]),
    ("hospital", "Two trolleys stand by the lifts and a porter walks to ward A.", ["a porter"]),
    ("office", "When the robot rolls into the boardroom, two managers watch it.", ["two managers"]),
])
def test_animals_things_and_the_robot_are_nobody(worlds, world, prompt, who):
    assert [g.who for g in read(worlds, world, prompt).groups] == who


@pytest.mark.parametrize("world, prompt, label, location", [
    ("station", "A juggler performs in the ticket hall.", "juggler", "ticket_hall"),
    ("airport", "A violinist plays near the café counter.", "violinist", "cafe_counter"),
])
def test_an_agent_noun_doing_something_is_a_person(worlds, world, prompt, label, location):
    group = one(read(worlds, world, prompt))
    assert (group.label, group.location) == (label, location)


@pytest.mark.parametrize("world, prompt, count, intent, places", [
    ("office", "Three interns haul chairs from the kitchen to the boardroom.", 3, "walk",
     {"start": "kitchen", "destination": "boardroom"}),
    ("station", "At 7:40 the commuters on platform 1 walk to the concourse.", 3, "walk",
     {"start": "platform_1", "destination": "concourse"}),
    ("hospital", "Nobody sits in the cafeteria; instead six visitors wait in the lobby.", 6, "wait",
     {"location": "entrance_lobby"}),
    ("airport", "Send twelve passengers from the concourse to gate B1.", 12, "walk",
     {"start": "concourse", "destination": "gate_b1"}),
    ("office", "In the evening two cleaners leave through the back door.", 2, "walk", {"destination": "back_exit"}),
    ("hospital", "Two porters wheel a trolley along the main corridor.", 2, "walk", {"via": ("main_corridor",)}),
])
def test_subjects_found_past_parser_slips_and_ways_out(worlds, world, prompt, count, intent, places):
    group = one(read(worlds, world, prompt))
    assert group.intent == intent and (group.count.value == count or group.count.low <= count <= group.count.high)
    for role, place in places.items():
        assert getattr(group, role) == place, (role, group)


@pytest.mark.parametrize("world, prompt, intent, places", [
    ("office", "The engineers who were sitting in the boardroom walk to the kitchen.", "walk",
     {"start": "boardroom", "destination": "kitchen"}),
    ("airport", "Passengers who are waiting at gate A1 queue at the A1 desk.", "queue", {"location": "gate_a1_desk"}),
])
def test_a_relative_clause_says_who_not_what_they_do(worlds, world, prompt, intent, places):
    group = one(read(worlds, world, prompt))
    assert group.intent == intent
    for role, place in places.items():
        assert getattr(group, role) == place


@pytest.mark.parametrize("world, prompt, interaction", [
    ("hospital", "Two toddlers waddle over to the robot.", "approach"),
    ("office", "Some interns gather round the robot in the kitchen.", "approach"),
    ("station", "A drunk fan refuses to let the robot through the gates.", "block"),
])
def test_robot_interactions_from_any_verb_of_walking_gathering_or_refusing(worlds, world, prompt, interaction):
    group = one(read(worlds, world, prompt))
    assert (group.intent, group.robot_interaction) == ("robot", interaction)


def test_the_doer_of_a_passive_approach_walks_there(worlds):
    group = one(read(worlds, "office", "The printer is approached by two engineers."))
    assert (group.intent, group.destination) == ("walk", "printer")


def test_compound_plurals_of_child_and_man(worlds):
    group = one(read(worlds, "station", "Three businessmen and no one else wait in the waiting room."))
    assert group.label == "businessman"
    assert one(read(worlds, "airport", "Ten schoolchildren walk to gate A1.")).label == "schoolchild"


def test_a_thing_that_goes_off_is_nobody(worlds):
    reading = read(worlds, "office", "When the smoke detectors go off, two engineers leave by the fire exit.")
    assert [g.who for g in reading.groups] == ["two engineers"]


@pytest.mark.parametrize("world, prompt, seconds, location", [
    ("office", "A courier waits ten minutes at the front desk.", 600.0, "reception_desk"),
    ("residential", "Grandma sits half an hour on the sofa.", 1800.0, "sofa"),
])
def test_a_wait_with_a_duration_but_no_for(worlds, world, prompt, seconds, location):
    group = one(read(worlds, world, prompt))
    assert (group.intent, group.wait_seconds, group.location) == ("wait", seconds, location)


@pytest.mark.parametrize("world, prompt, role, place", [
    ("hospital", "No visitors are allowed in ward C, but a nurse is working.", "location", None),
    ("station", "No trains stop at platform 1, but a porter sweeps platform 2.", "location", "platform_2"),
    ("airport", "Nobody uses the arrivals corridor; six pilots walk to gate B2.", "via", ()),
])
def test_a_clause_about_nobody_sets_no_scene(worlds, world, prompt, role, place):
    group = one(read(worlds, world, prompt))
    assert getattr(group, role) == place


def test_one_of_several_places(worlds):
    group = one(read(worlds, "office", "An engineer sits at one of the desks in the open office."))
    assert group.location == "open_plan_office"


@pytest.mark.parametrize("world, prompt, start", [
    ("hospital", "A gas leak is reported, so the pharmacy must be cleared; ten people leave by the main entrance.",
     "pharmacy"),
    ("office", "Because of the smoke the boardroom needs to be emptied and six managers head to the fire exit.",
     "boardroom"),
])
def test_a_zone_emptied_in_the_passive_anywhere_in_the_sentence(worlds, world, prompt, start):
    group = one(read(worlds, world, prompt))
    assert (group.intent, group.start, group.purpose) == ("evacuate", start, None)


def test_a_verb_no_list_names_with_a_place_object_is_the_groups_own_action(worlds):
    reading = read(worlds, "office", "A cleaner polishes the main corridor, two interns walk to the kitchen.")
    cleaner = reading.groups[0]
    assert (cleaner.intent, cleaner.location, cleaner.destination) == ("wait", "main_corridor", None)


@pytest.mark.parametrize("world, prompt, leader, led", [
    ("hospital", "Two porters escort six patients from the lobby to radiology.", 2, 6),
    ("station", "A guide leads fifteen students from the ticket hall to platform 1.", 1, 15),
])
def test_a_counted_group_led_by_someone_follows_the_same_route(worlds, world, prompt, leader, led):
    reading = read(worlds, world, prompt)
    assert [g.count.value for g in reading.groups] == [leader, led]
    first, second = reading.groups
    assert first.intent == "walk" and second.intent == "follow" and second.follows == first.who
    assert first.destination == second.destination is not None


@pytest.mark.parametrize("world, prompt, low, high", [
    ("residential", "Her parents wait in the living room.", 2, 2),
    ("residential", "The grandparents sit on the balcony.", 2, 4),
    ("hospital", "Parents wait in the main waiting room.", 3, 6),  # no family said: a bare plural
])
def test_family_plurals_said_of_one_family(worlds, world, prompt, low, high):
    group = one(read(worlds, world, prompt))
    assert (group.count.low, group.count.high) == (low, high)


@pytest.mark.parametrize("world, prompt, counts", [
    ("residential", "Dad and three guests walk from the hallway to the balcony.", [1, 3]),
    ("office", "The boss and the receptionist talk at the front desk.", [1, 1]),
])
def test_a_bare_person_joined_by_and_is_a_subject_of_its_own(worlds, world, prompt, counts):
    assert [g.count.value for g in read(worlds, world, prompt).groups] == counts


@pytest.mark.parametrize("world, prompt, role, place", [
    ("office", "Three developers chat in the far corner of the open office.", "location", "open_plan_office"),
    ("hospital", "A porter sweeps the floor of the cafeteria.", "location", "cafeteria"),
    ("station", "Two guards walk to the end of platform 2.", "destination", "platform_2"),
])
def test_a_part_of_a_place_is_the_place(worlds, world, prompt, role, place):
    group = one(read(worlds, world, prompt))
    assert getattr(group, role) == place


def test_leaving_at_once_is_an_evacuation_but_leaving_by_a_door_is_not(worlds):
    assert one(read(worlds, "office", "All the staff in the kitchen must exit immediately by the back door.")
               ).intent == "evacuate"
    assert one(read(worlds, "office", "Five visitors must leave by the main entrance.")).intent == "walk"


def test_places_of_animals_are_not_refused_but_those_of_an_alarm_are(worlds):
    reading = read(worlds, "hospital", "Three pigeons strut on a ledge while a porter naps in the staff room.")
    assert one(reading).location == "staff_room"
    reading = read(worlds, "hospital", "When the alarm sounds in the chapel, two nurses walk to the lobby.")
    assert "chapel" in reading.unknown_places


def test_a_misspelt_plural_place_word_is_corrected_to_the_plural(worlds):
    reading = read(worlds, "airport", "Three pilots sit on the A1 seets.")
    assert one(reading).location == "gate_a1_seats"
    assert reading.corrections == ("read 'seets' as 'seats'",)


def test_a_service_and_its_number_is_no_place(worlds):
    reading = read(worlds, "station", "Passengers off train 2C41 wait on platform 1.")
    assert one(reading).location == "platform_1"
    reading = read(worlds, "airport", "Travellers from flight EZY808 walk to baggage claim.")
    assert one(reading).destination == "baggage_claim"


def test_a_word_that_names_no_place_is_no_place_though_an_alias_shares_it(worlds):
    group = one(read(worlds, "station", "Travellers step off the train and walk to the café."))
    assert (group.start, group.destination) == (None, "cafe")


def test_everyone_who_has_gone_is_no_group_in_a_time_clause_either(worlds):
    reading = read(worlds, "office", "Two cleaners vacuum the boardroom after everybody has left.")
    assert [g.who for g in reading.groups] == ["Two cleaners"]


@pytest.mark.parametrize("world, prompt, start, destination", [
    ("hospital", "At noon, half the cafeteria walks back to ward A.", "cafeteria", "ward_a"),
    ("station", "Half of the commuters on platform 2 head to the concourse.", "platform_2", "concourse"),
])
def test_half_of_a_zone_or_of_its_people_is_half_a_whole_zone_count(worlds, world, prompt, start, destination):
    group = one(read(worlds, world, prompt))
    assert (group.start, group.destination, group.count.kind) == (start, destination, "whole_zone")
    full = one(read(worlds, world, prompt.replace("half the", "everyone in the").replace("Half of the commuters",
                                                                                         "All the commuters")))
    assert group.count.high <= (full.count.high + 1) // 2 + 1


def test_half_an_hour_and_half_a_dozen_stay_what_they_were(worlds):
    group = one(read(worlds, "station", "Half a dozen tourists wait half an hour on the concourse."))
    assert (group.count.value, group.wait_seconds) == (6, 1800.0)


def test_what_a_person_is_in_or_on_is_no_place_to_refuse(worlds):
    reading = read(worlds, "hospital", "A man in a wheelchair waits in the main waiting room.")
    assert one(reading).location == "main_waiting_room"
    assert "chapel" in read(worlds, "hospital", "Two nurses walk to a chapel.").unknown_places


def test_hundreds_and_scores_are_vague_counts(worlds):
    group = one(read(worlds, "station", "Hundreds of fans walk from platform 1 to the concourse."))
    assert group.count.kind == "vague" and 100 <= group.count.value <= 300
    assert 40 <= one(read(worlds, "station", "Scores of commuters wait on platform 2.")).count.value <= 80


def test_british_words_for_the_tv(worlds):
    group = one(read(worlds, "residential", "Two kids sit in front of the telly."))
    assert group.location == "tv" and not read(worlds, "residential", "Two kids sit in front of the telly.").unknown_places


def test_the_persons_own_things_are_no_place_and_their_own_people_no_group(worlds):
    reading = read(worlds, "hospital", "A surgeon on his break walks from ward B to the cafeteria.")
    assert one(reading).destination == "cafeteria"
    reading = read(worlds, "station", "Two tourists with their kids wait in the waiting room.")
    assert one(reading).location == "waiting_room"


def test_a_three_letter_misspelling_is_corrected_only_inside_a_name(worlds):
    reading = read(worlds, "station", "Two porters walk from the booking hal to platform 2.")
    assert one(reading).start == "ticket_hall" and reading.corrections == ("read 'hal' as 'hall'",)
    assert read(worlds, "office", "Two colleagues walk to the gym.").unknown_places == ("gym",)


def test_the_rest_and_the_exception_with_the_rests_place_between_them(worlds):
    reading = read(worlds, "airport", "All the travellers at gate B1 except two walk to the café.")
    rest, exception = reading.groups
    assert (rest.start, rest.destination, rest.intent) == ("gate_b1", "cafe", "walk")
    assert (exception.count.value, exception.intent, exception.location) == (2, "wait", "gate_b1")
