"""A small HuNavSim 2.0 scenario on disk (agents YAML and one tree per agent), for the import's tests and fuzzing.

The map is not a GROVE world, so importing builds an open floor: no world file needs to exist.
"""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

import yaml

BASE = "agents_lab"
TREE = """<root BTCPP_format="4" main_tree_to_execute="DefaultTree">
  <BehaviorTree ID="DefaultTree">
    <Fallback>
      <Inverter><RunOnce><SetGoal agent_id="{{id}}" goal_id="{goal}"/></RunOnce></Inverter>
      <Sequence><Inverter><IsGoalReached agent_id="{{id}}"/></Inverter><RegularNav agent_id="{{id}}" time_step="{{dt}}"/></Sequence>
    </Fallback>
  </BehaviorTree>
</root>
"""

PARAMS: dict[str, Any] = {
    "yaml_base_name": BASE, "simulator": "Gazebo Classic", "map": "lab", "publish_people": True,
    "global_goals": {1: {"x": 1.0, "y": 1.0}, 2: {"x": 6.0, "y": 1.5}},
    "agents": ["agent1", "agent2"],
    "agent1": {"id": 1, "group_id": -1, "skin": 0, "max_vel": 1.2, "radius": 0.4, "goal_radius": 0.3,
               "cyclic_goals": True, "init_pose": {"x": 0.5, "y": 4.0, "z": 1.25, "h": 0.0},
               "behavior": {"type": "Regular", "configuration": 0}, "goals": [1, 2]},
    "agent2": {"id": 2, "group_id": 1, "skin": 1, "max_vel": 1.0, "radius": 0.4, "goal_radius": 0.3,
               "cyclic_goals": True, "init_pose": {"x": 3.0, "y": 6.0, "z": 1.25, "h": 0.0},
               "behavior": {"type": "Surprised", "dist": 2.0, "duration": 20.0, "once": True, "configuration": 0},
               "goals": [2]},
}


def params() -> dict[str, Any]:
    """A fresh copy of the valid parameters, to change one value at a time."""
    return copy.deepcopy(PARAMS)


def document(values: dict[str, Any]) -> str:
    return yaml.safe_dump({"hunav_loader": {"ros__parameters": values}}, sort_keys=False)


def write_scenario(folder: Path, values: dict[str, Any] | None = None, text: str | bytes | None = None,
                   tree_ids: range | list[int] = (1, 2)) -> Path:  # type: ignore[assignment]
    """agents_lab.yaml (from `values`, or raw `text`) and agents_lab__agent_<id>_bt.xml per id; the YAML's path."""
    folder.mkdir(parents=True, exist_ok=True)
    for agent_id in tree_ids:
        (folder / f"{BASE}__agent_{agent_id}_bt.xml").write_text(TREE.format(goal=1 if agent_id % 2 else 2))
    path = folder / f"{BASE}.yaml"
    data = text if text is not None else document(values if values is not None else params())
    path.write_bytes(data if isinstance(data, bytes) else data.encode("utf-8", "surrogatepass"))
    return path
