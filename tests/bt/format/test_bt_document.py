"""The tree document: read, edit and write back through bt/ with nothing lost and nothing recursing."""

from __future__ import annotations

import pytest

from grove_tui.bt.format.document import TreeDocument, TreeElement, node, subtree_call
from xml.sax.saxutils import escape

from grove_tui.bt.format.manifest import NODES, treenodes_model_xml
from grove_tui.errors import BTError
from grove_tui.bt.format.xml import MAX_DEPTH, parse_tree_text, read_tree, validate_document, write_tree


def test_the_writer_writes_the_one_documented_layout():
    document = TreeDocument.single("agent_1", node("Sequence", [
        node("GoTo", target="desk", x="1.5", y="-2", waypoints=""),
        node("Wait", duration="2"),
    ]))
    assert write_tree(document) == (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        '<root BTCPP_format="4" main_tree_to_execute="agent_1">\n'
        '  <BehaviorTree ID="agent_1">\n'
        '    <Sequence>\n'
        '      <GoTo target="desk" x="1.5" y="-2" waypoints=""/>\n'
        '      <Wait duration="2"/>\n'
        '    </Sequence>\n'
        '  </BehaviorTree>\n'
        '</root>\n'
    )


def test_attribute_values_survive_any_characters():
    awkward = 'say "hi" & \'bye\' <now>\n\tthen\r done > {x}'
    document = TreeDocument.single("Main", node("SaySomething", message=awkward))
    text = write_tree(document)
    again = read_tree(text)
    assert again == document
    assert again.main.get("message") == awkward
    assert write_tree(again) == text
    assert parse_tree_text(text).main.ports == {"message": awkward}


def test_a_file_read_and_written_is_unchanged_models_and_subtrees_included():
    model = treenodes_model_xml().split('<root BTCPP_format="4">', 1)[1].rsplit("</root>", 1)[0]
    text = ('<root BTCPP_format="4" main_tree_to_execute="Main">'
            '<BehaviorTree ID="Main"><Sequence><SubTree ID="Errand" target="{goal}" _autoremap="true"/>'
            '<Action ID="Wait" name="pause" duration="3"/></Sequence></BehaviorTree>'
            '<BehaviorTree ID="Errand"><GoTo target="{target}"/></BehaviorTree>' + model + "</root>")
    document = read_tree(text)
    written = write_tree(document)
    assert read_tree(written) == document
    assert write_tree(read_tree(written)) == written
    goto_target = NODES["GoTo"].port("target").description
    assert "<TreeNodesModel>" in written and f'<input_port name="target"' in written
    assert escape(goto_target) in written
    call, pause = document.main.children
    assert (call.id, call.subtree_id, call.name, call.autoremap, call.ports) == (
        "SubTree", "Errand", "Errand", True, {"target": "{goal}"})
    assert (pause.id, pause.name, pause.ports) == ("Wait", "pause", {"duration": "3"})
    assert [t.get("ID") for t in document.ordered_trees()] == ["Main", "Errand"]
    assert validate_document(document) == document


def test_walks_are_depth_first_in_tick_order_and_edits_by_parent_land_in_place():
    document = TreeDocument.single("Main", node("Sequence", [
        node("Fallback", [node("GoTo", target="a"), node("GoTo", target="b")]),
        node("Wait"),
        subtree_call("Other"),
    ]))
    assert [e.id for e in document.nodes()] == ["Sequence", "Fallback", "GoTo", "GoTo", "Wait", "SubTree"]
    assert [p for p, _ in document.main.walk_with_paths()] == [(), (0,), (0, 0), (0, 1), (1,), (2,)]
    for parent, index, element in document.nodes_with_parents():
        if element.id == "GoTo":
            parent.children[index] = node("Wait", duration=element.get("target") == "a" and "1" or "2")
    assert [(e.id, e.get("duration")) for e in document.nodes()][2:4] == [("Wait", "1"), ("Wait", "2")]


def test_a_copy_is_independent():
    document = TreeDocument.single("Main", node("GoTo", target="a", x="1", y="1"))
    copy = document.copy()
    copy.main.set("x", "5")
    assert document.main.get("x") == "1" and copy != document


def test_very_deep_documents_neither_recurse_when_written_nor_load_when_read():
    deepest = root = TreeElement("Inverter")
    for _ in range(5000):  # far beyond Python's recursion limit
        child = TreeElement("Inverter")
        deepest.children.append(child)
        deepest = child
    deepest.children.append(node("AlwaysSuccess"))
    text = write_tree(TreeDocument.single("Main", root))
    assert text.count("<Inverter>") == 5001 and len(list(root.walk())) == 5002
    compact = ('<root><BehaviorTree ID="Main">' + "<Inverter>" * 200 + "<AlwaysSuccess/>" + "</Inverter>" * 200
               + "</BehaviorTree></root>")
    with pytest.raises(BTError, match=f"deeper than {MAX_DEPTH} levels"):
        read_tree(compact)


def test_read_tree_checks_structure_but_not_nodes():
    assert read_tree('<root><BehaviorTree ID="a"><NotANode foo="1"/></BehaviorTree></root>').main.id == "NotANode"
    for text, message in [
        ('<BehaviorTree ID="a"><Wait/></BehaviorTree>', "top element must be <root>"),
        ("<root/>", "no <BehaviorTree>"),
        ('<root><BehaviorTree><Wait/></BehaviorTree></root>', "needs an ID"),
        ('<root><BehaviorTree ID="a"><Wait/><Wait/></BehaviorTree></root>', "exactly one root node"),
    ]:
        with pytest.raises(BTError, match=message):
            read_tree(text)


@pytest.mark.parametrize("value", ["bell\x07", "nul\x00", "lone \ud800 surrogate"])
def test_characters_xml_cannot_carry_are_refused_on_both_sides(value):
    with pytest.raises(BTError, match="cannot be written in XML"):
        write_tree(TreeDocument.single("Main", node("SaySomething", message=value)))
    with pytest.raises(BTError):
        read_tree(f'<root><BehaviorTree ID="Main"><SaySomething message="{value}"/></BehaviorTree></root>')
