"""Refinement by the roi model (embedded, real llama.cpp): it may only choose among tied candidates."""

from __future__ import annotations

import pytest

from grove_tui.generation.presets import load_preset
from grove_tui.generation.rois import ambiguous_mentions, refine_with_model, select_rois
from grove_tui.world import load_world
from grove_tui.llm.embedded import embedded_model_path
from grove_tui.llm.local import LocalLLM


@pytest.fixture(scope="module")
def roi_llm():
    model = LocalLLM(embedded_model_path(), role="roi")
    yield model
    model.close()


@pytest.mark.slow
def test_the_model_resolves_a_tie_and_leaves_the_rest_alone(roi_llm):
    world = load_world("hospital")
    prompt = "Three patients sit in the main waiting room and one goes to the restroom"
    selection = select_rois(world, load_preset("normal"), prompt)
    assert [[m.name for m in g] for g in ambiguous_mentions(selection)] == [["restroom_men", "restroom_women"]]
    refined, prompt_tokens, completion_tokens = refine_with_model(world, load_preset("normal"), prompt, selection, roi_llm)
    restrooms = [n for n in refined.roi_names if n.startswith("restroom_")]
    assert len(restrooms) == 1
    assert "main_waiting_room" in refined.roi_names and refined.zones[0] == "main_waiting_room"
    assert refined.zones == ["main_waiting_room", restrooms[0]]
    assert prompt_tokens > 0 and completion_tokens > 0
    assert not ambiguous_mentions(refined)


def test_nothing_to_refine_costs_no_tokens(roi_llm):
    world = load_world("hospital")
    prompt = "Ten patients queue at the pharmacy counter"
    selection = select_rois(world, load_preset("queuing"), prompt)
    refined, prompt_tokens, completion_tokens = refine_with_model(world, load_preset("queuing"), prompt, selection, roi_llm)
    assert refined is selection and prompt_tokens == completion_tokens == 0
