"""The prompt reader (language/reading.py) on many phrasings per class, built combinatorially.

Every test reads with the real spaCy pipeline and the shipped worlds; the expected reading is
stated per phrasing class, never tuned to one sentence.
"""

from __future__ import annotations

import itertools

import pytest

from grove_tui.language import lexicon as lx
from grove_tui.language.reading import Count, GroupReading, PromptReading, effective_counts, read_prompt


def one(reading: PromptReading) -> GroupReading:
    assert len(reading.groups) == 1, [g.who for g in reading.groups]
    return reading.groups[0]


NUMBERS = {"two": 2, "3": 3, "five": 5, "twelve": 12, "twenty": 20, "twenty five": 25, "a dozen": 12}
NOUNS = {"patients": "patient", "visitors": "visitor", "nurses": "nurse", "people": "person",
         "elderly women": "woman", "staff members": "staff"}
WALKS = ["walk to the cafeteria", "go to the cafeteria", "head to the canteen", "are walking to the cafeteria",
         "hurry into the cafeteria"]


@pytest.mark.parametrize("number,noun,verb", list(itertools.product(NUMBERS, NOUNS, WALKS[:3])))
def test_exact_counts_labels_and_destinations(hospital, number, noun, verb):
    g = one(read_prompt(f"{number.capitalize()} {noun} {verb}.", hospital))
    assert g.count == Count("exact", NUMBERS[number], NUMBERS[number], NUMBERS[number])
    assert g.label == NOUNS[noun]
    assert g.intent == "walk" and g.destination == "cafeteria"


@pytest.mark.parametrize("word", sorted(lx.APPROXIMATE_WORDS - {"some", "maybe", "perhaps", "circa"}))
@pytest.mark.parametrize("number,value", [("twenty", 20), ("10", 10), ("thirty", 30)])
def test_approximate_counts_keep_the_number_with_a_range(hospital, word, number, value):
    g = one(read_prompt(f"{word.capitalize()} {number} visitors wait in the lobby.", hospital))
    assert g.count.kind == "approximate" and g.count.value == value
    assert g.count.low < value < g.count.high
    assert g.intent == "wait" and g.location == "entrance_lobby"


@pytest.mark.parametrize("phrase,word", [("A few", "few"), ("Several", "several"), ("Some", "some"),
                                         ("A handful of", "handful"), ("Many", "many")])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_vague_counts_are_seeded_inside_their_documented_range(hospital, phrase, word, seed):
    g = one(read_prompt(f"{phrase} patients wander around the waiting room.", hospital, seed=seed))
    low, high = lx.VAGUE_RANGES[word]
    assert g.count.kind == "vague" and (g.count.low, g.count.high) == (low, high)
    assert low <= g.count.value <= high
    again = one(read_prompt(f"{phrase} patients wander around the waiting room.", hospital, seed=seed))
    assert again.count == g.count  # deterministic per seed
    assert g.intent == "wander" and g.location == "main_waiting_room"


@pytest.mark.parametrize("phrase,noun,label", [("A family", "family", "family"), ("A couple", "couple", "couple"),
                                               ("A group of visitors", "group", "visitor"),
                                               ("A pair", "pair", "pair")])
@pytest.mark.parametrize("verb", ["walks to the pharmacy", "walk together to the pharmacy"])
def test_implied_counts_of_collectives(hospital, phrase, noun, label, verb):
    g = one(read_prompt(f"{phrase} {verb}.", hospital))
    low, high = lx.IMPLIED_RANGES[noun]
    assert g.count.kind in ("implied", "exact") and low <= g.count.value <= high
    assert g.label == label and g.together and g.destination == "pharmacy"


@pytest.mark.parametrize("phrase", ["A couple of nurses", "A pair of nurses", "Two nurses"])
def test_a_couple_of_people_is_two(hospital, phrase):
    g = one(read_prompt(f"{phrase} walk to the pharmacy.", hospital))
    assert g.count == Count("exact", 2, 2, 2) and g.label == "nurse"


