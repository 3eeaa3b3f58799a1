"""Fuzzing the tree reader, validator, writer and factory: whatever the bytes, the answer is a tree or a BTError.

Bounded for CI (a few seconds); the mutations start from valid trees, so most inputs get past the
XML parser and exercise the structure checks, the manifest validation, the SubTree analysis and
the runtime factory rather than dying in the first byte.
"""

from __future__ import annotations

import pytest

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from grove_tui.crowd.leaves.registry import tree_factory
from grove_tui.bt.format.xml import check_tree_text, parse_tree_text, read_tree, write_tree
from grove_tui.errors import BTError

SEEDS = (
    '<root BTCPP_format="4" main_tree_to_execute="Main"><BehaviorTree ID="Main"><Sequence>'
    '<GoTo target="desk" x="1" y="2" waypoints="1,2;3,4"/><Wait duration="2"/><SubTree ID="S" _autoremap="true"/>'
    '</Sequence></BehaviorTree><BehaviorTree ID="S"><Repeat num_cycles="3"><AlwaysSuccess/></Repeat>'
    "</BehaviorTree></root>",
    '<?xml version="1.0" encoding="UTF-8"?>\n<root><BehaviorTree ID="a"><Action ID="Wait" name="x"/></BehaviorTree>'
    '<TreeNodesModel><Action ID="X"><input_port name="p">d</input_port></Action></TreeNodesModel></root>',
)
PIECES = ('<', '>', '/', '=', '"', '{', '}', '&', ';', '!', ' ', '\n', 'ID', 'SubTree', 'BehaviorTree', 'root',
          'Sequence', '0', '9', '.', ',', '\x00', '\x7f', '&lt;', '&#0;', '<!DOCTYPE r [<!ENTITY e "x">]>',
          '<![CDATA[x]]>', '\ud800', 'é', "<xi:include xmlns:xi='http://www.w3.org/2001/XInclude' href='/etc/passwd'/>")


@st.composite
def mutated_trees(draw) -> str:
    text = draw(st.sampled_from(SEEDS))
    for _ in range(draw(st.integers(1, 6))):
        at = draw(st.integers(0, len(text)))
        kind = draw(st.sampled_from(("insert", "delete", "duplicate")))
        if kind == "insert":
            text = text[:at] + draw(st.sampled_from(PIECES)) + text[at:]
        elif kind == "delete":
            text = text[:at] + text[at + draw(st.integers(1, 8)):]
        else:
            text = text[:at] + text[draw(st.integers(0, len(text))):][: draw(st.integers(1, 40))] + text[at:]
    return text


@pytest.mark.slow
@settings(max_examples=1000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(text=mutated_trees(), as_bytes=st.booleans())
def test_any_input_gives_a_tree_or_a_bt_error(text, as_bytes):
    data = text.encode("utf-8", "surrogatepass") if as_bytes else text
    assert isinstance(check_tree_text(data), list)
    try:
        document = read_tree(data)
    except BTError:
        pass
    else:
        assert read_tree(write_tree(document)) == document
    try:
        document = parse_tree_text(data)
    except BTError:
        return
    tree_factory().create(document)
