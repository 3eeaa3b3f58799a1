"""The draft contract: the compact syntax, the grammar built per request from the manifest, and the strict parser."""

from __future__ import annotations

import random
import re

import pytest

from grove_tui.bt.format.manifest import NODES
from grove_tui.generation.draft import (
    BRANCH_CATEGORIES,
    LABEL_MAX_LENGTH,
    Draft,
    DraftError,
    DraftGroup,
    DraftNode,
    _sensible_floats,
    _sensible_ints,
    draft_grammar,
    draft_to_text,
    parse_draft,
    tree_text,
    written_ports,
)

NODE_SET = ["Sequence", "Fallback", "Inverter", "Repeat", "GoTo", "Queue", "Wait", "SaySomething", "IsRobotClose", "IsAnyoneSpeaking"]
ROIS = ["pharmacy", "pharmacy_counter", "main_exit"]
EXAMPLE = "10 patients from pharmacy: Sequence(GoTo(pharmacy_counter), Queue(pharmacy_counter, spacing=0.6))"
EXAMPLE_DRAFT = Draft((DraftGroup("patients", 10, "pharmacy", DraftNode("Sequence", {}, (
    DraftNode("GoTo", {"target": "pharmacy_counter"}),
    DraftNode("Queue", {"service_point": "pharmacy_counter", "spacing": 0.6}),
))),))


def _rules(grammar: str) -> dict[str, str]:
    return dict(line.split(" ::= ", 1) for line in grammar.splitlines())


def test_grammar_offers_only_the_requested_nodes_and_places():
    rules = _rules(draft_grammar(NODE_SET, ROIS, max_groups=3, max_count=40, max_depth=3))
    assert rules["place"] == '"pharmacy" | "pharmacy_counter" | "main_exit"'
    assert rules["count"].split(" | ")[0] == '"40"' and rules["count"].split(" | ")[-1] == '"1"'
    named = set(re.findall(r'"([A-Z][A-Za-z]+)\(?"', " ".join(rules.values())))
    assert named == set(NODE_SET)
    assert rules["goto"] == '"GoTo(" place (sep goto-options)? ")"'  # target positional; tolerance optional, named
    tolerances = [float(v.strip('"')) for v in rules["goto-tolerance"].split(" | ")]
    assert all(0.05 <= value <= 5.0 for value in tolerances)
    assert rules["root"].count("group") == 3  # at most three lines


def test_auto_and_id_ports_are_never_offered_to_the_model():
    grammar = draft_grammar(NODE_SET, ROIS)
    assert "agent_id" not in grammar and "waypoints" not in grammar and "speaker_id" not in grammar
    for spec in NODES.values():
        assert all(not port.auto and port.type not in ("agent", "agents", "point_list") for port in written_ports(spec))


def test_keys_the_grammar_knows_are_never_written():
    """Required ports are positional, node and group fields have no names: only optional ports the model chooses."""
    grammar = draft_grammar(NODE_SET, ROIS)
    for word in ("node", "children", "label", "count", "spawn", "tree", "target", "service_point", "num_cycles", "{", "["):
        assert f'"{word}' not in grammar.replace('"\\""', ""), word
    assert '"spacing="' in grammar and '"threshold="' in grammar  # optional ports are named when written


def test_depth_is_unrolled_and_bounded():
    rules = _rules(draft_grammar(NODE_SET, ROIS, max_depth=3))
    assert {"level-1", "level-2", "level-3"} <= set(rules) and "level-4" not in rules
    deepest = set(rules["level-3"].split(" | "))
    assert deepest == {"goto", "queue", "wait", "saysomething", "isrobotclose", "isanyonespeaking"}  # no branch at the last level
    assert rules["inverter-1"] == '"Inverter(" level-2 ")"'  # a decorator takes exactly one child
    assert rules["sequence-2"].count("level-3") == 4  # up to MAX_CHILDREN children
    assert rules["repeat-1"].startswith('"Repeat(" repeat-num-cycles sep level-2')  # required value, then the child


def test_numbers_and_strings_are_bounded_for_the_grammar():
    rules = _rules(draft_grammar(NODE_SET, ROIS))
    repeat = [int(v.strip('"')) for v in rules["repeat-num-cycles"].split(" | ")]
    assert -1 in repeat and max(repeat) <= 10000 and len(repeat) < 30
    # Long bounds are counted repetitions (llguidance refuses optionals nested 48 deep), still bounded.
    assert re.search(r"text-char \(?text-char\)?\{0,47\}", rules["text"]), rules["text"]
    assert re.search(rf"label-char\{{0,{LABEL_MAX_LENGTH - 2}\}}", rules["label"]), rules["label"]
    assert "*" not in "".join(rules.values()) and "+" not in "".join(rules.values())  # every repetition bounded


@pytest.mark.parametrize("names, rois, problem", [
    (["NoSuchNode"], ROIS, "unknown node type"),
    (["Sequence"], ROIS, "no action or condition"),
    (["GoTo"], [], "no RoI names"),
    ([], ROIS, "no node types"),
    (["GoTo"], ["main hall"], "not single words"),
])
def test_grammar_refuses_impossible_requests(names, rois, problem):
    with pytest.raises(DraftError, match=problem):
        draft_grammar(names, rois)