def test_a_crowd_is_many_people_not_one_party(hospital):
    g = one(read_prompt("A crowd gathers in the lobby.", hospital))
    assert g.count.kind == "implied" and 15 <= g.count.value <= 30
    assert g.label == "crowd" and g.location == "entrance_lobby"


@pytest.mark.parametrize("parties_word,parties", [("Two", 2), ("three", 3), ("4", 4)])
@pytest.mark.parametrize("collective", ["families", "groups"])
@pytest.mark.parametrize("size_word,size", [("three", 3), ("four", 4), ("2", 2)])
def test_structured_counts_are_parties_of_a_size(hospital, parties_word, parties, collective, size_word, size):
    g = one(read_prompt(f"{parties_word} {collective} of {size_word} walk together to the exit.", hospital))
    assert g.count == Count("structured", parties * size, parties * size, parties * size, parties, size)
    assert g.label not in lx.NUMBER_WORDS and not g.label.isdigit()
    assert g.together


@pytest.mark.parametrize("who", ["Everyone", "Everybody", "All the people"])
@pytest.mark.parametrize("zone,alias", [("cafeteria", "canteen"), ("main_waiting_room", "waiting room"),
                                        ("staff_room", "break room")])
def test_whole_zone_counts_fill_the_zone_at_a_density(hospital, who, zone, alias):
    g = one(read_prompt(f"{who} in the {alias} walks to the main entrance.", hospital))
    area = hospital.zone(zone).area
    assert g.count.kind == "whole_zone"
    assert g.count.low == max(1, min(lx.WHOLE_ZONE_CAP, round(area * lx.WHOLE_ZONE_DENSITY[0])))
    assert g.count.low <= g.count.value <= g.count.high <= lx.WHOLE_ZONE_CAP
    assert g.start == zone and g.destination == "main_entrance"


@pytest.mark.parametrize("frame", ["Nobody is here except {who}, who waits in the {place}.",
                                   "No one is in the {place} except {who}.",
                                   "The {place} is empty except for {who}."])
@pytest.mark.parametrize("who,value,label", [("one guard", 1, "guard"), ("a cleaner", 1, "cleaner"),
                                             ("two nurses", 2, "nurse")])
def test_exclusive_counts_and_no_false_unknown_place(hospital, frame, who, value, label):
    reading = read_prompt(frame.format(who=who, place="cafeteria"), hospital)
    g = one(reading)
    assert g.count.kind == "exclusive" and g.count.value == value and g.label == label
    assert g.location == "cafeteria" and g.intent == "wait"
    assert reading.unknown_places == ()


INTENT_PHRASES = {
    "queue": ["queue at the pharmacy counter", "line up at the pharmacy counter", "wait in line at the pharmacy counter",
              "are queuing at the pharmacy counter", "stand in line at the pharmacy counter"],
    "wait": ["wait at the pharmacy counter", "sit near the pharmacy counter", "stand by the pharmacy counter",
             "are waiting at the pharmacy counter", "rest at the pharmacy counter"],
    "converse": ["chat at the pharmacy counter", "talk at the pharmacy counter", "are chatting at the pharmacy counter",
                 "have a chat at the pharmacy counter"],
    "wander": ["wander around the pharmacy", "stroll around the pharmacy", "mill around the pharmacy",
               "walk around the pharmacy", "roam the pharmacy"],
}


@pytest.mark.parametrize("intent,verb", [(k, v) for k, vs in INTENT_PHRASES.items() for v in vs])
@pytest.mark.parametrize("subject", ["Four visitors", "Some patients", "A couple"])
def test_stationary_intents_have_a_location(hospital, intent, verb, subject):
    g = one(read_prompt(f"{subject} {verb}.", hospital))
    assert g.intent == intent
    assert g.location in ("pharmacy_counter", "pharmacy") and g.destination is None


@pytest.mark.parametrize("duration,seconds", [("five minutes", 300.0), ("30 seconds", 30.0), ("an hour", 3600.0),
                                              ("half an hour", 1800.0), ("two minutes", 120.0), ("a minute", 60.0)])
@pytest.mark.parametrize("frame", ["A parent waits in the hallway for {d}.", "Two men sit on the bench for {d}.",
                                   "Visitors wait for {d} in the lobby."])
