"""The draft contract: the schema built per request from the manifest, and the strict parser."""

from __future__ import annotations

import json

import pytest

from grove_tui.bt.manifest import NODES
from grove_tui.generation.draft import (
    Draft,
    DraftError,
    DraftGroup,
    DraftNode,
    build_draft_schema,
    draft_to_json,
    parse_draft,
    written_ports,
)
from grove_tui.llm.grammar import schema_to_gbnf

NODE_SET = ["Sequence", "Fallback", "Inverter", "Repeat", "GoTo", "Queue", "Wait", "SaySomething", "IsRobotClose", "IsAnyoneSpeaking"]
ROIS = ["pharmacy", "pharmacy_counter", "main_exit"]
EXAMPLE = {"groups": [{"label": "patients", "count": 10, "spawn": "pharmacy", "tree": {
    "node": "Sequence", "children": [{"node": "GoTo", "target": "pharmacy_counter"},
                                     {"node": "Queue", "service_point": "pharmacy_counter", "spacing": 0.6}]}}]}


def test_schema_offers_only_the_requested_nodes_and_places():
    schema = build_draft_schema(NODE_SET, ROIS, max_groups=3, max_count=40, max_depth=3)
    group = schema["properties"]["groups"]["items"]
    assert schema["properties"]["groups"]["maxItems"] == 3
    assert group["properties"]["spawn"] == {"enum": ROIS}
    assert group["properties"]["count"] == {"type": "integer", "minimum": 1, "maximum": 40}
    named = {d["properties"]["node"]["const"] for d in schema["$defs"].values() if "properties" in d}
    assert named == set(NODE_SET)
    goto = schema["$defs"]["GoTo"]
    assert goto["properties"]["target"] == {"enum": ROIS}
    assert goto["required"] == ["node", "target"]  # tolerance has a default: optional
    assert all(0.05 <= value <= 5.0 for value in goto["properties"]["tolerance"]["enum"])


def test_auto_and_id_ports_are_never_offered_to_the_model():
    schema = build_draft_schema(NODE_SET, ROIS)
    goto_ports = set(schema["$defs"]["GoTo"]["properties"])
    assert goto_ports == {"node", "target", "tolerance"}  # not agent_id, x, y, waypoints, goal_id...
    speaking = set(schema["$defs"]["IsAnyoneSpeaking"]["properties"])
    assert "speaker_id" not in speaking  # an agent id: post-processing's job
    for spec in NODES.values():
        assert all(not port.auto and port.type not in ("agent", "agents", "point_list") for port in written_ports(spec))


def test_depth_is_unrolled_and_bounded():
    schema = build_draft_schema(NODE_SET, ROIS, max_depth=3)
    defs = schema["$defs"]
    assert {"level_1", "level_2", "level_3"} <= set(defs) and "level_4" not in defs
    deepest = {option["$ref"].rsplit("/", 1)[1] for option in defs["level_3"]["anyOf"]}
    assert deepest == {"GoTo", "Queue", "Wait", "SaySomething", "IsRobotClose", "IsAnyoneSpeaking"}
    assert defs["Inverter_1"]["properties"]["children"]["maxItems"] == 1
    assert defs["Sequence_2"]["properties"]["children"] == {
        "type": "array", "items": {"$ref": "#/$defs/level_3"}, "minItems": 1, "maxItems": 4}
    assert defs["Repeat_1"]["required"] == ["node", "num_cycles", "children"]


def test_numbers_and_strings_are_bounded_for_the_grammar():
    schema = build_draft_schema(NODE_SET, ROIS)
    repeat = schema["$defs"]["Repeat_1"]["properties"]["num_cycles"]["enum"]
    assert -1 in repeat and max(repeat) <= 10000 and len(repeat) < 30
    message = schema["$defs"]["SaySomething"]["properties"]["message"]
    assert message["type"] == "string" and message["maxLength"] == 48
    schema_to_gbnf(schema)  # the whole schema stays inside the converter's subset


@pytest.mark.parametrize("names, rois, problem", [
    (["NoSuchNode"], ROIS, "unknown node type"),
    (["Sequence"], ROIS, "no action or condition"),
    (["GoTo"], [], "no RoI names"),
    ([], ROIS, "no node types"),
])
def test_schema_refuses_impossible_requests(names, rois, problem):
    with pytest.raises(DraftError, match=problem):
        build_draft_schema(names, rois)


def test_parse_round_trip():
    text = json.dumps(EXAMPLE)
    draft = parse_draft(text, NODE_SET, ROIS)
    assert draft == Draft((DraftGroup("patients", 10, "pharmacy", DraftNode("Sequence", {}, (
        DraftNode("GoTo", {"target": "pharmacy_counter"}),
        DraftNode("Queue", {"service_point": "pharmacy_counter", "spacing": 0.6}),
    ))),))
    assert parse_draft(draft_to_json(draft), NODE_SET, ROIS) == draft
    assert json.loads(draft_to_json(draft)) == EXAMPLE
    assert draft.places() == {"pharmacy", "pharmacy_counter"}
    assert draft.node_types() == {"Sequence", "GoTo", "Queue"}


