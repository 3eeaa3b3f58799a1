"""The HuNavSim export's world: a Gazebo SDF whose walls are the world file's walls (door gaps open,
furniture as boxes), and a nav2 map whose occupied cells are the occupancy grid's."""

from __future__ import annotations

import math

import numpy as np
import pytest
import yaml
from helpers.handmade import build_hospital_bundle
from lxml import etree
from shapely.geometry import LineString, Point

from grove_tui.exports.hunav import export_hunav
from grove_tui.exports.nav2_map import read_pgm
from grove_tui.navigation.grid import build_grid
from grove_tui.world import load_world


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    bundle = build_hospital_bundle(tmp_path_factory.mktemp("bundle"))
    return export_hunav(bundle, tmp_path_factory.mktemp("out") / "hunav")


def _floats(text, n):
    values = [float(v) for v in text.split()]
    assert len(values) == n and all(math.isfinite(v) for v in values), text
    return values


def _models(exported):
    data = exported.world_file.read_bytes()
    assert b"<!--" not in data  # HuNavSim's WorldGenerator (tinyxml2) refuses worlds with comments
    root = etree.fromstring(data)
    assert root.tag == "sdf" and root.get("version") == "1.6"
    worlds = root.findall("world")
    assert len(worlds) == 1 and worlds[0].get("name") == "hospital"
    models = {}
    for model in worlds[0].findall("model"):
        # SDF 1.6 structure of a static box model: pose, link, collision and visual with a box geometry
        assert model.findtext("static") == "true"
        pose = _floats(model.findtext("pose"), 6)
        link = model.find("link")
        sizes = [_floats(link.find(f"{kind}/geometry/box/size").text, 3) for kind in ("collision", "visual")]
        assert sizes[0] == sizes[1] and min(sizes[0]) > 0
        assert model.get("name") not in models
        models[model.get("name")] = (pose, sizes[0])
    return models


def test_sdf_walls_are_the_world_files_walls(exported):
    world = load_world("hospital")
    models = _models(exported)
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


def test_sdf_furniture_and_obstacles_are_boxes_on_their_footprints(exported):
    world = load_world("hospital")
    models = _models(exported)
    for entity in world.entities():
        pose, size = models[f"furniture_{entity.name}"]
        assert Point(pose[0], pose[1]).distance(entity.polygon.centroid) < 0.05
        assert size[0] * size[1] == pytest.approx(entity.polygon.minimum_rotated_rectangle.area, rel=1e-3)
    assert sum(1 for k in models if k.startswith("obstacle_")) == len(world.obstacles)


def test_nav2_map_cells_are_the_occupancy_grid(exported):
    world = load_world("hospital")
    description = yaml.safe_load(exported.map_yaml.read_text())
    assert description["mode"] == "trinary" and description["negate"] == 0
    image = read_pgm((exported.map_yaml.parent / description["image"]).read_bytes())
    grid = build_grid(world, description["resolution"], inflation=0.0)
    assert image.shape == grid.occupied.shape
    assert np.array_equal(image[::-1] == 0, grid.occupied)
    assert set(np.unique(image)) <= {0, 254}
    assert description["origin"][:2] == pytest.approx(list(grid.origin))
    # the origin is the lower-left corner: a free cell's centre maps back to a free world point
    row, col = map(int, np.argwhere(~grid.occupied)[0])
    x = description["origin"][0] + (col + 0.5) * description["resolution"]
    y = description["origin"][1] + (row + 0.5) * description["resolution"]
    assert grid.is_free(x, y)


def test_readme_says_where_the_world_and_map_go(exported):
    readme = exported.readme.read_text()
    assert "worlds/hospital.world" in readme and "maps/hospital.yaml" in readme
    assert "environment_name:=hospital" in readme