def test_waits_with_durations(hospital, duration, seconds, frame):
    g = one(read_prompt(frame.format(d=duration), hospital))
    assert g.intent == "wait" and g.wait_seconds == seconds
    assert g.location is not None and g.purpose is None


ROBOT_PHRASES = {
    "look": ["stares at the robot", "looks at the robot", "watches the robot", "glances at the robot"],
    "approach": ["approaches the robot", "walks up to the robot", "goes up to the robot", "greets the robot"],
    "follow": ["follows the robot", "walks behind the robot", "trails the robot"],
    "avoid": ["avoids the robot", "keeps away from the robot", "steps aside for the robot", "stays away from the robot"],
    "block": ["blocks the robot", "stands in front of the robot", "gets in the way of the robot", "obstructs the robot"],
}


@pytest.mark.parametrize("interaction,phrase", [(k, v) for k, vs in ROBOT_PHRASES.items() for v in vs])
@pytest.mark.parametrize("subject", ["Someone", "A visitor", "One nurse"])
def test_robot_interactions_map_to_hunavsim_reactions(hospital, interaction, phrase, subject):
    g = one(read_prompt(f"{subject} {phrase} in the lobby.", hospital))
    assert g.intent == "robot" and g.robot_interaction == interaction
    assert g.robot_reaction == lx.ROBOT_REACTIONS[interaction]
    assert g.count.value == 1


@pytest.mark.parametrize("start_phrase,start", [("from the lobby", "entrance_lobby"), ("from the pharmacy", "pharmacy"),
                                                ("out of the staff room", "staff_room")])
@pytest.mark.parametrize("dest_phrase,dest", [("to ward a", "ward_a"), ("into the cafeteria", "cafeteria"),
                                              ("towards the main entrance", "main_entrance")])
@pytest.mark.parametrize("via_phrase,via", [("", None), ("through the main corridor", "main_corridor"),
                                            ("past the nurse station", "nurse_station")])
def test_places_by_role(hospital, start_phrase, start, dest_phrase, dest, via_phrase, via):
    prompt = f"Six visitors walk {start_phrase} {via_phrase} {dest_phrase}."
    g = one(read_prompt(prompt, hospital))
    assert (g.start, g.destination) == (start, dest)
    assert g.via == ((via,) if via else ())


@pytest.mark.parametrize("zone_phrase,zone", [("the pharmacy", "pharmacy"), ("the cafeteria", "cafeteria"),
                                              ("the waiting room", "main_waiting_room")])
@pytest.mark.parametrize("exit_phrase,exit_name", [("the main entrance", "main_entrance"),
                                                   ("the west exit", "west_emergency_exit")])
@pytest.mark.parametrize("frame", ["Evacuate {z}: twenty people leave by {e}.",
                                   "Evacuate {z}. Twenty people leave through {e}.",
                                   "Twenty people evacuate {z} through {e}."])
def test_evacuating_a_named_zone_starts_there(hospital, zone_phrase, zone, exit_phrase, exit_name, frame):
    g = one(read_prompt(frame.format(z=zone_phrase, e=exit_phrase), hospital))
    assert g.intent == "evacuate" and g.start == zone and g.destination == exit_name and g.count.value == 20


@pytest.mark.parametrize("purpose", ["to register", "to check in", "to pick up prescriptions", "for coffee",
                                     "for a snack"])
def test_purposes_are_never_places(worlds, purpose):
    # office has a coffee machine aliased "coffee": a purpose must not be matched to it by name
    for world, counter, place in (("hospital", "the reception desk", "reception_desk"),
                                  ("office", "the front desk", "reception_desk")):
        g = one(read_prompt(f"Five visitors queue at {counter} {purpose}.", worlds[world]))
        assert g.intent == "queue" and g.location == place and g.destination is None
        assert g.purpose == purpose


@pytest.mark.parametrize("word,pace", [("slowly", "slow"), ("quickly", "fast"), ("in a hurry", "fast"),
                                       ("leisurely", "slow"), ("", "normal")])
