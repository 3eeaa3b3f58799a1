"""The compact synthesis prompt (issue 20): what the bt model reads is short, complete and fixed-first.

No model here: the prompt is built as the pipeline builds it (reading, RoI selection, retrieval,
cards) for sentences of every guided preset in every shipped world, and checked against what the
grammar lets the draft use. Drafts written from this prompt by the embedded model are checked in
test_pipeline_e2e.py (every preset in every world) and by the grammar tests in tests/llm.
"""

from __future__ import annotations

import re

import pytest

from grove_tui.bt.format.manifest import NODES
from grove_tui.generation.draft import written_ports
from grove_tui.generation.node_docs import node_card, node_signature
from grove_tui.generation.presets import load_preset
from grove_tui.generation.rois import select_rois
from grove_tui.generation.synthesis import fixed_system_message, pinned_cards, prepare_request
from grove_tui.language.reading import read_prompt
from grove_tui.world import list_worlds, load_world

# One everyday sentence per preset, with the places filled in from each world, so every world is
# exercised without a sentence written for it.
SENTENCES = {
    "queuing": "{n} people queue at the {entity}",
    "normal": "Three visitors walk from the {zone} to the {other}",
    "emergency": "A fire alarm: ten people in the {zone} evacuate",
}


def _places(world):
    zones = [z for z in world.zones if z.entities]
    zone, other = zones[0], zones[-1]
    entity = zone.entities[0]
    return {"zone": zone.name.replace("_", " "), "other": other.name.replace("_", " "),
            "entity": entity.name.replace("_", " "), "n": "Five"}


def build(world, preset_name, retriever, prompt):
    preset = load_preset(preset_name)
    reading = read_prompt(prompt, world, seed=0)
    selection = select_rois(world, preset, reading)
    retrieved = retriever.retrieve(prompt, preset.retrieval_filter, k=preset.retrieval_k)
    request = prepare_request(preset, selection, retrieved, reading, retriever.documents_for, world=world,
                              cards_for=retriever.cards_for, documents_named=retriever.documents_named)
    return preset, selection, request


CASES = [(w, p) for w in list_worlds() for p in SENTENCES]


@pytest.mark.slow
@pytest.mark.parametrize("world_name,preset_name", CASES)
def test_the_places_block_names_exactly_what_the_draft_may_use(world_name, preset_name, retriever):
    world = load_world(world_name)
    prompt = SENTENCES[preset_name].format(**_places(world))
    _, selection, request = build(world, preset_name, retriever, prompt)
    user = request.messages[1]["content"]
    places = re.search(r"Places:\n(.*?)\n(?:Nodes|Scenario):", user, re.S).group(1)
    named = set(re.findall(r"[a-z][a-z0-9_]*", places))
    assert set(request.roi_names) <= named, f"places the grammar allows but the prompt hides: {set(request.roi_names) - named}"
    # Every place the block lists (a name followed by its type) is one the grammar accepts; other
    # zones appear only as where a door leads or an exit lies.
    listed = set(re.findall(r"([a-z][a-z0-9_]*) \(", places))
    assert listed <= set(request.roi_names), listed - set(request.roi_names)
    assert not re.search(r"\(-?\d+(\.\d+)?,-?\d", user), "coordinates in a guided prompt"


@pytest.mark.slow
@pytest.mark.parametrize("world_name,preset_name", CASES)
def test_every_offered_node_has_its_card_and_the_sentence_comes_last(world_name, preset_name, retriever):
    world = load_world(world_name)
    prompt = SENTENCES[preset_name].format(**_places(world))
    preset, _, request = build(world, preset_name, retriever, prompt)
    system, user = (m["content"] for m in request.messages)
    assert system == fixed_system_message(preset, world, pinned_cards(preset, retriever.documents_named))
    assert prompt not in system
    lines = system.splitlines() + user.splitlines()
    for name in request.node_names:
        if NODES[name].category == "control":
            continue  # control nodes are in the rules' example and every template
        assert any(re.match(rf"{name}[(: ]", line) for line in lines) or any(
            name in line for line in lines if line.startswith("Template ")), name
    assert user.index("Places:") < user.index(f"Scenario: {prompt}")
    if "Nodes:" in user:  # cards beyond the pinned ones, between the places and the sentence
        assert user.index("Places:") < user.index("Nodes:") < user.index(f"Scenario: {prompt}")