def test_parse_round_trip():
    draft = parse_draft(EXAMPLE, NODE_SET, ROIS)
    assert draft == EXAMPLE_DRAFT
    assert draft_to_text(draft) == EXAMPLE
    assert draft.places() == {"pharmacy", "pharmacy_counter"}
    assert draft.node_types() == {"Sequence", "GoTo", "Queue"}


def test_hand_written_drafts_may_name_required_ports_and_space_freely():
    text = "\n  10  patients  from pharmacy :Sequence( GoTo( target = pharmacy_counter ) ,Queue(service_point=pharmacy_counter,spacing=0.6))\n\n"
    assert parse_draft(text, NODE_SET, ROIS) == EXAMPLE_DRAFT


def _random_value(rng: random.Random, port, rois: list[str]):
    if port.type == "target":
        return rng.choice(rois)
    if port.type == "bool":
        return rng.random() < 0.5
    if port.type == "int":
        return rng.choice(_sensible_ints(port))
    if port.type == "float":
        return rng.choice(_sensible_floats(port) + [round(rng.uniform(port.min, port.max), 3)])
    alphabet = "abcXYZ019 _.,'()/:-"
    return "".join(rng.choice(alphabet) for _ in range(rng.randint(0, 48)))


def _random_node(rng: random.Random, names: list[str], rois: list[str], level: int, max_depth: int) -> DraftNode:
    usable = [n for n in names if NODES[n].category not in BRANCH_CATEGORIES or level < max_depth]
    spec = NODES[rng.choice(usable)]
    ports = {port.name: _random_value(rng, port, rois) for port in written_ports(spec)
             if port.default is None or rng.random() < 0.4}
    children: tuple[DraftNode, ...] = ()
    if spec.category in BRANCH_CATEGORIES:
        most = 1 if spec.category == "decorator" else 4
        children = tuple(_random_node(rng, names, rois, level + 1, max_depth) for _ in range(rng.randint(1, most)))
    return DraftNode(spec.name, ports, children)


def _random_label(rng: random.Random) -> str:
    inner = "".join(rng.choice("abcdefghijklmnopqrstuvwxyzQ_'-") for _ in range(rng.randint(0, LABEL_MAX_LENGTH - 1)))
    return rng.choice("ABCxyz") + inner


def test_round_trip_property_over_every_llm_node():
    """DraftNode -> text -> parse gives the same draft, for random drafts over every node a model may write."""
    names = [name for name, spec in NODES.items() if spec.llm]
    rois = ["lobby", "cafe_2", "main_exit", "x"]
    rng = random.Random(20)
    for _ in range(300):
        groups = tuple(DraftGroup(_random_label(rng), rng.randint(1, 60), rng.choice(rois),
                                  _random_node(rng, names, rois, 1, 4))
                       for _ in range(rng.randint(1, 6)))
        draft = Draft(groups)
        text = draft_to_text(draft)
        assert parse_draft(text, names, rois, max_depth=4) == draft, text


def test_a_label_the_syntax_cannot_hold_is_refused_not_written():
    with pytest.raises(DraftError, match="one word"):
        draft_to_text(Draft((DraftGroup("old patients", 2, "pharmacy", DraftNode("Wait")),)))


def test_templates_render_in_draft_syntax():
    tree = {"node": "ReactiveFallback", "children": [
        {"node": "Sequence", "children": [{"node": "IsRobotVisible", "distance": 5},
                                          {"node": "BlockRobot", "front_dist": 1.0, "duration": 10}]},
        {"node": "GoTo", "target": "<destination>"}]}
    assert tree_text(tree) == ("ReactiveFallback(Sequence(IsRobotVisible(distance=5), BlockRobot(front_dist=1, duration=10)), "
                               "GoTo(<destination>))")


def _line(text: str, old: str, new: str) -> str:
    assert old in text
    return text.replace(old, new, 1)


