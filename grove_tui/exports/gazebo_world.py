"""A bundle's scene as a Gazebo world (SDF 1.6) for HuNavSim's Gazebo wrapper.

hunav_gazebo_wrapper's launch loads `worlds/<environment_name>.world` as the *base world*
(launch/simulation.launch.py, `world_file`), and its WorldGenerator (src/WorldGenerator.cpp@ab3786e,
humble) opens it with tinyxml2, walks `sdf > world`, inserts a `physics` block if there is none and
adds the agents as actors with the HuNav plugin. It refuses files with XML comments ("check that the
world file does not contain any comment"), so this file has none.

Content, all static models (exports/scene.py gives every size, so the nav2 map and the bags agree):
- a ground plane whose visual spans the scene's extent: the building, every goal and every muster
  point outside (a plane collision is infinite in Gazebo; the visual shows where the scene ends);
- one box per building wall segment, furniture piece and obstacle (`scene_boxes`);
- a sun, included from Gazebo's model database as every HuNavSim world does.
"""

from __future__ import annotations

from grove_tui.exports.scene import Scene, SceneBox

GROUND_MATERIAL = "Gazebo/Grey"

_ATTRIBUTE_ESCAPES = str.maketrans({"&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;"})


def quoteattr(value: str) -> str:
    """An SDF attribute value in double quotes (names come from the world file; escape what XML needs).
    Not xml.sax.saxutils: XML libraries belong to grove_tui/bt/format/ (tests/bt/format/test_bt_ownership.py)."""
    return '"' + str(value).translate(_ATTRIBUTE_ESCAPES) + '"'


def _f(value: float) -> str:
    return f"{value:.4f}".rstrip("0").rstrip(".") if value != 0 else "0"


def _box_model(box: SceneBox) -> list[str]:
    geometry = f"<geometry><box><size>{_f(box.length)} {_f(box.width)} {_f(box.height)}</size></box></geometry>"
    return [
        f"    <model name={quoteattr(box.name)}>",
        "      <static>true</static>",
        f"      <pose>{_f(box.x)} {_f(box.y)} {_f(box.height / 2)} 0 0 {_f(box.yaw)}</pose>",
        "      <link name=\"link\">",
        f"        <collision name=\"collision\">{geometry}</collision>",
        f"        <visual name=\"visual\">{geometry}</visual>",
        "      </link>",
        "    </model>",
    ]


def ground_plane(scene: Scene) -> tuple[float, float, float, float]:
    """(centre x, centre y, size x, size y) of the ground plane: exactly the scene's extent."""
    x0, y0, x1, y1 = scene.extent
    return (x0 + x1) / 2, (y0 + y1) / 2, x1 - x0, y1 - y0


def _ground_model(scene: Scene) -> list[str]:
    cx, cy, sx, sy = ground_plane(scene)
    plane = f"<geometry><plane><normal>0 0 1</normal><size>{_f(sx)} {_f(sy)}</size></plane></geometry>"
    material = (f"<material><script><uri>file://media/materials/scripts/gazebo.material</uri>"
                f"<name>{GROUND_MATERIAL}</name></script></material>")
    return [
        "    <model name=\"ground_plane\">",
        "      <static>true</static>",
        f"      <pose>{_f(cx)} {_f(cy)} 0 0 0 0</pose>",
        "      <link name=\"link\">",
        f"        <collision name=\"collision\">{plane}</collision>",
        f"        <visual name=\"visual\">{plane}{material}</visual>",
        "      </link>",
        "    </model>",
    ]


def world_sdf(scene: Scene) -> str:
    """The SDF text of the scene (see the module docstring)."""
    lines = ['<?xml version="1.0" ?>', '<sdf version="1.6">', f"  <world name={quoteattr(scene.world.name)}>",
             "    <include><uri>model://sun</uri></include>"]
    lines += _ground_model(scene)
    for box in scene.boxes:
        lines += _box_model(box)
    lines += ["  </world>", "</sdf>", ""]
    return "\n".join(lines)
