"""Our JSON-schema -> GBNF converter: exact output for small schemas, refusal of anything unbounded,
and every grammar the tests build compiled and sampled by llama.cpp (in the worker process, so a bad
grammar would show up as a ModelError, not a crashed test run)."""

from __future__ import annotations

import json

import pytest

from grove_tui.generation.draft import draft_grammar, parse_draft
from grove_tui.generation.presets import list_presets, load_preset
from grove_tui.world import list_worlds, load_world
from grove_tui.llm.grammar import GrammarError, gbnf_literal, json_literal, schema_to_gbnf
from grove_tui.llm.local import LocalLLM, ModelError


def rules(grammar: str) -> dict[str, str]:
    return dict(line.split(" ::= ", 1) for line in grammar.strip().splitlines())


def test_object_with_required_and_optional_properties():
    grammar = schema_to_gbnf({
        "type": "object",
        "properties": {"a": {"enum": ["x", "y"]}, "b": {"type": "boolean"}, "c": {"const": 3}},
        "required": ["a", "c"], "additionalProperties": False})
    table = rules(grammar)
    root_body = table[table["root"]] if table["root"] in table else table["root"]
    assert root_body == ('"{" "\\"a\\":" ws root-a ("," ws "\\"b\\":" ws boolean)? "," ws "\\"c\\":" ws "3" "}"')
    assert table["root-a"] == '"\\"x\\"" | "\\"y\\""'
    assert table["ws"] == '" "?'


def test_array_bounds_expand_to_nested_optionals():
    table = rules(schema_to_gbnf({"type": "array", "items": {"const": 1}, "minItems": 2, "maxItems": 4}))
    assert table[table["root"]] == '"[" "1" "," ws "1" ("," ws "1" ("," ws "1")?)? "]"'
    table = rules(schema_to_gbnf({"type": "array", "items": {"const": 1}, "minItems": 0, "maxItems": 2}))
    assert table[table["root"]] == '"[" ("1" ("," ws "1")?)? "]"'


def test_bounded_string_uses_the_safe_character_class():
    table = rules(schema_to_gbnf({"type": "string", "minLength": 1, "maxLength": 3}))
    assert table["safe-char"] == "[A-Za-z0-9 _.,'()/:-]"
    assert table["string-1-3"] == '"\\"" safe-char (safe-char (safe-char)?)? "\\""'


def test_integer_range_is_enumerated():
    table = rules(schema_to_gbnf({"type": "integer", "minimum": 8, "maximum": 11}))
    assert set(table["int-8-11"].split(" | ")) == {'"8"', '"9"', '"10"', '"11"'}


def test_refs_become_shared_rules_and_identical_bodies_are_merged():
    schema = {
        "type": "object",
        "properties": {"p": {"$ref": "#/$defs/place"}, "q": {"$ref": "#/$defs/other"}},
        "required": ["p", "q"], "additionalProperties": False,
        "$defs": {"place": {"enum": ["a", "b"]}, "other": {"enum": ["a", "b"]}},
    }
    table = rules(schema_to_gbnf(schema))
    assert table["place"] == '"\\"a\\"" | "\\"b\\""'
    assert "other" not in table
    assert table[table["root"]].count("place") == 2


@pytest.mark.parametrize("schema, problem", [
    ({"type": "string"}, "maxLength"),
    ({"type": "string", "maxLength": 4, "pattern": "^.*$"}, "pattern"),
    ({"type": "array", "items": {"const": 1}}, "maxItems"),
    ({"type": "array", "items": {"const": 1}, "maxItems": 100}, "maxItems"),
    ({"type": "number"}, "enum"),
    ({"type": "integer"}, "minimum"),
    ({"type": "integer", "minimum": 0, "maximum": 100000}, "range"),
    ({"type": "object", "properties": {"a": {"const": 1}}, "required": [], "additionalProperties": False}, "first property"),
    ({"type": "object", "properties": {"a": {"const": 1}}, "required": ["a"], "additionalProperties": True}, "additionalProperties"),
    ({"type": "object", "properties": {"a": {"const": 1}}, "required": ["a", "z"]}, "unknown properties"),
    ({"$ref": "#/$defs/loop", "$defs": {"loop": {"anyOf": [{"const": 1}, {"$ref": "#/$defs/loop"}]}}}, "cycle"),
    ({"$ref": "#/$defs/missing", "$defs": {}}, "no such definition"),
    ({"enum": []}, "non-empty"),
    ({"enum": [{"a": 1}]}, "scalar"),
    ({"type": "string", "maxLength": 4, "format": "date"}, "unsupported keyword"),
    ({"allOf": [{"const": 1}]}, "unsupported"),
])
def test_anything_outside_the_subset_is_refused(schema, problem):
    with pytest.raises(GrammarError, match=problem):
        schema_to_gbnf(schema)


def test_literals_are_escaped():
    assert gbnf_literal('a"b\\c') == '"a\\"b\\\\c"'
    assert gbnf_literal("\n") == '"\\x0A"'
    assert gbnf_literal("é") == '"\\xE9"'
    assert json_literal(2.0) == "2" and json_literal(0.5) == "0.5" and json_literal(True) == "true"
    assert json_literal("café") == '"caf\\u00e9"'


