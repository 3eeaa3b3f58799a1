"""World loading, validation messages and the RoI index, on the shipped worlds and bad fixtures."""

from __future__ import annotations

from helpers.paths import REPO, TEST_DATA
import math

import numpy as np
import pytest
from shapely.geometry import Point

from grove_tui.errors import GroveError
from grove_tui.navigation.grid import build_grid
from grove_tui.world import (
    Door,
    Entity,
    WorldError,
    Zone,
    check_world_file,
    list_worlds,
    load_world,
    parse_world,
)

BAD = TEST_DATA / "worlds_bad"
SHIPPED = ("hospital", "office", "residential", "airport", "station")

MINI = """\
name: mini
description: Two rooms joined by a door, with a desk.
zones:
  - name: room_a
    type: room
    aliases: [first room]
    boundary: [[0, 0], [5, 0], [5, 4], [0, 4]]
    doors:
      - {name: front_door, position: [2.5, 0], width: 1.2, leads_to: outside, exit: true}
      - {name: inner_door, position: [5, 2], width: 1.2, leads_to: room_b}
    entities:
      - name: desk
        type: desk
        footprint: [[1, 3], [2, 3], [2, 3.5], [1, 3.5]]
        interaction_point: [1.5, 2.4]
  - name: room_b
    type: room
    boundary: [[5, 0], [10, 0], [10, 4], [5, 4]]
"""


def mini_world():
    world, problems = parse_world(MINI, "mini.yaml")
    assert problems == []
    return world


# --- shipped worlds --------------------------------------------------------------------------


def test_all_four_worlds_are_shipped():
    assert set(SHIPPED) <= set(list_worlds())


@pytest.mark.parametrize("name", SHIPPED)
def test_shipped_world_loads_without_problems(name):
    path = REPO / "worlds" / f"{name}.yaml"
    assert check_world_file(path) == []
    world = load_world(name)
    assert world.name == name
    assert world.source == path.resolve()
    assert len(world.exits()) >= (2 if name != "residential" else 1)


@pytest.mark.parametrize("name", SHIPPED)
def test_names_are_unique_and_snake_case(name):
    world = load_world(name)
    names = [roi.name for roi in world.roi_index()] + [obstacle.name for obstacle in world.obstacles]
    assert len(names) == len(set(names))
    assert all(n.replace("_", "").isalnum() and n == n.lower() for n in names)


@pytest.mark.parametrize("name", SHIPPED)
def test_doors_are_wide_enough_for_crowds(name):
    world = load_world(name)
    for door in world.doors():
        assert door.width >= 1.2, door.name
        if door.exit and name != "residential":
            assert door.width >= 1.8, door.name


def test_hospital_has_what_prompts_name():
    world = load_world("hospital")
    assert len(world.zones) >= 12
    xmin, ymin, xmax, ymax = world.bounds()
    assert xmax - xmin >= 60 and ymax - ymin >= 40
    types = {zone.type for zone in world.zones}
    assert {"lobby", "pharmacy", "waiting_room", "corridor", "ward", "cafeteria", "restroom", "staff_room"} <= types
    entity_types = {entity.type for entity in world.entities()}
    assert {"reception_desk", "counter", "bed", "chair", "table", "vending_machine"} <= entity_types
    exits = {door.name for door in world.exits()}
    assert "main_entrance" in exits and len(exits) >= 2
    assert world.zone("pharmacy").type == "pharmacy"
    assert "drugstore" in world.zone("pharmacy").aliases


def test_corridors_are_at_least_two_point_four_metres_wide():
    for name in SHIPPED:
        world = load_world(name)
        for zone in world.zones:
            if zone.type == "corridor":
                xmin, ymin, xmax, ymax = zone.polygon.bounds
                assert min(xmax - xmin, ymax - ymin) >= 2.4 - 1e-9, (name, zone.name)


