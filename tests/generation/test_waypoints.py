"""Waypoint injection: planned legs land in the navigation nodes, the tree is otherwise untouched."""

from __future__ import annotations

import numpy as np
import pytest
from lxml import etree

from grove_tui.navigation.grid import OccupancyGrid, build_grid
from grove_tui.navigation.theta_star import PlanningError, ThetaStarPlanner
from grove_tui.bt.format.ports import format_point_list, parse_point_list
from grove_tui.errors import BTError
from grove_tui.bt.format.xml import read_tree, write_tree
from grove_tui.generation.waypoints import plan_waypoints
from grove_tui.world import load_world


def inject_waypoints(xml: str, start, planner, start_label: str = "start") -> str:
    """`plan_waypoints` on a tree written as text: read and written back by the codec."""
    return write_tree(plan_waypoints(read_tree(xml), start, planner, start_label))


def two_rooms() -> OccupancyGrid:
    occupied = np.zeros((60, 60), dtype=bool)
    occupied[0, :] = occupied[-1, :] = occupied[:, 0] = occupied[:, -1] = True
    occupied[:, 30] = True
    occupied[45:49, 30] = False  # the only door, near the top
    occupied[20:40, 45:47] = True  # a screen in the right room
    return OccupancyGrid(origin=(0.0, 0.0), resolution=0.1, occupied=occupied, inflation=0.0, world_name="rooms")


TREE = """<?xml version="1.0" encoding="UTF-8"?>
<root BTCPP_format="4" main_tree_to_execute="agent_1">
  <!-- written by post-processing -->
  <BehaviorTree ID="agent_1">
    <Sequence name="errand">
      <GoTo target="desk" x="5.0" y="1.0" tolerance="0.3" agent_id="{id}"/>
      <Wait duration="2.5"/>
      <Fallback>
        <GoTo target="counter" x="1.0" y="1.0" waypoints="9,9;8,8"/>
        <Converse target="sofa" x="5.5" y="5.0" members="2,3" duration="10"/>
      </Fallback>
    </Sequence>
  </BehaviorTree>
  <BehaviorTree ID="helper">
    <GoTo target="counter" x="1.0" y="1.0"/>
  </BehaviorTree>
</root>
"""
START = (1.0, 2.0)  # left room


@pytest.fixture(scope="module")
def planner():
    return ThetaStarPlanner(two_rooms())


def navigation_nodes(xml: str):
    root = etree.fromstring(xml.encode())
    return [e for e in root.iter() if e.tag in ("GoTo", "Converse")]


def test_each_leg_is_planned_from_the_previous_target(planner):
    out = inject_waypoints(TREE, START, planner)
    nodes = navigation_nodes(out)
    assert [n.get("target") for n in nodes] == ["desk", "counter", "sofa", "counter"]
    chains = [
        (START, nodes[0]),  # start -> desk (through the door)
        ((5.0, 1.0), nodes[1]),  # desk -> counter (back through the door)
        ((1.0, 1.0), nodes[2]),  # counter -> sofa
        (START, nodes[3]),  # the second tree starts from the start again
    ]
    for origin, node in chains:
        target = (float(node.get("x")), float(node.get("y")))
        expected = planner.plan(origin, target)[1:-1]
        assert node.get("waypoints") == format_point_list(expected)
        parsed = parse_point_list(node.get("waypoints"))
        assert len(parsed) == len(expected)
        if parsed:
            np.testing.assert_allclose(parsed, expected, atol=0.0051)
    assert nodes[3].get("waypoints") == "", "a straight leg has no intermediate points"
    waypoints = parse_point_list(nodes[0].get("waypoints"))
    through_door = [(x, y) for x, y in waypoints if 2.8 <= x <= 3.3 and 4.3 <= y <= 5.0]
    assert through_door, f"start -> desk crosses the wall, so it bends at the door: {nodes[0].get('waypoints')}"


def test_structure_and_other_attributes_are_kept(planner):
    out = inject_waypoints(TREE, START, planner)
    # comments and layout are not part of a tree: the hardened reader drops them
    layout_free = etree.XMLParser(remove_comments=True, remove_blank_text=True)
    before = etree.fromstring(TREE.encode(), layout_free)
    after = etree.fromstring(out.encode(), layout_free)
    for element in (*before.iter(), *after.iter()):
        if isinstance(element.tag, str):
            element.attrib.pop("waypoints", None)
    assert etree.tostring(before) == etree.tostring(after)
    assert out.startswith('<?xml version="1.0" encoding="UTF-8"?>')
    assert "<!--" not in out


def test_injecting_twice_changes_nothing(planner):
    once = inject_waypoints(TREE, START, planner)
    assert inject_waypoints(once, START, planner) == once
    stale = etree.fromstring(once.encode())
    for node in stale.iter("GoTo"):
        node.set("waypoints", "9.00,9.00")
    stale_xml = '<?xml version="1.0" encoding="UTF-8"?>\n' + etree.tostring(stale, encoding="unicode")
    assert stale_xml != once
    assert inject_waypoints(stale_xml, START, planner) == once


