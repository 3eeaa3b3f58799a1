"""The HuNavSim export's world: a Gazebo SDF whose walls are the world file's walls (door gaps open,
furniture as boxes) on a ground plane under every goal, and a nav2 map of those same boxes over the
same extent (issue 30: whole scenes, one truth per quantity)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import yaml
from helpers.handmade import build_evacuation_bundle
from lxml import etree
import shapely
from shapely.geometry import LineString, Point, Polygon

from grove_tui.exports.hunav import export_hunav
from grove_tui.exports.nav2_map import read_pgm
from grove_tui.world import load_world

GROUND = "ground_plane"


@pytest.fixture(scope="module")
def evacuation_export(tmp_path_factory):
    """Office evacuees through the main entrance: their muster points lie outside the building."""
    bundle = build_evacuation_bundle(tmp_path_factory.mktemp("evac") / "bundle")
    return export_hunav(bundle, tmp_path_factory.mktemp("out") / "hunav")


def _floats(text, n):
    values = [float(v) for v in text.split()]
    assert len(values) == n and all(math.isfinite(v) for v in values), text
    return values


def _models(hospital_export):
    data = hospital_export.world_file.read_bytes()
    assert b"<!--" not in data  # HuNavSim's WorldGenerator (tinyxml2) refuses worlds with comments
    root = etree.fromstring(data)
    assert root.tag == "sdf" and root.get("version") == "1.6"
    worlds = root.findall("world")
    assert len(worlds) == 1 and worlds[0].get("name") == hospital_export.world_file.stem
    models = {}
    for model in worlds[0].findall("model"):
        if model.get("name") == GROUND:
            continue
        # SDF 1.6 structure of a static box model: pose, link, collision and visual with a box geometry
        assert model.findtext("static") == "true"
        pose = _floats(model.findtext("pose"), 6)
        link = model.find("link")
        sizes = [_floats(link.find(f"{kind}/geometry/box/size").text, 3) for kind in ("collision", "visual")]
        assert sizes[0] == sizes[1] and min(sizes[0]) > 0
        assert model.get("name") not in models
        models[model.get("name")] = (pose, sizes[0])
    return models


def test_sdf_walls_are_the_world_files_walls(hospital_export):
    world = load_world("hospital")
    models = _models(hospital_export)
    walls = [v for k, v in models.items() if k.startswith("wall_")]
    expected = np.asarray(world.room_walls(), dtype=float)
    assert len(walls) == len(expected)
    for (pose, size), (x1, y1, x2, y2) in zip(walls, expected):
        x, y, _, _, _, yaw = pose
        half = size[0] / 2
        ends = ((x - half * math.cos(yaw), y - half * math.sin(yaw)), (x + half * math.cos(yaw), y + half * math.sin(yaw)))
        assert ends[0] == pytest.approx((x1, y1), abs=2e-4) and ends[1] == pytest.approx((x2, y2), abs=2e-4)
    # every door is a gap: no wall box crosses its centre
    segments = [LineString([(a, b), (c, d)]) for a, b, c, d in expected]
    for door in world.doors():
        assert min(s.distance(Point(door.position)) for s in segments) >= door.width / 2 - 0.03, door.name


def test_sdf_furniture_and_obstacles_are_boxes_on_their_footprints(hospital_export):
    world = load_world("hospital")
    models = _models(hospital_export)
    for entity in world.entities():
        pose, size = models[f"furniture_{entity.name}"]
        assert Point(pose[0], pose[1]).distance(entity.polygon.centroid) < 0.05
        assert size[0] * size[1] == pytest.approx(entity.polygon.minimum_rotated_rectangle.area, rel=1e-3)
    assert sum(1 for k in models if k.startswith("obstacle_")) == len(world.obstacles)


def _ground(hospital_export):
    """(xmin, ymin, xmax, ymax) the SDF's ground plane spans."""
    root = etree.fromstring(hospital_export.world_file.read_bytes())
    [model] = [m for m in root.find("world").findall("model") if m.get("name") == GROUND]
    x, y = _floats(model.findtext("pose"), 6)[:2]
    sizes = [_floats(model.find(f"link/{kind}/geometry/plane/size").text, 2) for kind in ("collision", "visual")]
    assert sizes[0] == sizes[1] and _floats(model.findtext("link/visual/geometry/plane/normal"), 3) == [0, 0, 1]
    sx, sy = sizes[0]
    return x - sx / 2, y - sy / 2, x + sx / 2, y + sy / 2


def _map(hospital_export):
    description = yaml.safe_load(hospital_export.map_yaml.read_text())
    assert description["mode"] == "trinary" and description["negate"] == 0
    assert description["origin"][2] == 0.0
    image = read_pgm((hospital_export.map_yaml.parent / description["image"]).read_bytes())
    return description, image[::-1] == 0  # row 0 the smallest y, as the world