def test_pharmacy_queue_of_ten_fits_in_front_of_the_counter():
    world = load_world("hospital")
    counter = world.find("pharmacy_counter")
    assert isinstance(counter, Entity)
    start = np.array(counter.interaction_point)
    centre = np.array(counter.polygon.centroid.coords[0])
    away = (start - centre) / np.linalg.norm(start - centre)
    walkable = world.walkable()
    pharmacy = world.zone("pharmacy").polygon
    grid = build_grid(world, resolution=0.1, inflation=0.35)
    for k in range(10):
        spot = Point(*(start + away * 0.6 * k))
        # Each person (radius 0.25) stands fully on free floor inside the pharmacy.
        assert walkable.contains(spot.buffer(0.25)), k
        assert pharmacy.contains(spot), k
        assert grid.is_free(spot.x, spot.y), k


# --- model and geometry -----------------------------------------------------------------------


def test_zone_door_entity_lookups():
    world = mini_world()
    zone = world.zone("room_a")
    assert isinstance(zone, Zone)
    assert zone.centroid == (2.5, 2.0)
    assert isinstance(world.find("inner_door"), Door)
    assert isinstance(world.find("desk"), Entity)
    assert world.find("first room") is zone
    assert world.find("Room A") is zone
    assert world.zone_at(7, 1).name == "room_b"
    assert world.zone_at(11, 1) is None
    assert [door.name for door in world.exits()] == ["front_door"]
    assert {door.name for door in world.doors_of("room_b")} == {"inner_door"}
    with pytest.raises(WorldError, match="no zone named 'room_z'.*room_a"):
        world.zone("room_z")
    with pytest.raises(GroveError, match="did you mean desk"):
        world.find("desks")


def test_door_inward_point_is_inside_its_zone():
    world = mini_world()
    front = world.find("front_door")
    assert front.inward_point(0.6) == pytest.approx((2.5, 0.6))
    assert front.outward_point(0.6) == pytest.approx((2.5, -0.6))
    inner = world.find("inner_door")
    assert inner.inward_point(1.0) == pytest.approx((4.0, 2.0))
    assert world.zone_at(*inner.outward_point(1.0)).name == "room_b"
    assert np.allclose(inner.opening, ((5.0, 1.4), (5.0, 2.6)))


def _segments_on_line_x(walls, x):
    on_line = walls[(np.abs(walls[:, 0] - x) < 1e-9) & (np.abs(walls[:, 2] - x) < 1e-9)]
    return sorted(tuple(sorted((round(s[1], 6), round(s[3], 6)))) for s in on_line)


def test_walls_merge_shared_edges_and_cut_door_openings():
    walls = mini_world().walls()
    assert walls.dtype == np.float64 and walls.shape[1] == 4
    # The shared wall x = 5 appears once, with the 1.2 m inner door cut from y 1.4 to 2.6.
    assert _segments_on_line_x(walls, 5.0) == [(0.0, 1.4), (2.6, 4.0)]
    lengths = np.hypot(walls[:, 2] - walls[:, 0], walls[:, 3] - walls[:, 1])
    outer, shared, doors, desk = 28.0, 4.0, 2.4, 3.0
    assert lengths.sum() == pytest.approx(outer + shared - doors + desk)


def test_walkable_excludes_footprints_and_keeps_doors_open():
    world = mini_world()
    walkable = world.walkable()
    assert walkable.geom_type == "Polygon"  # one piece: the door joins the rooms
    assert not walkable.contains(Point(1.5, 3.2))  # desk
    assert walkable.contains(Point(5.0, 2.0))  # inner door opening
    assert not walkable.contains(Point(5.0, 3.0))  # shared wall