def test_a_card_is_one_line_with_every_writable_port_and_no_automatic_one():
    """The card shows the node as the draft writes it: required values in place (a place as <place>, anything
    else with its port's name), optional ports as name=..., and no port the grammar would refuse."""
    for spec in NODES.values():
        if not spec.llm:
            continue
        card = node_card(spec, {"use_when": "always.", "constraints": ["Never alone."]})
        assert "\n" not in card and card.startswith(node_signature(spec) + ":")
        signature = node_signature(spec)
        assert re.match(rf"{spec.name}(\(|$| optional )", signature), signature
        for port in spec.ports:
            if port.default is None and port.type == "target":
                continue  # shown as <place>: its name says nothing the model needs
            shown = re.search(rf"[ ,(<]{re.escape(port.name)}[=:]", signature) is not None
            assert shown == (port in written_ports(spec)), (spec.name, port.name)
        assert card.endswith("Always. Never alone.")


@pytest.mark.slow
def test_the_system_message_is_fixed_per_world_and_preset_and_differs_between_them(retriever):
    hospital, office = load_world("hospital"), load_world("office")
    _, _, a = build(hospital, "queuing", retriever, "Ten patients queue at the pharmacy counter")
    _, _, b = build(hospital, "queuing", retriever, "Two visitors wait in line at the reception desk")
    assert a.messages[0] == b.messages[0] and a.messages[1] != b.messages[1]
    queuing = pinned_cards(load_preset("queuing"), retriever.documents_named)
    assert fixed_system_message(load_preset("queuing"), office, queuing) != a.messages[0]["content"]
    assert fixed_system_message(load_preset("normal"), hospital, queuing) != a.messages[0]["content"]


@pytest.mark.slow
def test_vanilla_keeps_the_full_documents_and_world(retriever):
    hospital = load_world("hospital")
    _, _, request = build(hospital, "vanilla", retriever, "Ten patients queue at the pharmacy counter")
    user = request.messages[1]["content"]
    assert all(f"zone {z.name} " in user for z in hospital.zones)
    assert "Ports:" in user and "boundary:" in user


# One group each, worded plainly, with the places filled in from each world.
ONE_GROUP = {
    "queuing": "{n} people queue at the {entity}",
    "normal": "Two visitors walk from the {zone} to the {other}",
    "emergency": "Ten people in the {zone} evacuate",
}


@pytest.fixture(scope="module")
def tokenize():
    """The embedded model's BPE, which the Qwen3-shaped bench models use too (bench/models.py)."""
    from llama_cpp import Llama

    from grove_tui.llm.embedded import embedded_model_path

    llm = Llama(model_path=str(embedded_model_path()), vocab_only=True, verbose=False)
    return lambda text: len(llm.tokenize(text.encode("utf-8"), add_bos=False, special=True))


@pytest.mark.slow
@pytest.mark.parametrize("world_name,preset_name", [(w, p) for w in list_worlds() for p in ONE_GROUP])
def test_a_one_group_sentence_writes_one_tree_and_prefills_a_short_tail(world_name, preset_name, retriever, tokenize):
    """Issue 33: the reading fixes label, count and start, so the grammar asks for exactly one tree; the
    system message (pinned cards included) is the cached prefix, and what follows it stays short."""
    world = load_world(world_name)
    prompt = ONE_GROUP[preset_name].format(**_places(world))
    preset, selection, request = build(world, preset_name, retriever, prompt)
    assert len(request.heads) == 1 and request.grammar.startswith("root ::= level-1\n")
    assert request.heads[0].count >= 1 and request.heads[0].spawn
    user = request.messages[1]["content"]
    assert user.rstrip().splitlines()[-2:][0] == "Groups:"
    # The user message plus the chat template's few tokens around it: what a warm request prefills.
    assert tokenize(user) + 12 <= 150, (tokenize(user), user)


@pytest.mark.slow
def test_the_lean_draft_parses_into_the_reading_groups(retriever):
    from grove_tui.generation.draft import parse_trees

    world = load_world("hospital")
    _, selection, request = build(world, "normal", retriever,
                                  "Two nurses chat at the nurse station while a doctor walks to ward B")
    assert [h.label for h in request.heads] == ["nurse", "doctor"]
    text = "Converse(nurse_station)\nSequence(GoTo(ward_b))"
    place = {"nurse_station": next(n for n in request.roi_names if "nurse" in n),
             "ward_b": next(n for n in request.roi_names if n.endswith("b"))}
    text = text.replace("nurse_station", place["nurse_station"]).replace("ward_b", place["ward_b"])
    draft = parse_trees(text, request.heads, request.node_names, request.roi_names)
    assert [(g.label, g.count) for g in draft.groups] == [("nurse", 2), ("doctor", 1)]
    assert draft.groups[0].tree.node == "Converse" and draft.groups[1].tree.children[0].ports["target"] == place["ward_b"]
