"""Strategic layer: the RoIs are the places the reading names, plus what the preset needs; places the
world does not have are refused with the closest names; places the reader is unsure of come with
the places it weighed."""

from __future__ import annotations

import math

import pytest

from grove_tui.generation.presets import PromptError, load_preset
from grove_tui.generation.rois import close_matches, describe_selection, reading_places, select_rois
from grove_tui.language.reading import read_prompt
from grove_tui.world import list_worlds, load_world


def select(world, preset, prompt):
    return select_rois(world, load_preset(preset), read_prompt(prompt, world))


def names(selection):
    return [m.name for m in selection.matches]


def test_entity_named_by_two_words_wins_over_every_counter(clinic):
    sel = select(clinic, "queuing", "Ten patients queue at the pharmacy counter")
    assert names(sel) == ["pharmacy_counter", "pharmacy"]
    assert sel.zones == ["pharmacy"] and sel.named_zones == ["pharmacy"]
    assert "coffee_counter" not in sel.summary and "cafeteria" not in sel.summary
    assert sel.summary == "- pharmacy (pharmacy): pharmacy_counter (counter)"
    assert sel.matches[0].reason == "prompt" and sel.matches[0].matched == ("0.location",)


def test_aliases_and_synonyms_select_zones_in_prompt_order(clinic):
    assert select(clinic, "normal", "A family walks from the lobby to the canteen").zones == ["lobby", "cafeteria"]
    assert select(clinic, "normal", "two visitors use the toilet").zones == ["restroom"]
    assert names(select(clinic, "normal", "nurses chat near the check-in")) == ["reception_desk", "lobby"]


def test_irrelevant_zones_are_dropped_from_the_summary(clinic):
    sel = select(clinic, "normal", "people wander in the cafeteria")
    assert sel.zones == ["cafeteria"]
    # The guided summary names only what the draft may use (sel.roi_names), with no coordinates.
    assert sel.summary == "- cafeteria (cafeteria)" and sel.roi_names == ["cafeteria"]


def test_emergency_always_offers_the_exits(clinic):
    sel = select(clinic, "emergency", "a fire alarm empties the pharmacy")
    assert sel.zones == ["pharmacy"]
    assert sel.exits == ["main_entrance", "back_exit"]
    assert {"main_entrance", "back_exit"} <= set(sel.roi_names)
    assert "- exits: main_entrance (in lobby), back_exit (in corridor)" in sel.summary


def test_nothing_named_falls_back_to_the_best_connected_zones(clinic):
    sel = select(clinic, "normal", "people walk around")
    assert sel.zones == ["corridor", "lobby", "cafeteria"]
    assert all(m.reason == "default" for m in sel.matches)


@pytest.mark.parametrize("prompt, phrase", [
    ("ten people swim in the swimming pool", "swimming pool"),
    ("a doctor walks to the helipad", "helipad"),
    ("patients wait at the helipad", "helipad"),
])
def test_unknown_place_is_an_error_with_close_matches(clinic, prompt, phrase):
    with pytest.raises(PromptError, match=f"does not have: '{phrase}' \\(closest: "):
        select(clinic, "normal", prompt)


@pytest.mark.parametrize("prompt", [
    "people walk to the robot in the lobby",
    "at the same time two nurses leave the pharmacy in a hurry",
    "ten patients in line at the pharmacy counter",
    "everyone evacuates through the nearest exit",
    "they walk to the other side of the lobby",
])
def test_non_places_and_qualified_places_are_not_errors(clinic, prompt):
    select(clinic, "normal", prompt)


def test_close_matches_prefer_similar_names(clinic):
    assert close_matches(clinic, "pharmacy counters")[0] == "pharmacy_counter"


def test_vanilla_gets_the_whole_world(clinic):
    sel = select(clinic, "vanilla", "Ten patients queue at the pharmacy counter")
    assert sel.zones == [z.name for z in clinic.zones]
    assert sel.named_zones == ["pharmacy"]
    assert "coffee_counter" in sel.summary and "restroom_door" in sel.summary
    guided = select(clinic, "queuing", "Ten patients queue at the pharmacy counter")
    assert len(guided.summary) * 2 < len(sel.summary)


def test_selection_record_is_json_ready(clinic):
    import json
    record = describe_selection(select(clinic, "queuing", "Ten patients queue at the pharmacy counter"))
    assert json.loads(json.dumps(record))[0]["name"] == "pharmacy_counter"


def test_the_exit_means_the_one_exit_nearest_the_places_named(clinic):
    reading = read_prompt("ten patients queue at the pharmacy while a family walks to the exit", clinic)
    pharmacy = clinic.zone("pharmacy").centroid
    assert reading.groups[1].destination == min(clinic.exits(), key=lambda d: math.dist(d.position, pharmacy)).name
    assert read_prompt("visitors leave through the back exit", clinic).groups[0].destination == "back_exit"


def test_exit_as_a_verb_names_no_place(clinic):
    assert reading_places(read_prompt("five people exit the building", clinic)) == []


def test_places_the_reader_is_unsure_of_come_with_the_places_it_weighed():
    world = load_world("hospital")
    sel = select(world, "normal", "Three patients sit in the main waiting room and one goes to the restroom")
    (ambiguity,) = sel.ambiguous
    assert ambiguity.field == "destination" and set(ambiguity.options) == {"restroom_men", "restroom_women"}
    assert {"restroom_men", "restroom_women"} <= set(sel.roi_names)
    assert [m.reason for m in sel.matches if m.name in ambiguity.options[1:]] == ["alternative"]


@pytest.mark.parametrize("world_name", list_worlds())
def test_every_world_grounds_the_exit_to_exactly_one_exit_door(world_name):
    world = load_world(world_name)
    reading = read_prompt("a group of visitors walks to the exit", world)
    destination = reading.groups[0].destination
    assert destination is not None and world.find(destination).exit