def test_roi_index_has_every_zone_door_and_entity_with_a_reachable_point():
    world = load_world("hospital")
    rois = world.roi_index()
    kinds = {kind: [r for r in rois if r.kind == kind] for kind in ("zone", "door", "entity")}
    assert len(kinds["zone"]) == len(world.zones)
    assert len(kinds["door"]) == len(world.doors())
    assert len(kinds["entity"]) == len(world.entities())
    walkable = world.walkable()
    for roi in rois:
        if roi.kind != "door":
            assert walkable.contains(Point(roi.point)), roi.name
    counter = next(r for r in rois if r.name == "pharmacy_counter")
    assert counter.zone == "pharmacy" and counter.type == "counter" and counter.polygon is not None
    entrance = next(r for r in rois if r.name == "main_entrance")
    assert entrance.exit and entrance.leads_to == "outside" and entrance.type == "exit"
    assert "dispensing" in counter.words()


def test_world_is_immutable():
    world = mini_world()
    with pytest.raises(AttributeError):
        world.name = "other"  # type: ignore[misc]
    with pytest.raises(Exception):
        world.zones[0].name = "x"  # type: ignore[misc]
    with pytest.raises(ValueError):
        world.walls()[0, 0] = 99.0


def test_unknown_world_name_lists_the_shipped_ones():
    with pytest.raises(WorldError, match="no shipped world.*hospital"):
        load_world("hospitl")
    with pytest.raises(WorldError, match="does not exist"):
        load_world("/nonexistent/world.yaml")


def test_loading_by_path_and_caching(tmp_path):
    path = tmp_path / "mini.yaml"
    path.write_text(MINI)
    first = load_world(path)
    assert first is load_world(str(path))
    path.write_text(MINI.replace("Two rooms", "Two small rooms") + "\n")
    assert load_world(path).description.startswith("Two small rooms")


# --- bad input: one test per class of problem -------------------------------------------------


def only_problem(filename, contains):
    problems = check_world_file(BAD / filename)
    matching = [p for p in problems if contains in p.message]
    assert matching, [str(p) for p in problems]
    return matching[0]


def assert_located(problem, filename, path, line):
    text = str(problem)
    assert text.startswith(f"{BAD / filename}:{line}: {path}: "), text
    assert problem.line == line and problem.path == path


def test_broken_yaml():
    problem = only_problem("broken_yaml.yaml", "broken YAML")
    assert_located(problem, "broken_yaml.yaml", "(document)", 7)


def test_door_not_on_its_zone_boundary():
    problem = only_problem("door_off_boundary.yaml", "is not on the boundary of its zone 'room_a'")
    assert_located(problem, "door_off_boundary.yaml", "zones[0].doors[0].position", 8)


def test_door_not_on_the_other_zones_boundary():
    problem = only_problem("door_off_other_boundary.yaml", "leads_to 'room_b' but is not on that zone's boundary")
    assert_located(problem, "door_off_other_boundary.yaml", "zones[0].doors[1].position", 9)


def test_entity_outside_its_zone():
    problem = only_problem("entity_outside_zone.yaml", "footprint is not inside its zone 'room_a'")
    assert_located(problem, "entity_outside_zone.yaml", "zones[0].entities[0].footprint", 13)


def test_interaction_point_inside_footprint():
    problem = only_problem("interaction_point_inside_footprint.yaml", "is inside its own footprint")
    assert_located(problem, "interaction_point_inside_footprint.yaml", "zones[0].entities[0].interaction_point", 14)


def test_interaction_point_outside_zone():
    problem = only_problem("interaction_point_outside_zone.yaml", "is outside its zone 'room_a'")
    assert_located(problem, "interaction_point_outside_zone.yaml", "zones[0].entities[0].interaction_point", 14)


def test_unknown_leads_to():
    problem = only_problem("unknown_leads_to.yaml", "leads_to unknown zone 'room_c'")
    assert "did you mean room_b" in problem.message
    assert_located(problem, "unknown_leads_to.yaml", "zones[0].doors[1].leads_to", 9)


def test_self_intersecting_polygon():
    problem = only_problem("self_intersecting_polygon.yaml", "self-intersecting")
    assert_located(problem, "self_intersecting_polygon.yaml", "zones[1].boundary", 17)


