"""Tactical-layer request building (no model needed): which nodes are offered, what the prompt holds."""

from __future__ import annotations

import pytest

from grove_tui.bt.format.manifest import NODES
from grove_tui.generation.pipeline import STAGES, world_reference
from grove_tui.generation.presets import load_preset
from grove_tui.language.reading import read_prompt
from grove_tui.generation.retrieval import RetrievedNode
from grove_tui.generation.rois import select_rois
from grove_tui.generation.synthesis import offered_nodes, prepare_request
from grove_tui.world import load_world


def request(hospital, retriever, preset_name, prompt):
    preset = load_preset(preset_name)
    reading = read_prompt(prompt, hospital)
    selection = select_rois(hospital, preset, reading)
    retrieved = retriever.retrieve(prompt, preset.retrieval_filter, k=preset.retrieval_k) if preset.retrieval_filter else []
    return preset, selection, prepare_request(preset, selection, retrieved, reading, retriever.documents_for,
                                              world=hospital, cards_for=retriever.cards_for)


def test_emergency_offers_only_field_following_and_no_social_nodes():
    preset = load_preset("emergency")
    offered = offered_nodes(preset, ["FollowVelocityField", "Converse", "Wander", "GoTo", "JoinGroup"])
    assert offered == ["Sequence", "FollowVelocityField", "JoinGroup"]
    assert "FollowVelocityField" in offered_nodes(preset, [])  # required even when not retrieved


def test_queuing_always_offers_the_queue_and_normal_never_the_field():
    assert {"GoTo", "Queue"} <= set(offered_nodes(load_preset("queuing"), ["Wait"]))
    assert "FollowVelocityField" not in offered_nodes(load_preset("normal"), ["FollowVelocityField", "Converse"])
    assert "Converse" in offered_nodes(load_preset("normal"), ["FollowVelocityField", "Converse"])


def test_vanilla_offers_every_node_a_model_may_write():
    offered = set(offered_nodes(load_preset("vanilla"), []))
    writable = {n for n, s in NODES.items() if s.llm and "vanilla" in s.presets and s.category != "control"}
    assert writable <= offered


@pytest.mark.slow
def test_guided_prompt_puts_the_fixed_system_text_first_and_the_sentence_last(hospital, retriever):
    prompt = "Ten patients queue at the pharmacy counter"
    preset, selection, req = request(hospital, retriever, "queuing", prompt)
    system, user = req.messages
    assert system["role"] == "system" and prompt not in system["content"]
    _, _, other = request(hospital, retriever, "queuing", "Eight visitors line up at the reception desk")
    assert other.messages[0] == system  # identical prefix across prompts: the KV cache is reused
    assert user["content"].index("Places:") < user["content"].index("Nodes:") < user["content"].index(prompt)
    assert "Groups:\n1. patient x10: queue, location pharmacy_counter" in user["content"]
    assert "- pharmacy (" in user["content"] and "cafeteria" not in user["content"]
    assert req.roi_names == selection.roi_names
    # one group read, one tree to write (the lean draft: the reading gives its label, count and start)
    assert req.max_groups == 1 and req.grammar.startswith("root ::= level-1\n")


@pytest.mark.slow
def test_vanilla_prompt_has_the_whole_world_and_every_node(hospital, retriever):
    prompt = "Ten patients queue at the pharmacy counter"
    _, _, guided = request(hospital, retriever, "queuing", prompt)
    _, selection, baseline = request(hospital, retriever, "vanilla", prompt)
    text = baseline.messages[1]["content"]
    assert all(f"zone {z.name} " in text for z in hospital.zones)
    assert {d.name for d in baseline.documents} >= {"GoTo", "Queue", "Converse", "FollowVelocityField", "Wander"}
    assert "Groups to write" not in text  # no guidance
    assert len(text) > 4 * len(guided.messages[1]["content"])


def test_stage_names_and_world_reference(tmp_path):
    assert STAGES == ("rois", "retrieval", "synthesis", "postprocess", "planning")
    assert world_reference(load_world("office")) == "office"
    from grove_tui.paths import worlds_dir

    copy = tmp_path / "my_office.yaml"
    copy.write_text((worlds_dir() / "office.yaml").read_text())
    assert world_reference(load_world(str(copy))) == str(copy.resolve())


def test_retrieved_templates_with_unoffered_nodes_are_left_out(hospital, retriever):
    from grove_tui.generation.synthesis import choose_documents

    preset = load_preset("emergency")
    retrieved = [RetrievedNode("conversation_circle", "template", 0.9, "talk", ("Converse", "GoTo")),
                 RetrievedNode("evacuation_group", "template", 0.8, "leave together", ("JoinGroup", "FollowVelocityField"))]
    offered = offered_nodes(preset, [n for r in retrieved for n in r.nodes])
    docs = choose_documents(preset, retrieved, offered, retriever.documents_for)
    assert [d.name for d in docs] == ["evacuation_group"]