def test_queue_moves_the_start_of_the_next_leg(planner):
    xml = ('<root><BehaviorTree ID="a"><Sequence>'
           '<Queue service_point="counter" x="5.5" y="5.5"/>'
           '<GoTo target="exit" x="1.0" y="5.5"/>'
           '</Sequence></BehaviorTree></root>')
    out = inject_waypoints(xml, START, planner)
    (goto,) = navigation_nodes(out)
    assert goto.get("waypoints") == format_point_list(planner.plan((5.5, 5.5), (1.0, 5.5))[1:-1])
    assert "waypoints" not in etree.fromstring(out.encode()).find(".//Queue").attrib


def test_missing_or_unresolved_target_is_an_error_naming_the_node(planner):
    xml = '<root><BehaviorTree ID="a"><GoTo target="pharmacy" y="1.0"/></BehaviorTree></root>'
    with pytest.raises(PlanningError, match=r"<GoTo> target='pharmacy' line 1 has no resolved 'x'"):
        inject_waypoints(xml, START, planner)
    xml = '<root><BehaviorTree ID="a"><GoTo target="pharmacy" x="{px}" y="1.0"/></BehaviorTree></root>'
    with pytest.raises(PlanningError, match="not a number"):
        inject_waypoints(xml, START, planner)


def test_unreachable_leg_names_both_ends():
    occupied = np.zeros((20, 40), dtype=bool)
    occupied[:, 20] = True
    grid = OccupancyGrid(origin=(0.0, 0.0), resolution=0.1, occupied=occupied, inflation=0.0, world_name="split")
    xml = ('<root><BehaviorTree ID="a"><Sequence><GoTo target="lobby" x="0.5" y="0.5"/>'
           '<GoTo target="ward_3" x="3.5" y="0.5"/></Sequence></BehaviorTree></root>')
    with pytest.raises(PlanningError, match="'lobby'.*'ward_3'"):
        inject_waypoints(xml, (0.2, 0.2), ThetaStarPlanner(grid))


def test_external_entities_and_broken_xml_are_refused(planner, tmp_path):
    secret = tmp_path / "secret.txt"
    secret.write_text("TOP-SECRET")
    xml = (f'<!DOCTYPE root [<!ENTITY leak SYSTEM "file://{secret}">]>'
           '<root><BehaviorTree ID="a"><GoTo target="desk" x="5.0" y="1.0">&leak;</GoTo></BehaviorTree></root>')
    with pytest.raises(BTError, match="DOCTYPE/ENTITY declarations are not allowed") as info:
        inject_waypoints(xml, START, planner)
    assert "TOP-SECRET" not in str(info.value)
    with pytest.raises(BTError, match="not well-formed"):
        inject_waypoints("<root><BehaviorTree>", START, planner)


def test_planning_a_document_edits_it_in_place_and_text_round_trips(planner):
    document = read_tree(TREE)
    assert plan_waypoints(document, START, planner) is document
    assert write_tree(document) == inject_waypoints(TREE, START, planner)
    assert read_tree(write_tree(document)) == document


def test_waypoint_text_round_trips():
    assert format_point_list([(1.0, -2.004), (-0.001, 3.456)]) == "1.00,-2.00;0.00,3.46"
    assert parse_point_list("1.00,-2.00;0.00,3.46") == ((1.0, -2.0), (0.0, 3.46))
    assert parse_point_list("") == ()
    with pytest.raises(ValueError, match="expected points like 'x1,y1;x2,y2', got '1.0'"):
        parse_point_list("1.0")


def test_hospital_tree_waypoints_keep_clear_of_walls():
    world = load_world("hospital")
    grid = build_grid(world, resolution=0.1)
    planner = ThetaStarPlanner(grid, landmarks=0)  # injection is under test here, not the heuristic
    entities = world.entities()
    first, second = entities[0], entities[-1]
    exit_point = world.exits()[0].inward_point(0.6)
    xml = ('<root><BehaviorTree ID="a"><Sequence>'
           f'<GoTo target="{first.name}" x="{first.interaction_point[0]}" y="{first.interaction_point[1]}"/>'
           f'<GoTo target="{second.name}" x="{second.interaction_point[0]}" y="{second.interaction_point[1]}"/>'
           f'<GoTo target="exit" x="{exit_point[0]}" y="{exit_point[1]}"/>'
           '</Sequence></BehaviorTree></root>')
    start = world.zones[0].anchor
    out = inject_waypoints(xml, start, planner)
    legs = 0
    for node in navigation_nodes(out):
        points = parse_point_list(node.get("waypoints"))
        legs += bool(points)
        for x, y in points:
            assert grid.is_free(x, y), f"waypoint ({x}, {y}) of {node.get('target')} is not in free space"
        for a, b in zip(points[:-1], points[1:]):
            assert planner.segment_is_free(*a, *b), f"{node.get('target')}: {a} -> {b} crosses an obstacle"
    assert legs >= 2, "crossing the hospital needs intermediate waypoints"