def test_zones_overlapping():
    problem = only_problem("zones_overlapping.yaml", "overlaps zone 'room_a'")
    assert "4.00 m^2" in problem.message
    assert_located(problem, "zones_overlapping.yaml", "zones[1].boundary", 17)


def test_duplicate_names():
    problem = only_problem("duplicate_names.yaml", "duplicate name 'room_b'")
    assert "zones[0].entities[0] (line 11)" in problem.message
    assert_located(problem, "duplicate_names.yaml", "zones[1].name", 15)


def test_non_positive_width():
    problem = only_problem("non_positive_width.yaml", "width must be positive, got 0")
    assert_located(problem, "non_positive_width.yaml", "zones[0].doors[1].width", 9)


def test_load_world_raises_with_every_problem():
    with pytest.raises(WorldError) as caught:
        load_world(BAD / "many_problems.yaml")
    error = caught.value
    assert isinstance(error, GroveError)
    paths = {problem.path for problem in error.problems}
    assert {"zones[0].doors[0].width", "zones[0].doors[1].leads_to",
            "zones[0].entities[0].interaction_point"} <= paths
    assert f"{(BAD / 'many_problems.yaml').resolve()}:8: zones[0].doors[0].width: width must be positive" in str(error)


def test_wrong_types_and_unknown_keys_are_reported_with_paths():
    text = MINI.replace("type: desk", "type: desk\n        colour: red").replace("width: 1.2, leads_to: room_b",
                                                                               "width: wide, leads_to: room_b")
    world, problems = parse_world(text, "typed.yaml")
    assert world is None
    by_path = {problem.path: problem for problem in problems}
    assert "unknown key 'colour'" in by_path["zones[0].entities[0].colour"].message
    assert by_path["zones[0].entities[0].colour"].line == 14
    assert "width must be a number" in by_path["zones[0].doors[1].width"].message


def test_entity_blocking_a_door_is_reported():
    text = MINI.replace("[[1, 3], [2, 3], [2, 3.5], [1, 3.5]]", "[[4.2, 1.5], [4.8, 1.5], [4.8, 2.5], [4.2, 2.5]]")
    text = text.replace("interaction_point: [1.5, 2.4]", "interaction_point: [3.5, 2.0]")
    _, problems = parse_world(text, "blocked.yaml")
    assert any("blocks door 'inner_door'" in p.message and p.path == "zones[0].entities[0].footprint" for p in problems)


def test_outside_door_on_a_shared_wall_is_reported():
    text = MINI.replace("position: [5, 2], width: 1.2, leads_to: room_b", "position: [5, 2], width: 1.2, leads_to: outside")
    _, problems = parse_world(text, "leak.yaml")
    assert any("sits on the wall shared with zone 'room_b'" in p.message for p in problems)


def test_door_wider_than_its_wall_is_reported():
    text = MINI.replace("position: [5, 2], width: 1.2", "position: [5, 2], width: 5.0")
    _, problems = parse_world(text, "wide.yaml")
    assert any(p.path == "zones[0].doors[1].width" and "runs past the corner" in p.message for p in problems)


def test_yaml_tags_beyond_safe_load_are_rejected():
    _, problems = parse_world("!!python/object:os.system {}\n", "evil.yaml")
    assert len(problems) == 1 and "broken YAML" in problems[0].message


def test_interaction_point_distances_are_sane_in_shipped_worlds():
    for name in SHIPPED:
        for entity in load_world(name).entities():
            gap = entity.polygon.exterior.distance(Point(entity.interaction_point))
            assert 0.45 <= gap <= 1.5, (name, entity.name, round(gap, 2))
            assert math.isfinite(gap)


def test_readme_example_is_a_valid_world():
    import re

    readme = (REPO / "worlds" / "README.md").read_text()
    example = re.search(r"```yaml\n(.*?)```", readme, re.S).group(1)
    world, problems = parse_world(example, "worlds/README.md")
    assert problems == []
    assert world.find("seats").name == "waiting_chairs"
    assert world.find("clinic_entrance").exit


