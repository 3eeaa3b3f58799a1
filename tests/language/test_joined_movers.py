"""People joined by "and" who move someone along (language/escorted.py `share_with_joined_movers`,
language/leading_verb_tags.py): every one of them takes the moved person's route, and "a nurse wheel" after
"A porter and" is the verb, not one noun. A verb after "to" with an object is no place
(language/infinitive_verbs.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

JOINED = [
    ("museum", "A guard and two volunteers wheel a fainting visitor from the great hall to the cafe.",
     ["guard", "volunteer"], "great_hall", "cafe"),
    ("station", "A guard and a cleaner push an elderly traveller from the concourse to the waiting room.",
     ["guard", "cleaner"], "concourse", "waiting_room"),
    ("mall", "A security guard and a shop assistant wheel Mrs Okoro from the food court to the pharmacy.",
     ["guard", "assistant"], "food_court", "pharmacy"),
]
INFINITIVES = [
    ("airport", "The robot parks by gate A1 and a guard strolls over to check it.", "check_in_hall"),
    ("airport", "A cleaner goes over to check the robot", "check_in_hall"),
    ("mall", "a guard wanders over to check on the robot", "information_desk"),
]


@pytest.mark.parametrize("world, sentence, movers, start, destination", JOINED)
def test_everyone_joined_to_the_movers_takes_the_route(world, sentence, movers, start, destination):
    groups = read_prompt(sentence, load_world(world)).groups
    by_label = {g.label.split("-")[-1].split("_")[-1]: g for g in groups}
    for label in movers:
        group = next(g for key, g in by_label.items() if key.endswith(label))
        assert (group.intent, group.start, group.destination) == ("walk", start, destination), label
    assert any(g.intent == "follow" and g.destination == destination for g in groups)


@pytest.mark.parametrize("world, sentence, not_there", INFINITIVES)
def test_a_verb_with_an_object_after_to_is_no_place(world, sentence, not_there):
    reading = read_prompt(sentence, load_world(world))
    assert all(not_there not in (g.destination, g.location) for g in reading.groups)
    assert not reading.unknown_places


def test_go_to_check_in_still_finds_the_check_in_place():
    group = read_prompt("Two travellers go to check in at the kiosks.", load_world("airport")).groups[0]
    assert group.destination == "check_in_kiosks"