def _with(path: str, value):
    data = json.loads(json.dumps(EXAMPLE))
    target = data
    keys = path.split(".")
    for key in keys[:-1]:
        target = target[int(key)] if key.isdigit() else target[key]
    last = keys[-1]
    if value is KeyError:
        del target[last]
    else:
        target[int(last) if last.isdigit() else last] = value
    return json.dumps(data)


@pytest.mark.parametrize("text, problem", [
    ("{\"groups\": [", "not valid JSON"),
    ('{"groups": [], "groups": []}', "appears twice"),
    (json.dumps({"groups": []}), "1..6 groups"),
    (_with("groups.0.count", 0), r"groups\[0\].count: 0 is not a whole number in 1..60"),
    (_with("groups.0.count", 61), "1..60"),
    (_with("groups.0.count", 2.5), "whole number"),
    (_with("groups.0.count", True), "whole number"),
    (_with("groups.0.spawn", "mars"), r"groups\[0\].spawn: \"mars\" is not one of the selected places"),
    (_with("groups.0.label", "x" * 25), "longer than 24"),
    (_with("groups.0.label", "bad\u0007label"), "characters outside"),
    (_with("groups.0.label", "  "), "must not be empty"),
    (_with("groups.0.extra", 1), "unexpected key"),
    (_with("groups.0.tree.children.0.target", "nowhere"), r"children\[0\].target"),
    (_with("groups.0.tree.children.0.target", KeyError), "missing key.*target"),
    (_with("groups.0.tree.children.0.node", "FlyTo"), "not one of the allowed node types"),
    (_with("groups.0.tree.children.0.agent_id", 3), "unexpected key.*agent_id"),
    (_with("groups.0.tree.children.1.spacing", 9.0), "outside 0.3..3.0"),
    (_with("groups.0.tree.children.1.spacing", "wide"), "expected a number"),
    (_with("groups.0.tree.children", []), "1..4 children"),
    (_with("groups.0.tree.children.0.children", []), "unexpected key.*children"),
    ('{"groups": [{"label": "a", "count": 1, "spawn": "pharmacy", "tree": {"node": "GoTo", "target": "main_exit", "tolerance": NaN}}]}',
     "NaN is not valid JSON"),
])
def test_parse_rejects_with_the_json_path(text, problem):
    with pytest.raises(DraftError, match=problem):
        parse_draft(text, NODE_SET, ROIS)


def test_parse_enforces_depth_and_decorator_arity():
    deep = {"node": "Sequence", "children": [{"node": "Sequence", "children": [{"node": "Sequence", "children": [{"node": "Wait"}]}]}]}
    text = json.dumps({"groups": [{"label": "a", "count": 1, "spawn": "pharmacy", "tree": deep}]})
    with pytest.raises(DraftError, match="3 levels deep"):
        parse_draft(text, NODE_SET, ROIS, max_depth=3)
    assert parse_draft(text, NODE_SET, ROIS, max_depth=4).groups[0].tree.children[0].children[0].children[0].node == "Wait"
    twins = {"node": "Inverter", "children": [{"node": "Wait"}, {"node": "Wait"}]}
    text = json.dumps({"groups": [{"label": "a", "count": 1, "spawn": "pharmacy", "tree": twins}]})
    with pytest.raises(DraftError, match="exactly 1 child"):
        parse_draft(text, NODE_SET, ROIS)


def test_children_bound_is_configurable():
    schema = build_draft_schema(NODE_SET, ROIS, max_children=2)
    assert schema["$defs"]["Sequence_1"]["properties"]["children"]["maxItems"] == 2
    assert schema["$defs"]["Inverter_1"]["properties"]["children"]["maxItems"] == 1
    three = json.dumps({"groups": [{"label": "a", "count": 1, "spawn": "pharmacy", "tree": {
        "node": "Sequence", "children": [{"node": "Wait"}] * 3}}]})
    assert len(parse_draft(three, NODE_SET, ROIS).groups[0].tree.children) == 3
    with pytest.raises(DraftError, match="1..2 children"):
        parse_draft(three, NODE_SET, ROIS, max_children=2)


def test_parse_accepts_in_bounds_numbers_outside_the_grammar_menu():
    """The grammar offers a short menu of values; a hand-written draft is held to the manifest bounds only."""
    text = _with("groups.0.tree.children.1.spacing", 0.65)
    assert parse_draft(text, NODE_SET, ROIS).groups[0].tree.children[1].ports["spacing"] == 0.65