# ---- compiled and sampled by llama.cpp ---------------------------------------------------------

@pytest.fixture(scope="module")
def grammar_llm(tiny_path):
    """The tiny Qwen3 with room for the longest preset grammar's drafts."""
    llm = LocalLLM(tiny_path, role="grammar-test", n_ctx=2048, n_threads=1)
    yield llm
    llm.close()


UNIT_SCHEMAS = [
    {"type": "object", "properties": {"a": {"enum": ["x", "y"]}, "b": {"type": "boolean"}, "c": {"const": 3}},
     "required": ["a", "c"], "additionalProperties": False},
    {"type": "array", "items": {"type": "integer", "minimum": -3, "maximum": 12}, "minItems": 0, "maxItems": 5},
    {"type": "object", "properties": {"s": {"type": "string", "minLength": 0, "maxLength": 12}, "n": {"enum": [0.5, 1.0, 2.5]},
                                      "z": {"type": "null"}},
     "required": ["s", "n", "z"], "additionalProperties": False},
    {"anyOf": [{"const": "only"}, {"type": "array", "items": {"$ref": "#/$defs/leaf"}, "minItems": 1, "maxItems": 3}],
     "$defs": {"leaf": {"enum": ["p", "q", 'quo"te']}}},
]


@pytest.mark.slow
@pytest.mark.parametrize("index", range(len(UNIT_SCHEMAS)))
def test_unit_grammars_compile_and_produce_strict_json(grammar_llm, index):
    grammar = schema_to_gbnf(UNIT_SCHEMAS[index])
    for seed in range(4):
        result = grammar_llm.generate("<|im_start|>assistant\n", grammar=grammar, max_tokens=400, seed=seed, temperature=1.0)
        json.loads(result.text)
        assert result.grammar_engine == "llguidance"  # token masks took the grammar (no GBNF fallback)


def _preset_node_sets():
    """Per preset, every node the model may be offered from the real node database (all it can retrieve)."""
    from grove_tui.generation.node_docs import load_node_database
    from grove_tui.generation.synthesis import offered_nodes
    from grove_tui.paths import node_db_dir

    database = load_node_database(node_db_dir())
    sets = {}
    for name in list_presets():
        preset = load_preset(name)
        retrievable = [node for doc in database.documents
                       if preset.retrieval_filter is None or preset.retrieval_filter in doc.presets for node in doc.nodes]
        sets[name] = (offered_nodes(preset, retrievable), preset.limits)
    return sets


@pytest.mark.slow
def test_every_preset_draft_grammar_compiles_and_parses(grammar_llm):
    """The grammar of every preset's full node set over every shipped world: llama.cpp compiles and samples it
    (random weights write long, varied drafts), and parse_draft accepts what it wrote."""
    worlds = list_worlds()
    assert len(worlds) >= 4
    for index, world_name in enumerate(worlds):
        rois = [roi.name for roi in load_world(world_name).roi_index()]
        for preset, (nodes, limits) in _preset_node_sets().items():
            grammar = draft_grammar(nodes, rois, max_groups=limits.max_groups, max_count=limits.max_count,
                                    max_depth=limits.max_depth)
            result = grammar_llm.generate([{"role": "user", "content": f"{preset} scenario"}], grammar=grammar,
                                       max_tokens=1800, seed=index, temperature=1.0)
            draft = parse_draft(result.text, nodes, rois, max_groups=limits.max_groups, max_count=limits.max_count,
                                max_depth=limits.max_depth)
            assert draft.node_types() <= set(nodes) and draft.places() <= set(rois), (world_name, preset)
            assert result.grammar_engine == "llguidance", (world_name, preset)  # token masks, not the GBNF fallback


@pytest.mark.slow
def test_a_malformed_grammar_costs_one_worker_not_the_app(grammar_llm):
    """The reason only our own grammars are compiled: llama.cpp may die on a bad one, and only the worker goes."""
    with pytest.raises(ModelError):
        grammar_llm.generate("x", grammar="root ::= [a-", max_tokens=4)
    assert json.loads(grammar_llm.generate("x", grammar=schema_to_gbnf({"const": 7}), max_tokens=4).text) == 7


@pytest.mark.slow
def test_forced_tokens_are_evaluated_not_sampled_and_the_answer_repeats(grammar_llm):
    """Token masks (issue 33): the tokens the grammar forces (a node name's rest, its bracket) are taken
    without sampling and evaluated in one batch with the sampled token; the same seed gives the same text."""
    grammar = draft_grammar(["Sequence", "GoTo", "Queue"], ["pharmacy_counter", "pharmacy"], max_groups=2)
    runs = [grammar_llm.generate([{"role": "user", "content": "queue"}], grammar=grammar, max_tokens=600, seed=4,
                              temperature=1.0) for _ in range(2)]
    assert runs[0].text == runs[1].text
    assert runs[0].grammar_engine == "llguidance" and 0 < runs[0].forced_tokens < runs[0].completion_tokens
    parse_draft(runs[0].text, ["Sequence", "GoTo", "Queue"], ["pharmacy_counter", "pharmacy"], max_groups=2)