@pytest.mark.parametrize("verb", ["walk", "go"])
def test_pace(hospital, word, pace, verb):
    g = one(read_prompt(f"Three patients {verb} {word} to the pharmacy.", hospital))
    assert g.pace == pace and g.destination == "pharmacy"


@pytest.mark.parametrize("verb", ["rush", "run", "hurry"])
def test_fast_verbs_walk_fast(hospital, verb):
    g = one(read_prompt(f"Three nurses {verb} to the intensive care unit.", hospital))
    assert g.intent == "walk" and g.pace == "fast" and g.destination == "intensive_care"


@pytest.mark.parametrize("phrase", ["together", "as a group", "side by side"])
def test_togetherness(hospital, phrase):
    g = one(read_prompt(f"Four friends walk {phrase} to the cafeteria.", hospital))
    assert g.together and g.count.value == 4 and g.destination == "cafeteria"


JOINERS = [", while", " and", ". Meanwhile,", "; ", ", and", " while"]
SECOND = [("a few others stroll around the lobby", "wander", "entrance_lobby", "others_of:0"),
          ("two nurses chat in the staff room", "converse", "staff_room", None),
          ("some visitors wait in the waiting room", "wait", "main_waiting_room", None),
          ("a family queues at the reception desk", "queue", "reception_desk", None)]


@pytest.mark.parametrize("joiner", JOINERS)
@pytest.mark.parametrize("second,intent,location,relation", SECOND)
def test_compound_sentences_keep_the_second_group(hospital, joiner, second, intent, location, relation):
    prompt = f"Ten patients walk to the pharmacy{joiner} {second}."
    reading = read_prompt(prompt, hospital)
    assert len(reading.groups) == 2, [g.who for g in reading.groups]
    first, other = reading.groups
    assert first.count.value == 10 and first.intent == "walk" and first.destination == "pharmacy"
    assert other.intent == intent and other.location == location and other.relation == relation


@pytest.mark.parametrize("third", ["someone stares at the robot", "one of them avoids the robot"])
def test_three_groups(hospital, third):
    prompt = f"Twelve visitors walk to the cafeteria, two nurses chat in the staff room, and {third}."
    reading = read_prompt(prompt, hospital)
    assert [g.intent for g in reading.groups] == ["walk", "converse", "robot"]
    assert reading.groups[2].count.value == 1


def test_relations_one_of_them_the_others_and_more(hospital):
    reading = read_prompt("Twenty people leave by the main entrance and one of them follows the robot, "
                          "while the others walk to the cafeteria. A few more wait in the lobby.", hospital)
    parent, subset, others, more = reading.groups
    assert subset.relation == "subset_of:0" and subset.robot_interaction == "follow" and subset.count.value == 1
    assert others.relation == "others_of:0" and others.count.value == 19
    assert more.relation == "more_of:0" and more.intent == "wait"
    assert effective_counts(reading) == {1: 1, 2: 19, 3: more.count.value}  # parent is split into the two


def test_shared_predicate_gives_both_groups_the_action(hospital):
    reading = read_prompt("Ten people in the cafeteria and five in the pharmacy walk to the main exit.", hospital)
    assert [(g.count.value, g.start, g.destination) for g in reading.groups] == [
        (10, "cafeteria", "main_entrance"), (5, "pharmacy", "main_entrance")]


@pytest.mark.parametrize("prompt", [
    "Nobody is here except one guard.", "Ten people walk around the hospital.", "Five people leave the building.",
    "Visitors walk to the pharmacy at the same time.", "Two nurses walk in a hurry to the cafeteria.",
    "A man follows the nurse to the pharmacy.", "Ten people wait in line at the pharmacy counter.",
    "Patients walk to the pharmacy with their children.", "The robot passes while visitors walk to the cafeteria.",
])
def test_words_for_people_time_manner_and_the_building_are_never_unknown_places(hospital, prompt):
    assert read_prompt(prompt, hospital).unknown_places == ()


@pytest.mark.parametrize("place", ["swimming pool", "gift shop", "rooftop helipad"])
@pytest.mark.parametrize("frame", ["Ten people walk to the {p}.", "Five visitors wait in the {p}.",
                                   "Two nurses come from the {p}."])