def _box_polygon(pose, size, grow=0.0, grow_along=0.0):
    x, y, _, _, _, yaw = pose
    half_l, half_w = max(size[0] / 2, grow) + grow_along, max(size[1] / 2, grow)
    c, s = math.cos(yaw), math.sin(yaw)
    return Polygon([(x + a * c - b * s, y + a * s + b * c)
                    for a, b in ((-half_l, -half_w), (half_l, -half_w), (half_l, half_w), (-half_l, half_w))])


@pytest.mark.parametrize("which", ["hospital_export", "evacuation_export"])
def test_nav2_map_cells_are_the_worlds_boxes_not_inflated(which, request):
    exported = request.getfixturevalue(which)
    description, occupied = _map(exported)
    r = description["resolution"]
    x0, y0 = description["origin"][:2]
    models = _models(exported)

    def cells(polygon, test):
        """`occupied`-shaped mask of the cells whose centre passes `test` against the polygon."""
        mask = np.zeros(occupied.shape, dtype=bool)
        bx0, by0, bx1, by1 = polygon.bounds
        c0, c1 = max(int((bx0 - x0) // r) - 1, 0), min(int((bx1 - x0) // r) + 2, occupied.shape[1])
        r0, r1 = max(int((by0 - y0) // r) - 1, 0), min(int((by1 - y0) // r) + 2, occupied.shape[0])
        rows, cols = np.mgrid[r0:r1, c0:c1]
        mask[r0:r1, c0:c1] = test(polygon, x0 + (cols + 0.5) * r, y0 + (rows + 0.5) * r)
        return mask

    # every cell whose centre lies inside a box of the world file is occupied...
    inside = np.zeros(occupied.shape, dtype=bool)
    for pose, size in models.values():
        inside |= cells(_box_polygon(pose, size), shapely.contains_xy)
    assert occupied[inside].all()
    # ...and every occupied cell is one: a box grown by at most half a cell diagonal (so a 0.1 m wall is
    # a closed chain of cells), nothing inflated by a body radius
    grown = np.zeros(occupied.shape, dtype=bool)
    d = r * math.sqrt(0.5) + 1e-9
    for name, (pose, size) in models.items():
        grown |= cells(_box_polygon(pose, size, d, d if name.startswith("wall_") else 0.0), shapely.intersects_xy)
    assert not (occupied & ~grown).any()
    # the door openings stay free: a robot's planner can pass them
    world = load_world(yaml.safe_load(exported.agents_yaml.read_text())["hunav_loader"]["ros__parameters"]["map"])
    for door in world.doors():
        row, col = int((door.position[1] - y0) // r), int((door.position[0] - x0) // r)
        assert not occupied[row, col], door.name


@pytest.mark.parametrize("which", ["hospital_export", "evacuation_export"])
def test_world_and_map_span_one_extent_that_covers_every_goal_and_pose(which, request):
    exported = request.getfixturevalue(which)
    description, occupied = _map(exported)
    r = description["resolution"]
    x0, y0 = description["origin"][:2]
    extent = (x0, y0, x0 + occupied.shape[1] * r, y0 + occupied.shape[0] * r)
    assert _ground(exported) == pytest.approx(extent, abs=1e-6)
    params = yaml.safe_load(exported.agents_yaml.read_text())["hunav_loader"]["ros__parameters"]
    points = [(g["x"], g["y"]) for g in params["global_goals"].values()]
    points += [(params[a]["init_pose"]["x"], params[a]["init_pose"]["y"]) for a in params["agents"]]
    for x, y in points:
        assert extent[0] < x < extent[2] and extent[1] < y < extent[3], (x, y)
        # where an agent stands or heads for is free ground, outside the building too
        assert not occupied[int((y - y0) // r), int((x - x0) // r)], (x, y)


def test_evacuees_muster_points_outside_are_goals_inside_the_scene(evacuation_export):
    params = yaml.safe_load(evacuation_export.agents_yaml.read_text())["hunav_loader"]["ros__parameters"]
    world = load_world("office")
    building = world.outline()
    outside = [(g["x"], g["y"]) for g in params["global_goals"].values()
               if not building.intersects(Point(g["x"], g["y"]))]
    # one point of its own outside per evacuee, 2 m and more beyond the door
    assert len({params[a]["goals"][-1] for a in params["agents"]}) <= len(params["agents"])
    assert len(outside) >= len(params["agents"])
    ground = _ground(evacuation_export)
    assert all(ground[0] < x < ground[2] and ground[1] < y < ground[3] for x, y in outside)


def test_readme_says_where_the_world_and_map_go(hospital_export):
    readme = hospital_export.readme.read_text()
    assert "worlds/hospital.world" in readme and "maps/hospital.yaml" in readme
    assert "environment_name:=hospital" in readme