@pytest.mark.parametrize("text, problem", [
    ("", "draft is empty"),
    ("10 patients from pharmacy Sequence(Wait)", "found no ':'"),
    ("patients from pharmacy: Wait", "expected `COUNT LABEL from SPAWN`"),
    ("10 patients pharmacy: Wait", "expected `COUNT LABEL from SPAWN`"),
    ("\n".join([EXAMPLE] * 7), "7 groups, at most 6"),
    (_line(EXAMPLE, "10 ", "0 "), r"groups\[0\].count \(line 1\): '0' is not a whole number in 1..60"),
    (_line(EXAMPLE, "10 ", "61 "), "1..60"),
    (_line(EXAMPLE, "10 ", "2.5 "), "whole number"),
    (_line(EXAMPLE, " pharmacy:", " mars:"), r"groups\[0\].spawn \(line 1\): 'mars' is not one of the selected places"),
    (_line(EXAMPLE, "patients", "x" * 25), "longer than 24"),
    (_line(EXAMPLE, "patients", "bad\u0007label"), "must be one word: a letter, then letters"),
    (_line(EXAMPLE, "patients", "group2"), "must be one word"),
    (_line(EXAMPLE, "patients", "old patients"), "expected `COUNT LABEL from SPAWN`"),
    (_line(EXAMPLE, "patients", "Here is: a draft"), "expected `COUNT LABEL from SPAWN`"),
    (_line(EXAMPLE, "GoTo(pharmacy_counter)", "GoTo(nowhere)"),
     r"children\[0\] \(GoTo\).target \(line 1, column 42\): 'nowhere' is not one of the selected places"),
    (_line(EXAMPLE, "GoTo(pharmacy_counter)", "GoTo"), r"\(GoTo\) \(line 1, column 37\): missing required port\(s\) target"),
    (_line(EXAMPLE, "GoTo(pharmacy_counter)", "FlyTo(pharmacy)"), "'FlyTo' is not one of the allowed node types"),
    (_line(EXAMPLE, "GoTo(pharmacy_counter)", "GoTo(pharmacy_counter, agent_id=3)"), "GoTo has no port 'agent_id'"),
    (_line(EXAMPLE, "spacing=0.6", "spacing=9"), "9 is outside 0.3..3"),
    (_line(EXAMPLE, "spacing=0.6", "spacing=wide"), "expected a number, found 'wide'"),
    (_line(EXAMPLE, "spacing=0.6", "spacing=0.6, spacing=1"), "port spacing is written twice"),
    (_line(EXAMPLE, "spacing=0.6", "spacing=nan"), "expected a number, found 'nan'"),
    (_line(EXAMPLE, "Queue(pharmacy_counter, spacing=0.6)", "Queue(pharmacy_counter, pharmacy)"), "Queue takes 1 value"),
    ("1 a from pharmacy: Sequence()", "expected a node|is not one of the allowed node types"),
    ("1 a from pharmacy: Sequence", "Sequence takes 1..4 children"),
    ("1 a from pharmacy: Wait(Wait)", "Wait takes no values"),
    ("1 a from pharmacy: Sequence(Wait, Wait", "expected ',' or '\\)', found the end of the line"),
    ("1 a from pharmacy: Wait) x", "unexpected '\\)' after the tree"),
    ("1 a from pharmacy: Sequence(Wait, duration=3)", "port duration|Sequence has no port"),
    ("1 a from pharmacy: SaySomething(message=hello)", "expected a quoted text"),
    ("1 a from pharmacy: SaySomething(message=\"" + "x" * 49 + "\")", "longer than 48"),
    ("1 a from pharmacy: Repeat(2.5, Wait)", "expected a whole number, found 2.5"),
    ("1 a from pharmacy: GoTo(main_exit, tolerance=0.3) # note", "unexpected '#' after the tree"),
])
def test_parse_rejects_with_a_clear_message(text, problem):
    with pytest.raises(DraftError, match=problem):
        parse_draft(text, NODE_SET, ROIS)


def test_parse_enforces_depth_and_decorator_arity():
    text = "1 a from pharmacy: Sequence(Sequence(Sequence(Wait)))"
    with pytest.raises(DraftError, match="3 levels deep"):
        parse_draft(text, NODE_SET, ROIS, max_depth=3)
    assert parse_draft(text, NODE_SET, ROIS, max_depth=4).groups[0].tree.children[0].children[0].children[0].node == "Wait"
    with pytest.raises(DraftError, match="exactly 1 child"):
        parse_draft("1 a from pharmacy: Inverter(Wait, Wait)", NODE_SET, ROIS)


def test_children_bound_is_configurable():
    rules = _rules(draft_grammar(NODE_SET, ROIS, max_children=2))
    assert rules["sequence-1"].count("level-2") == 2 and rules["inverter-1"].count("level-2") == 1
    three = "1 a from pharmacy: Sequence(Wait, Wait, Wait)"
    assert len(parse_draft(three, NODE_SET, ROIS).groups[0].tree.children) == 3
    with pytest.raises(DraftError, match="1..2 children"):
        parse_draft(three, NODE_SET, ROIS, max_children=2)


def test_parse_accepts_in_bounds_numbers_outside_the_grammar_menu():
    """The grammar offers a short menu of values; a hand-written draft is held to the manifest bounds only."""
    text = _line(EXAMPLE, "spacing=0.6", "spacing=0.65")
    assert parse_draft(text, NODE_SET, ROIS).groups[0].tree.children[1].ports["spacing"] == 0.65


def test_a_value_outside_a_port_with_one_bound_is_refused_with_that_bound():
    """A port bounded on one side only: the parser names the bound it has (it used to fail on the other)."""
    from grove_tui.bt.format.manifest import NodeSpec, PortSpec

    nodes = {"Pause": NodeSpec("Pause", "action", (PortSpec("seconds", "float", min=1.0),), "Wait a while.", "grove")}
    assert parse_draft("2 people from pharmacy: Pause(3)", ["Pause"], ROIS, nodes=nodes).groups[0].tree.ports == {
        "seconds": 3.0}
    with pytest.raises(DraftError, match=r"0\.5 is outside 1\.\."):
        parse_draft("2 people from pharmacy: Pause(0.5)", ["Pause"], ROIS, nodes=nodes)
