"""Refinement by the roi model (embedded, real llama.cpp): it may only choose among the places the
reader weighed for a field it is unsure of, and the reading then says the choice."""

from __future__ import annotations

import pytest

from grove_tui.generation.presets import load_preset
from grove_tui.generation.rois import refine_with_model, select_rois
from grove_tui.language.reading import read_prompt
from grove_tui.llm.embedded import embedded_model_path
from grove_tui.llm.local import LocalLLM
from grove_tui.world import load_world


@pytest.fixture(scope="module")
def roi_llm():
    model = LocalLLM(embedded_model_path(), role="roi")
    yield model
    model.close()


@pytest.mark.slow
def test_the_model_settles_an_unsure_place_and_leaves_the_rest_alone(roi_llm):
    world = load_world("hospital")
    reading = read_prompt("Three patients sit in the main waiting room and one goes to the restroom", world)
    selection = select_rois(world, load_preset("normal"), reading)
    assert [set(a.options) for a in selection.ambiguous] == [{"restroom_men", "restroom_women"}]
    refined, settled, prompt_tokens, completion_tokens = refine_with_model(world, load_preset("normal"), reading,
                                                                           selection, roi_llm)
    restrooms = [n for n in refined.roi_names if n.startswith("restroom_")]
    assert len(restrooms) == 1 and settled.groups[1].destination == restrooms[0]
    assert "main_waiting_room" in refined.roi_names and refined.zones[0] == "main_waiting_room"
    assert settled.groups[0] == reading.groups[0]  # the field the reader was sure of is untouched
    assert not settled.unsure() or all(c.field == "count" for _, c in settled.unsure())
    assert prompt_tokens > 0 and completion_tokens > 0 and not refined.ambiguous


@pytest.mark.slow
def test_nothing_to_refine_costs_no_tokens(roi_llm):
    world = load_world("hospital")
    reading = read_prompt("Ten patients queue at the pharmacy counter", world)
    selection = select_rois(world, load_preset("queuing"), reading)
    refined, settled, prompt_tokens, completion_tokens = refine_with_model(world, load_preset("queuing"), reading,
                                                                           selection, roi_llm)
    assert refined is selection and settled is reading and prompt_tokens == completion_tokens == 0


@pytest.mark.parametrize("world_name, prompt", [
    ("airport", "twelve people at gate b2 evacuate through the nearest exit"),
    ("office", "the staff in the open office leave by the closest exit when the alarm sounds"),
    ("hospital", "everyone in the cafeteria evacuates through the nearest exit"),
])
def test_evacuees_unsure_of_the_exit_are_not_narrowed_to_one(world_name, prompt):
    # The evacuation sends each person to the exit nearest to them: a model's pick of one exit would
    # be a promise the run does not keep (the report said ✗ for people who all got out).
    world = load_world(world_name)
    reading = read_prompt(prompt, world)
    evacuees = [i for i, g in enumerate(reading.groups) if g.intent == "evacuate"]
    assert evacuees, reading
    selection = select_rois(world, load_preset("emergency"), reading)
    assert not [a for a in selection.ambiguous if a.group in evacuees and a.field == "destination"]
