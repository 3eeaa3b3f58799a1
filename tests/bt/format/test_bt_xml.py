"""Parsing and validation: hostile and malformed XML is rejected with clear, line-numbered errors."""

from __future__ import annotations

import pytest
from click.testing import CliRunner
from lxml import etree

from grove_tui.bt.format.manifest import NODES, treenodes_model_xml
from grove_tui.bt.format.ports import format_point_list, parse_point_list
from grove_tui.bt.format.source import MAX_BYTES
from grove_tui.errors import BTError
from grove_tui.bt.format.xml import (
    MAX_DEPTH, MAX_EXPANDED_DEPTH, MAX_EXPANDED_NODES, MAX_PROBLEMS, MAX_SUGGESTIONS, check_tree_file, check_tree_text,
    load_tree_file, parse_tree_text,
)
from grove_tui.errors import GroveError


def tree(body: str, extra: str = "") -> str:
    return f'<root BTCPP_format="4" main_tree_to_execute="Main">\n<BehaviorTree ID="Main">\n{body}\n</BehaviorTree>{extra}\n</root>\n'


BILLION_LAUGHS = """<?xml version="1.0"?>
<!DOCTYPE lolz [
 <!ENTITY lol "lol">
 <!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
 <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">
 <!ENTITY lol4 "&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;">
 <!ENTITY lol9 "&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;">
]>
<root BTCPP_format="4"><BehaviorTree ID="Main"><SaySomething message="&lol9;"/></BehaviorTree></root>
"""

EXTERNAL_ENTITY = """<?xml version="1.0"?>
<!DOCTYPE root [<!ENTITY xxe SYSTEM "file:///etc/passwd">]>
<root BTCPP_format="4"><BehaviorTree ID="Main"><SaySomething message="&xxe;"/></BehaviorTree></root>
"""

EXTERNAL_DTD = """<?xml version="1.0"?>
<!DOCTYPE root SYSTEM "http://example.com/evil.dtd">
<root BTCPP_format="4"><BehaviorTree ID="Main"><Wait/></BehaviorTree></root>
"""


@pytest.mark.parametrize("text", [BILLION_LAUGHS, EXTERNAL_ENTITY, EXTERNAL_DTD], ids=["billion-laughs", "xxe", "dtd"])
def test_dtds_and_entities_are_rejected_before_parsing(text):
    with pytest.raises(BTError, match="DOCTYPE/ENTITY declarations are not allowed") as info:
        parse_tree_text(text, "evil.xml")
    assert "evil.xml:2" in str(info.value)
    assert isinstance(info.value, GroveError)


def test_undeclared_entity_reference_is_malformed_not_expanded():
    with pytest.raises(BTError, match="not well-formed"):
        parse_tree_text(tree('<SaySomething message="&xxe;"/>'), "t.xml")


def test_deep_nesting_is_rejected():
    depth = MAX_DEPTH + 10
    body = "<Inverter>" * depth + "<Wait/>" + "</Inverter>" * depth
    with pytest.raises(BTError, match=f"deeper than {MAX_DEPTH}"):
        parse_tree_text(tree(body), "deep.xml")