def test_unknown_places_in_a_place_role_are_reported(hospital, place, frame):
    reading = read_prompt(frame.format(p=place), hospital)
    assert reading.unknown_places == (place,)


def test_reading_round_trips_through_json(hospital):
    reading = read_prompt("Two families of three walk together to the cafeteria, while someone stares at the robot.",
                          hospital, seed=3)
    assert PromptReading.from_dict(reading.to_dict()) == reading


def test_labels_are_never_numbers_or_node_names(worlds):
    nodes = {"GoTo", "Queue", "Wander", "Converse", "FollowAgent", "Wait"}
    for world in worlds.values():
        for prompt in ("Two families of three walk together", "Twenty people and ten others wait",
                       "Three of them queue", "a few more wander around", "Five groups walk"):
            for g in read_prompt(prompt, world).groups:
                assert g.label and g.label not in lx.NUMBER_WORDS and not g.label.isdigit() and g.label not in nodes


@pytest.mark.parametrize("noun,label", [("flight attendants", "attendant"), ("dog walkers", "walker"),
                                        ("security guards", "guard"), ("staff members", "staff")])
@pytest.mark.parametrize("verb", ["run to the cafeteria", "head over to the cafeteria"])
def test_compound_person_nouns(hospital, noun, label, verb):
    g = one(read_prompt(f"Twelve {noun} {verb}.", hospital))
    assert g.count.value == 12 and g.label == label and g.destination == "cafeteria"


@pytest.mark.parametrize("who", ["Every visitor", "Every patient", "All the nurses"])
def test_every_x_in_a_zone_is_a_whole_zone_count(hospital, who):
    g = one(read_prompt(f"{who} in the pharmacy goes to the cafeteria.", hospital))
    assert g.count.kind == "whole_zone" and g.start == "pharmacy" and g.destination == "cafeteria"


@pytest.mark.parametrize("frame", ["The only people in the {p} are {w}, wandering around.",
                                   "There is no one in the {p} apart from {w}, who wait there.",
                                   "Apart from {w}, nobody is in the {p}; they wander around."])
def test_more_exclusive_phrasings(hospital, frame):
    g = one(read_prompt(frame.format(p="staff room", w="two nurses"), hospital))
    assert g.count == Count("exclusive", 2, 2, 2) and g.location == "staff_room"


@pytest.mark.parametrize("number,value", [("Fifteen", 15), ("5", 5), ("twenty", 20)])
def test_or_so_is_approximate(hospital, number, value):
    g = one(read_prompt(f"{number} or so visitors head to the lobby.", hospital))
    assert g.count.kind == "approximate" and g.count.value == value


@pytest.mark.parametrize("fronted,check", [
    ("from the pharmacy", lambda g: g.start == "pharmacy"),
    ("for 90 seconds", lambda g: g.wait_seconds == 90.0),
    ("in the lobby", lambda g: g.location == "entrance_lobby" or g.start == "entrance_lobby"),
])
@pytest.mark.parametrize("joiner", [", and", ";", ", while"])
def test_a_fronted_phrase_belongs_to_the_group_after_it(hospital, fronted, check, joiner):
    reading = read_prompt(f"Five nurses walk to the cafeteria{joiner} {fronted}, two visitors wait.", hospital)
    assert len(reading.groups) == 2
    assert reading.groups[0].destination == "cafeteria" and reading.groups[0].wait_seconds is None
    assert check(reading.groups[1])


@pytest.mark.parametrize("negation", ["instead of", "rather than"])
def test_a_place_after_instead_of_is_neither_a_role_nor_unknown(hospital, negation):
    reading = read_prompt(f"Six doctors go to the pharmacy {negation} the waiting room.", hospital)
    g = one(reading)
    assert g.intent == "walk" and g.destination == "pharmacy" and g.location is None
    assert reading.unknown_places == ()


