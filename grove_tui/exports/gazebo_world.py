"""The GROVE world as a Gazebo world (SDF 1.6) for HuNavSim's Gazebo wrapper.

hunav_gazebo_wrapper's launch loads `worlds/<environment_name>.world` as the *base world*
(launch/simulation.launch.py, `world_file`), and its WorldGenerator (src/WorldGenerator.cpp@ab3786e,
humble) opens it with tinyxml2, walks `sdf > world`, inserts a `physics` block if there is none and
adds the agents as actors with the HuNav plugin. It refuses files with XML comments ("check that the
world file does not contain any comment"), so this file has none.

Content, all static models:
- one box per building wall segment (zone boundaries with the door openings cut out,
  World.room_walls()), 0.1 m thick (twice the world's WALL_HALF_THICKNESS), WALL_HEIGHT tall;
- one box per entity (furniture) and obstacle: the footprint's minimum rotated rectangle, as tall as
  its type suggests (FURNITURE_HEIGHT);
- a ground plane and a sun, included from Gazebo's model database as every HuNavSim world does.
"""

from __future__ import annotations

import math
import numpy as np

WALL_HEIGHT = 2.5
WALL_THICKNESS = 0.1
FURNITURE_HEIGHT = {"table": 0.75, "desk": 0.75, "counter": 1.05, "reception_desk": 1.05, "bed": 0.6,
                    "sofa": 0.8, "chair": 0.9, "vending_machine": 1.8, "coffee_machine": 1.2, "shelf": 1.8}
DEFAULT_FURNITURE_HEIGHT = 1.0
OBSTACLE_HEIGHT = WALL_HEIGHT


_ATTRIBUTE_ESCAPES = str.maketrans({"&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;"})


def quoteattr(value: str) -> str:
    """An SDF attribute value in double quotes (names come from the world file; escape what XML needs).
    Not xml.sax.saxutils: XML libraries belong to grove_tui/bt/ (tests/bt/test_bt_ownership.py)."""
    return '"' + str(value).translate(_ATTRIBUTE_ESCAPES) + '"'


def _f(value: float) -> str:
    return f"{value:.4f}".rstrip("0").rstrip(".") if value != 0 else "0"


def _box_model(name: str, x: float, y: float, yaw: float, sx: float, sy: float, sz: float) -> list[str]:
    size = f"{_f(sx)} {_f(sy)} {_f(sz)}"
    geometry = f"<geometry><box><size>{size}</size></box></geometry>"
    return [
        f"    <model name={quoteattr(name)}>",
        "      <static>true</static>",
        f"      <pose>{_f(x)} {_f(y)} {_f(sz / 2)} 0 0 {_f(yaw)}</pose>",
        "      <link name=\"link\">",
        f"        <collision name=\"collision\">{geometry}</collision>",
        f"        <visual name=\"visual\">{geometry}</visual>",
        "      </link>",
        "    </model>",
    ]


def wall_boxes(world) -> list[tuple[float, float, float, float]]:
    """(centre x, centre y, yaw, length) of each building wall segment."""
    boxes = []
    for x1, y1, x2, y2 in np.asarray(world.room_walls(), dtype=float):
        length = math.hypot(x2 - x1, y2 - y1)
        boxes.append(((x1 + x2) / 2, (y1 + y2) / 2, math.atan2(y2 - y1, x2 - x1), length))
    return boxes


def _rectangle(polygon) -> tuple[float, float, float, float, float]:
    """(centre x, centre y, yaw, side along yaw, side across) of a footprint's minimum rotated rectangle."""
    corners = list(polygon.minimum_rotated_rectangle.exterior.coords)[:4]
    (ax, ay), (bx, by), (cx, cy) = corners[0], corners[1], corners[2]
    along = math.hypot(bx - ax, by - ay)
    across = math.hypot(cx - bx, cy - by)
    centre = polygon.minimum_rotated_rectangle.centroid
    return centre.x, centre.y, math.atan2(by - ay, bx - ax), along, across


def world_sdf(world) -> str:
    """The SDF text of `world` (see the module docstring)."""
    lines = ['<?xml version="1.0" ?>', '<sdf version="1.6">', f"  <world name={quoteattr(world.name)}>",
             "    <include><uri>model://ground_plane</uri></include>",
             "    <include><uri>model://sun</uri></include>"]
    for k, (x, y, yaw, length) in enumerate(wall_boxes(world)):
        lines += _box_model(f"wall_{k}", x, y, yaw, length, WALL_THICKNESS, WALL_HEIGHT)
    for entity in world.entities():
        x, y, yaw, sx, sy = _rectangle(entity.polygon)
        height = FURNITURE_HEIGHT.get(entity.type, DEFAULT_FURNITURE_HEIGHT)
        lines += _box_model(f"furniture_{entity.name}", x, y, yaw, sx, sy, height)
    for obstacle in world.obstacles:
        x, y, yaw, sx, sy = _rectangle(obstacle.polygon)
        lines += _box_model(f"obstacle_{obstacle.name}", x, y, yaw, sx, sy, OBSTACLE_HEIGHT)
    lines += ["  </world>", "</sdf>", ""]
    return "\n".join(lines)