def test_oversized_input_is_rejected():
    body = "<Sequence>" + '<Wait duration="1"/>' * (MAX_BYTES // 20 + 1) + "</Sequence>"
    with pytest.raises(BTError, match="limited to"):
        parse_tree_text(tree(body), "big.xml")


def test_malformed_xml_names_the_line():
    with pytest.raises(BTError, match=r"broken.xml:4: not well-formed"):
        parse_tree_text('<root BTCPP_format="4">\n<BehaviorTree ID="Main">\n<Sequence>\n<Wait></Sequence>\n</root>',
                        "broken.xml")


def test_every_problem_is_reported_with_its_line():
    text = tree('<Sequence>\n<GoTo targt="counter"/>\n<Queu service_point="counter"/>\n<Wait duration="-3"/>\n'
                '<Repeat num_cycles="abc"><Wait/></Repeat>\n<RunOnce then_skip="maybe"><Wait/></RunOnce>\n'
                '<Inverter><Wait/><Wait/></Inverter>\n<Wait duration="1"><Wait/></Wait>\n</Sequence>')
    problems = check_tree_text(text, "bad.xml")
    messages = [(p.line, p.message) for p in problems]
    assert (4, "GoTo: unknown port 'targt' (did you mean target, target_y, target_x?); its ports are: target, x, y, waypoints, "
               "tolerance, agent_id, time_step, target_x, target_y, temporary, stop_duration, goal_id") in messages
    assert any(line == 4 and "missing required port 'target'" in m for line, m in messages)
    assert (5, "unknown node 'Queu' (did you mean Queue?)") in messages
    assert (6, "Wait: port 'duration' (float): -3.0 is below the minimum 0.0") in messages
    assert (7, "Repeat: port 'num_cycles' (int): expected an integer, got 'abc'") in messages
    assert (8, "RunOnce: port 'then_skip' (bool): expected true or false, got 'maybe'") in messages
    assert (9, "Inverter is a decorator and needs exactly one child, has 2") in messages
    assert (10, "Wait is an action and cannot have children") in messages
    with pytest.raises(BTError) as info:
        parse_tree_text(text, "bad.xml")
    assert f"{len(problems)} problem(s)" in str(info.value)
    assert "line 5: unknown node 'Queu'" in str(info.value)


def test_out_of_range_and_blackboard_pointers():
    problems = check_tree_text(tree('<Sequence><Wait duration="4000"/><RandomChanceCondition probability="1.5"/>'
                                    '<Queue service_point="c" spacing="{s}"/><Wait duration="{bad key}"/></Sequence>'))
    text = "\n".join(p.message for p in problems)
    assert "4000.0 is above the maximum 3600.0" in text
    # HuNavSim declares its ports without bounds; a value it runs is not refused here (issue 18)
    assert "probability" not in text
    assert "spacing" not in text  # {s} is a valid pointer, checked at run time
    assert "not a valid blackboard pointer" in text


def test_output_port_must_be_a_pointer():
    problems = check_tree_text(tree('<FindNearestAgent target_agent_id="3"/>'))
    assert any("output port 'target_agent_id' must name a blackboard entry" in p.message for p in problems)


def test_tree_structure_errors():
    assert any("main_tree_to_execute='Nope'" in p.message
               for p in check_tree_text('<root BTCPP_format="4" main_tree_to_execute="Nope">'
                                        '<BehaviorTree ID="Main"><Wait/></BehaviorTree></root>'))
    assert any("several BehaviorTrees" in p.message
               for p in check_tree_text('<root BTCPP_format="4"><BehaviorTree ID="A"><Wait/></BehaviorTree>'
                                        '<BehaviorTree ID="B"><Wait/></BehaviorTree></root>'))
    assert any('BTCPP_format must be "4"' in p.message
               for p in check_tree_text('<root BTCPP_format="3"><BehaviorTree ID="A"><Wait/></BehaviorTree></root>'))
    assert any("unknown BehaviorTree ID 'Missing'" in p.message for p in check_tree_text(tree('<SubTree ID="Missing"/>')))
    recursive = tree('<SubTree ID="Other"/>', '<BehaviorTree ID="Other"><SubTree ID="Main"/></BehaviorTree>')
    assert any("SubTree recursion: Main -> Other -> Main" in p.message for p in check_tree_text(recursive))
    assert any("<include> is resolved only for tree files" in p.message
               for p in check_tree_text('<root BTCPP_format="4"><include path="x.xml"/>'
                                        '<BehaviorTree ID="A"><Wait/></BehaviorTree></root>'))
    assert any("scripting attribute _skipIf" in p.message for p in check_tree_text(tree('<Wait _skipIf="x"/>')))
    assert any("exactly one root node" in p.message
               for p in check_tree_text('<root BTCPP_format="4"><BehaviorTree ID="A"><Wait/><Wait/></BehaviorTree></root>'))


def test_explicit_node_form_and_category_check():
    doc = parse_tree_text(tree('<Control ID="Sequence"><Action ID="Wait" duration="2"/></Control>'))
    assert doc.main.id == "Sequence" and doc.main.children[0].ports == {"duration": "2"}
    assert any("Wait is an action, not a condition" in p.message
               for p in check_tree_text(tree('<Condition ID="Wait"/>')))


def test_hunavsim_2_agent_tree_validates():
    """The shape of hunav_gazebo_wrapper/behavior_trees/agents_warehouse__agent_2_bt.xml (v4)."""
    text = """<root main_tree_to_execute="DefaultTree" BTCPP_format="4">
  <BehaviorTree ID="DefaultTree">
    <Fallback>
      <Sequence>
        <RunOnce then_skip="true"><SetGoal agent_id="{id}" goal_id="1"/></RunOnce>
        <Inverter><RunOnce then_skip="true"><SetGoal agent_id="{id}" goal_id="2"/></RunOnce></Inverter>
      </Sequence>
      <Sequence>
        <Inverter><IsGoalReached agent_id="{id}"/></Inverter>
        <RegularNav agent_id="{id}" time_step="{dt}"/>
      </Sequence>
      <UpdateGoal agent_id="{id}"/>
    </Fallback>
  </BehaviorTree>
</root>"""
    assert check_tree_text(text) == []


def test_point_lists_round_trip():
    points = parse_point_list("1.5,2;3,-4.25")
    assert points == ((1.5, 2.0), (3.0, -4.25))
    assert parse_point_list(format_point_list(points)) == points
    with pytest.raises(ValueError, match="x1,y1;x2,y2"):
        parse_point_list("1,2,3")


def test_treenodes_model_lists_every_non_builtin_node_with_its_ports():
    root = etree.fromstring(treenodes_model_xml().encode())
    model = root.find("TreeNodesModel")
    by_id = {el.get("ID"): el for el in model}
    expected = {name for name, spec in NODES.items() if spec.origin != "btcpp"}
    assert set(by_id) == expected
    goto = by_id["GoTo"]
    assert goto.tag == "Action"
    ports = {p.get("name"): p for p in goto.findall("input_port")}
    assert set(ports) == {p.name for p in NODES["GoTo"].ports}
    assert ports["tolerance"].get("default") == "0.3" and ports["tolerance"].get("type") == "double"
    assert by_id["FindNearestAgent"].find("output_port").get("name") == "target_agent_id"
    assert by_id["TimeDelay"].tag == "Decorator"


def test_behaviortree_cpp_loads_a_file_with_our_model():
    bt = pytest.importorskip("behaviortreepy")
    model = treenodes_model_xml().split("<root BTCPP_format=\"4\">", 1)[1].rsplit("</root>", 1)[0]
    text = ('<root BTCPP_format="4" main_tree_to_execute="Main"><BehaviorTree ID="Main"><Sequence><AlwaysSuccess/>'
            '</Sequence></BehaviorTree>' + model + "</root>")
    assert check_tree_text(text) == []
    factory = bt.BehaviorTreeFactory()
    assert factory.create_tree_from_text(text).tick_exactly_once() == bt.NodeStatus.SUCCESS


def test_cli_manifest_and_validate(tmp_path):
    from grove_tui.cli.bt import bt

    runner = CliRunner()
    result = runner.invoke(bt, ["manifest"])
    assert result.exit_code == 0 and "<TreeNodesModel>" in result.output and 'ID="Queue"' in result.output
    good = tmp_path / "good.xml"
    good.write_text(tree('<Sequence><GoTo target="counter"/><Queue service_point="counter"/></Sequence>'))
    bad = tmp_path / "bad.xml"
    bad.write_text(tree("<Sequence>\n<GoTo/>\n<Wander zone='hall' duration='x'/>\n</Sequence>"))
    result = runner.invoke(bt, ["validate", str(good)])
    assert result.exit_code == 0 and "good.xml: ok" in result.output
    result = runner.invoke(bt, ["validate", str(bad)])
    assert result.exit_code == 1  # problems found, like a linter
    result = runner.invoke(bt, ["validate", str(good), str(bad), str(tmp_path / "missing.xml")])
    assert result.exit_code == 2  # a file that cannot be read wins; the others are still checked and listed
    assert f"{bad}:4: GoTo: missing required port 'target'" in result.output
    assert f"{bad}:5: Wander: port 'duration' (float): expected a number, got 'x'" in result.output
    assert f"error: {tmp_path / 'missing.xml'}: does not exist (hint: " in result.stderr
    assert "1 of 3 file(s) have problems; 1 could not be read" in result.output


def test_check_tree_file_reports_unreadable_files(tmp_path):
    problems = check_tree_file(tmp_path / "nope.xml")
    assert len(problems) == 1 and problems[0].message == "does not exist"


# ---- hostile files and limits (issue 17) --------------------------------------------------------

def _chain(n: int, leaf: str = "<Wait/>") -> str:
    """A main tree calling T1, which calls T2, ... down to T<n>, which runs `leaf`."""
    trees = "".join(f'<BehaviorTree ID="T{i}"><SubTree ID="T{i + 1}"/></BehaviorTree>' for i in range(n))
    return f'<root BTCPP_format="4" main_tree_to_execute="T0">{trees}<BehaviorTree ID="T{n}">{leaf}</BehaviorTree></root>'


@pytest.mark.parametrize("path, kind", [("/dev/zero", "a device"), ("symlink", "a device"), ("fifo", "a pipe")])
def test_validate_refuses_devices_links_to_them_and_fifos_at_once(tmp_path, path, kind):
    import os
    import time

    from grove_tui.cli.bt import bt

    if path == "symlink":
        path = tmp_path / "tree.xml"
        path.symlink_to("/dev/zero")
    elif path == "fifo":
        path = tmp_path / "tree.xml"
        os.mkfifo(path)  # no writer: a blocking open would wait for ever
    started = time.perf_counter()
    result = CliRunner().invoke(bt, ["validate", str(path)])
    assert time.perf_counter() - started < 5
    assert result.exit_code == 2  # could not read the input, apart from exit 1 (a tree with problems)
    (line,) = result.stderr.splitlines()
    assert line.startswith(f"error: {path}: is {kind}, not a file (hint: ")
    with pytest.raises(BTError, match=f"is {kind}, not a file"):
        load_tree_file(path)


def test_a_file_over_the_size_limit_is_refused_before_it_is_read(tmp_path):
    big = tmp_path / "big.xml"
    with open(big, "wb") as handle:
        handle.truncate(MAX_BYTES * 50)  # sparse: large on paper, nothing to read
    problems = check_tree_file(big)
    assert len(problems) == 1 and "the limit is" in problems[0].message
    from grove_tui.cli.bt import bt

    result = CliRunner().invoke(bt, ["validate", str(big)])
    assert result.exit_code == 2 and result.stderr.startswith(f"error: {big}: ") and "the limit is" in result.stderr
    with pytest.raises(BTError, match="the limit is"):
        load_tree_file(big)


@pytest.mark.parametrize("text, message", [
    ("", "empty file"),
    ("   \n", "empty file"),
    ("hello, not a tree", "not well-formed XML: Start tag expected"),
    ('{"groups": []}', "not well-formed XML"),
    ("<root>", "not well-formed XML"),
])
def test_empty_or_not_xml_is_one_line(tmp_path, text, message):
    from grove_tui.cli.bt import bt

    path = tmp_path / "t.xml"
    path.write_text(text)
    with pytest.raises(BTError, match=message) as info:
        parse_tree_text(text, "t.xml")
    assert "\n" not in str(info.value)
    (problem,) = check_tree_file(path)
    assert message in problem.message
    result = CliRunner().invoke(bt, ["validate", str(path)])
    assert result.exit_code == 1
    lines = result.output.splitlines()
    assert len(lines) == 2 and message in lines[0] and lines[1] == "1 of 1 file(s) have problems"


def test_a_chain_of_2400_subtrees_is_a_bt_error_not_a_recursion_error():
    with pytest.raises(BTError, match=f"SubTree calls nest 2401 levels deep from 'T0'; the limit is "
                                      f"{MAX_EXPANDED_DEPTH}"):
        parse_tree_text(_chain(2400), "chain.xml")
    # a chain within the limit builds and runs
    from grove_tui.crowd.leaves.registry import tree_factory
    from grove_tui.bt.runtime.tree_node import SUCCESS

    tree = tree_factory().create(parse_tree_text(_chain(MAX_EXPANDED_DEPTH - 2, "<AlwaysSuccess/>")))
    assert tree.tick() == SUCCESS


def test_subtrees_that_expand_exponentially_are_refused():
    trees = "".join(f'<BehaviorTree ID="T{i}"><Sequence><SubTree ID="T{i + 1}"/><SubTree ID="T{i + 1}"/></Sequence>'
                    "</BehaviorTree>" for i in range(40))
    text = f'<root BTCPP_format="4" main_tree_to_execute="T0">{trees}<BehaviorTree ID="T40"><Wait/></BehaviorTree></root>'
    assert [p.message for p in check_tree_text(text)] == [
        f"expanding the SubTree calls of 'T0' gives more than {MAX_EXPANDED_NODES} nodes"]


def test_recursion_through_a_long_chain_is_found_without_recursing():
    text = _chain(2400, '<SubTree ID="T0"/>')
    assert any(p.message.startswith("SubTree recursion: T0 -> T1 -> T2") and p.message.endswith("T2400 -> T0")
               for p in check_tree_text(text))


def test_2400_subtrees_calling_unknown_ids_are_reported_fast_with_bounded_suggestions():
    import time

    n = 2400
    # every call is one letter off a real tree ID, so every one of them has a close match
    trees = "".join(f'<BehaviorTree ID="Tree{i}"><SubTree ID="Tree{i}x"/></BehaviorTree>' for i in range(n))
    text = f'<root BTCPP_format="4" main_tree_to_execute="Tree0">{trees}</root>'
    started = time.perf_counter()
    problems = check_tree_text(text)
    assert time.perf_counter() - started < 10
    assert len(problems) == MAX_PROBLEMS + 1
    assert problems[-1].message == f"... and {n - MAX_PROBLEMS} more problem(s)"
    suggested = [p for p in problems if "did you mean" in p.message]
    assert 0 < len(suggested) <= MAX_SUGGESTIONS
    assert "SubTree refers to unknown BehaviorTree ID 'Tree0x' (did you mean Tree0" in problems[0].message


def test_xinclude_is_never_processed(tmp_path):
    secret = tmp_path / "secret.xml"
    secret.write_text('<BehaviorTree ID="Leak"><SaySomething message="TOP-SECRET"/></BehaviorTree>')
    text = (f'<root BTCPP_format="4" xmlns:xi="http://www.w3.org/2001/XInclude"><xi:include href="{secret}"/>'
            '<BehaviorTree ID="Main"><Wait/></BehaviorTree></root>')
    problems = check_tree_text(text)
    # refused as a namespaced element (BT.CPP files use none), so it is never read, nor written back unreadable
    assert [p.message for p in problems] == ["<xi:include>: XML namespaces are not used in behavior trees"]
    assert "TOP-SECRET" not in str(problems)
