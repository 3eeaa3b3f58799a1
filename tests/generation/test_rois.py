"""Strategic layer: the prompt's places are found in the world's RoI index; unknown places are refused."""

from __future__ import annotations

import math

import pytest

from grove_tui.generation.presets import PromptError, load_preset
from grove_tui.generation.rois import RoIMatcher, describe_selection, select_rois
from grove_tui.world import list_worlds, load_world


@pytest.fixture(scope="module")
def matcher(clinic):
    return RoIMatcher(clinic)


def names(selection):
    return [m.name for m in selection.matches]


def test_entity_named_by_two_words_wins_over_every_counter(clinic, matcher):
    sel = select_rois(clinic, load_preset("queuing"), "Ten patients queue at the pharmacy counter", matcher)
    assert names(sel) == ["pharmacy_counter", "pharmacy"]
    assert sel.zones == ["pharmacy"] and sel.named_zones == ["pharmacy"]
    assert "coffee_counter" not in sel.summary and "cafeteria" not in sel.summary
    assert sel.summary == "- pharmacy (pharmacy): pharmacy_counter (counter)"


def test_aliases_and_synonyms_select_zones_in_prompt_order(clinic, matcher):
    sel = select_rois(clinic, load_preset("normal"), "A family walks from the lobby to the canteen", matcher)
    assert sel.zones == ["lobby", "cafeteria"]
    sel = select_rois(clinic, load_preset("normal"), "two visitors use the toilet", matcher)
    assert sel.zones == ["restroom"]
    sel = select_rois(clinic, load_preset("normal"), "nurses chat near the check-in", matcher)
    assert names(sel) == ["reception_desk", "lobby"]


def test_irrelevant_zones_are_dropped_from_the_summary(clinic, matcher):
    sel = select_rois(clinic, load_preset("normal"), "people wander in the cafeteria", matcher)
    assert sel.zones == ["cafeteria"]
    assert "lobby" not in sel.summary and "- cafeteria (cafeteria)" in sel.summary
    # The guided summary names only what the draft may use (sel.roi_names), with no coordinates.
    assert sel.summary == "- cafeteria (cafeteria)" and sel.roi_names == ["cafeteria"]


def test_emergency_always_offers_the_exits(clinic, matcher):
    sel = select_rois(clinic, load_preset("emergency"), "a fire alarm empties the pharmacy", matcher)
    assert sel.zones == ["pharmacy"]
    assert sel.exits == ["main_entrance", "back_exit"]
    assert {"main_entrance", "back_exit"} <= set(sel.roi_names)
    assert "- exits: main_entrance (in lobby), back_exit (in corridor)" in sel.summary


def test_nothing_named_falls_back_to_the_best_connected_zones(clinic, matcher):
    sel = select_rois(clinic, load_preset("normal"), "people walk around", matcher)
    assert sel.zones == ["corridor", "lobby", "cafeteria"]
    assert all(m.reason == "default" for m in sel.matches)


@pytest.mark.parametrize("prompt, phrase", [
    ("ten people swim in the swimming pool", "swimming pool"),
    ("patients wait in the waiting room", "waiting room"),
    ("a doctor walks to the helipad", "helipad"),
])
def test_unknown_place_is_an_error_with_close_matches(clinic, matcher, prompt, phrase):
    with pytest.raises(PromptError, match=f"does not have: '{phrase}' \\(closest: "):
        select_rois(clinic, load_preset("normal"), prompt, matcher)


@pytest.mark.parametrize("prompt", [
    "people walk to the robot in the lobby",
    "at the same time two nurses leave the pharmacy in a hurry",
    "ten patients in line at the pharmacy counter",
])
def test_non_places_after_prepositions_are_not_errors(clinic, matcher, prompt):
    select_rois(clinic, load_preset("normal"), prompt, matcher)


def test_close_matches_prefer_similar_names(matcher):
    assert matcher.close_matches("pharmacy counters")[0] == "pharmacy_counter"


def test_vanilla_gets_the_whole_world(clinic, matcher):
    sel = select_rois(clinic, load_preset("vanilla"), "Ten patients queue at the pharmacy counter", matcher)
    assert sel.zones == [z.name for z in clinic.zones]
    assert sel.named_zones == ["pharmacy"]
    assert "coffee_counter" in sel.summary and "restroom_door" in sel.summary
    guided = select_rois(clinic, load_preset("queuing"), "Ten patients queue at the pharmacy counter", matcher)
    assert len(guided.summary) * 2 < len(sel.summary)


def test_embedding_similarity_reranks_lexical_candidates_only(clinic):
    seen = []

    def embed(texts):
        import numpy as np
        seen.extend(texts)
        # the prompt vector points at whatever mentions "coffee"
        return np.array([[1.0, 0.0] if "coffee" in t or "cafe" in t else [0.0, 1.0] for t in texts])

    m = RoIMatcher(clinic, embed=embed)
    sel = select_rois(clinic, load_preset("normal"), "two people grab a coffee at the counter", m)
    assert names(sel)[0] == "coffee_counter"
    assert "restroom" not in names(sel)


def test_selection_record_is_json_ready(clinic, matcher):
    import json
    sel = select_rois(clinic, load_preset("queuing"), "Ten patients queue at the pharmacy counter", matcher)
    record = describe_selection(sel)
    assert json.loads(json.dumps(record))[0]["name"] == "pharmacy_counter"


def test_qualified_places_are_not_unknown_places(clinic):
    from grove_tui.generation.rois import RoIMatcher

    matcher = RoIMatcher(clinic)
    assert matcher.unknown_places("everyone evacuates through the nearest exit") == []
    assert matcher.unknown_places("they walk to the other side of the lobby") == []
    assert matcher.unknown_places("patients wait at the helipad") == ["helipad"]


def test_the_exit_means_the_one_exit_nearest_the_places_named(clinic, matcher):
    matches = matcher.match("ten patients queue at the pharmacy while a family walks to the exit")
    doors = [m.name for m in matches if m.kind == "door"]
    pharmacy = clinic.zone("pharmacy").centroid
    assert doors == [min(clinic.exits(), key=lambda d: math.dist(d.position, pharmacy)).name]
    assert [m.name for m in matches if m.kind == "zone"] == ["pharmacy"]
    # with nothing else named, the world's first exit; a qualified exit is still one exit
    assert [m.name for m in matcher.match("a family walks to the nearest exit")] == [clinic.exits()[0].name]
    assert [m.name for m in matcher.match("visitors leave through the back exit")] == ["back_exit"]


def test_exit_as_a_verb_names_no_place(matcher):
    assert matcher.match("five people exit the building") == []


@pytest.mark.parametrize("world_name", list_worlds())
def test_every_world_grounds_the_exit_to_exactly_one_exit_door(world_name):
    world = load_world(world_name)
    matches = RoIMatcher(world).match("a group of visitors walks to the exit")
    assert len(matches) == 1 and matches[0].kind == "door" and world.find(matches[0].name).exit