@pytest.mark.parametrize("zone_phrase,zone", [("the pharmacy", "pharmacy"), ("the staff room", "staff_room")])
def test_during_the_evacuation_of_a_zone_people_start_there(hospital, zone_phrase, zone):
    g = one(read_prompt(f"During the evacuation of {zone_phrase}, nine people head to the west exit.", hospital))
    assert g.intent == "evacuate" and g.start == zone and g.destination == "west_emergency_exit"


@pytest.mark.parametrize("tail", ["follows close behind", "follows behind them", "follows them"])
def test_following_the_group_before(hospital, tail):
    reading = read_prompt(f"Three visitors walk to the pharmacy, and a porter {tail}.", hospital)
    assert [g.intent for g in reading.groups] == ["walk", "follow"]


@pytest.mark.parametrize("phrase,interaction", [("stand in the robot's way", "block"), ("get in the robot's way", "block"),
                                                ("tag along behind the robot", "follow"),
                                                ("stop and stare at the robot", "look"),
                                                ("turn to look at the robot", "look")])
def test_robot_phrases_around_the_robot(hospital, phrase, interaction):
    g = one(read_prompt(f"Two guests {phrase}.", hospital))
    assert g.robot_interaction == interaction and g.robot_reaction == lx.ROBOT_REACTIONS[interaction]


@pytest.mark.parametrize("phrase,place", [("the check-in kiosk", "checkin_kiosk"), ("ward b", "ward_b"),
                                          ("the patient room c", "ward_c"), ("exam room 2", "exam_room_2")])
def test_names_with_letters_numbers_and_hyphens(hospital, phrase, place):
    g = one(read_prompt(f"Four visitors go to {phrase}.", hospital))
    assert g.destination == place


@pytest.mark.parametrize("prompt,expected", [
    ("A nurse pushes a cart to ward b while two orderlies stand near the lifts.",
     [("walk", "ward_b", None), ("wait", None, "elevator_hall")]),
    ("Half a dozen kids run around the waiting room as their parents sit on the benches.",
     [("wander", None, "main_waiting_room"), ("wait", None, "lobby_bench_1")]),
    ("Around 30 people are in the cafeteria; a few of them leave through the terrace door.",
     [("wait", None, "cafeteria"), ("walk", "cafeteria_terrace_door", None)]),
])
def test_verbs_the_lexicon_lacks_possessives_and_subsets(hospital, prompt, expected):
    reading = read_prompt(prompt, hospital)
    assert [(g.intent, g.destination, g.location) for g in reading.groups] == expected


@pytest.mark.parametrize("phrase", ["run up to it", "walk over to it", "head towards it"])
def test_it_is_the_robot_once_the_robot_was_named(hospital, phrase):
    g = one(read_prompt(f"When the robot enters the lobby, three children {phrase}.", hospital))
    assert g.robot_interaction == "approach" and g.destination is None


def test_followed_by_a_second_group(worlds):
    reading = read_prompt("The manager walks to the boardroom, followed by two assistants.", worlds["office"])
    manager, assistants = reading.groups
    assert assistants.intent == "follow" and assistants.count.value == 2
    assert assistants.destination == manager.destination == "boardroom"


@pytest.mark.parametrize("who,label", [("Mum", "mum"), ("Grandpa", "grandpa"), ("Her grandson", "grandson")])
def test_a_role_without_a_number_is_one_person(worlds, who, label):
    g = one(read_prompt(f"{who} cooks in the kitchen.", worlds["residential"]))
    assert g.count.value == 1 and g.label == label and g.location == "kitchen"


@pytest.mark.parametrize("verb", ["skip", "bypass"])
def test_a_place_people_skip_is_not_on_their_way(hospital, verb):
    g = one(read_prompt(f"Thirteen people {verb} the pharmacy and go straight to the cafeteria.", hospital))
    assert g.via == () and g.destination == "cafeteria"


@pytest.mark.parametrize("verb", ["gawk", "smile", "point", "wave"])
def test_an_unknown_verb_aimed_at_the_robot_is_looking(hospital, verb):
    g = one(read_prompt(f"A couple of kids {verb} at the robot.", hospital))
    assert g.robot_interaction == "look" and g.count.value == 2