def test_repeated_keys_are_reported_not_silently_overwritten():
    text = MINI.replace("    type: room\n    aliases", "    type: room\n    type: hall\n    aliases")
    world, problems = parse_world(text, "repeat.yaml")
    assert world is None
    assert [(p.path, p.line) for p in problems] == [("zones[0].type", 6)]
    assert "appears twice" in problems[0].message


def test_mangled_worlds_give_problems_never_crashes():
    import random
    import re

    base = (REPO / "worlds" / "residential.yaml").read_text()
    numbers = list(re.finditer(r"(?<![\w.])-?\d+(\.\d+)?", base))
    lines = base.splitlines()
    rng = random.Random(3)
    loaded = rejected = 0
    for _ in range(60):
        if rng.random() < 0.5:
            text = base
            for match in sorted(rng.sample(numbers, 2), key=lambda m: -m.start()):
                text = text[:match.start()] + str(rng.choice([0, -3, 0.5, 7.5, 16, 100, 6, 9])) + text[match.end():]
        else:
            mangled = list(lines)
            k = rng.randrange(len(mangled))
            mangled[k] = mangled[k].split(":")[0] + ": " + rng.choice(["null", "[]", "{}", "-1", "[[0, 0], [1, 1]]", "x"])
            text = "\n".join(mangled)
        world, problems = parse_world(text, "mangled.yaml")
        assert (world is None) == bool(problems)
        for problem in problems:
            assert problem.file == "mangled.yaml" and problem.path and problem.message
        if world is None:
            rejected += 1
        else:
            loaded += 1
            assert world.walls().shape[1] == 4
    assert rejected > 20


CORRIDOR_INTO_HALL = """
name: corridor_into_hall
description: A 2 m corridor whose whole east end is a door into a hall.
zones:
  - name: corridor
    type: corridor
    description: Corridor.
    boundary: [[0, 4], [10, 4], [10, 6], [0, 6]]
    doors:
      - {name: corridor_end, position: [10, 5], width: 2.0, leads_to: hall}
  - name: hall
    type: hall
    description: Hall.
    boundary: [[10, 0], [20, 0], [20, 10], [10, 10]]
"""


def test_a_door_spanning_a_whole_wall_edge_leaves_clean_jambs():
    """Issue 19: the cut used to bite 2 cm off the corridor's side walls, leaving gaps at both jambs."""
    from grove_tui.world import parse_world

    world, problems = parse_world(CORRIDOR_INTO_HALL, "corridor_into_hall.yaml")
    assert not problems
    walls = world.walls()
    ends = {(round(x, 9), round(y, 9)) for x1, y1, x2, y2 in walls for x, y in ((x1, y1), (x2, y2))}
    # The side walls run right up to the door line, where the hall's wall takes over: one corner each.
    assert (10.0, 4.0) in ends and (10.0, 6.0) in ends
    assert not any(9.9 < x < 10.0 for x, _y in ends), sorted(ends)
    assert _segments_on_line_x(walls, 10.0) == [(0.0, 4.0), (6.0, 10.0)]
    # ...and the opening itself stays open for the length of the door.
    lengths = np.hypot(walls[:, 2] - walls[:, 0], walls[:, 3] - walls[:, 1])
    assert lengths.sum() == pytest.approx(2 * 10 + 2 + 4 * 10 - 2)


@pytest.mark.parametrize("name", list_worlds())
def test_every_zone_anchor_is_walkable(name):
    """Plans, fields and labels start from a zone's anchor: it lies on a free cell of the planning grid,
    clear of the zone's entities and of the world's obstacles (the mall's racks sit on a shop's centre)."""
    world = load_world(name)
    grid = build_grid(world, resolution=0.1)
    for zone in world.zones:
        assert not grid.occupied[grid.world_to_cell(*zone.anchor)], (name, zone.name, zone.anchor)
        for obstacle in world.obstacles:
            assert not obstacle.polygon.contains(Point(zone.anchor)), (name, zone.name, obstacle.name)
