"""Round 72: hazards said without a word of fire (trouble that breaks out, a pot that catches on the
stove) make leaving an evacuation (trouble_events); talk said by what is swapped with words between
("swap old school stories") is conversing and people who snake back from a desk queue at it
(spanned_intents)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


def _groups(world: str, sentence: str):
    return read_prompt(sentence, load_world(W + world + ".yaml")).groups


@pytest.mark.parametrize("world, sentence", [
    ("restaurant", "A frying pan catches on the hob and the forty diners in the main dining room leave by the front door."),
    ("nightclub", "A fight breaks out, the main floor is closed and the two hundred clubbers are ushered out to the queue pen."),
    ("nightclub", "A scuffle erupts by the bar; the dance floor is cleared and its clubbers are moved to the smoking terrace."),
])
def test_trouble_or_a_pot_catching_makes_leaving_an_evacuation(world, sentence):
    assert _groups(world, sentence)[-1].intent == "evacuate"


def test_fighting_ones_way_through_is_no_hazard():
    g = _groups("nightclub", "Two friends fight their way through the crowd to the upstairs bar.")
    assert g[0].intent == "walk"


def test_people_snaking_back_from_a_desk_queue_at_it():
    g = _groups("gp_surgery", "A dozen patients snake back from the reception desk, waiting to check in.")
    assert g[0].intent == "queue" and g[0].location == "reception_desk"


def test_stories_swapped_with_words_between_are_talk():
    assert _groups("gp_surgery", "Two friends swap old school stories in the waiting area.")[0].intent == "converse"


def test_sharing_a_sandwich_is_no_talk():
    assert _groups("gp_surgery", "Two nurses share a sandwich in the staff kitchen.")[0].intent == "wait"
