"""A small hand-built hospital bundle (five agents: a visitor, a two-person queue, a conversing pair),
written the way post-processing writes bundles, for tests of what consumes bundles."""

from __future__ import annotations

from pathlib import Path

from lxml import etree

from grove_tui.navigation.grid import build_grid
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.scenario.model import AgentSpec, RobotSpec, Scenario
from grove_tui.generation.waypoints import inject_waypoints
from grove_tui.world import load_world


def _tree(agent_id: int, body: str) -> str:
    return (f'<root BTCPP_format="4" main_tree_to_execute="agent_{agent_id}">'
            f'<BehaviorTree ID="agent_{agent_id}">{body}</BehaviorTree></root>')


def build_hospital_bundle(bundle: Path) -> Path:
    world = load_world("hospital")
    grid = build_grid(world, 0.1)
    planner = ThetaStarPlanner(grid)
    counter = world.find("pharmacy_counter").interaction_point
    table = world.find("cafeteria_table_1").interaction_point
    (bundle / "trees").mkdir(parents=True, exist_ok=True)
    converse = (f'<Sequence><JoinGroup group_id="1" members="4,5"/><Converse target="cafeteria_table_1" '
                f'x="{table[0]}" y="{table[1]}" members="4,5" duration="30"/></Sequence>')
    queue = (f'<Queue service_point="pharmacy_counter" x="{counter[0]}" y="{counter[1]}" spacing="0.6" '
             f'service_time="8"/>')
    bodies = {
        1: f'<Sequence><GoTo target="pharmacy_counter" x="{counter[0]}" y="{counter[1]}" goal_id="7"/>'
           f'<Wait duration="4"/></Sequence>',
        2: f'<Sequence><GoTo target="pharmacy" x="{counter[0] - 1.0}" y="{counter[1] + 2.0}"/>{queue}</Sequence>',
        3: queue,
        4: converse,
        5: converse,
    }
    starts = {1: (30.0, 5.0), 2: (31.0, 6.0), 3: (32.0, 5.0), 4: (33.0, 6.0), 5: (33.5, 5.0)}
    specs = []
    for agent_id, body in bodies.items():
        xml = inject_waypoints(_tree(agent_id, body), starts[agent_id], planner)
        (bundle / "trees" / f"agent_{agent_id}.xml").write_text(xml)
        goals = []
        for el in etree.fromstring(xml.encode()).iter():
            if el.tag in ("GoTo", "Converse"):
                wps = [tuple(map(float, p.split(","))) for p in (el.get("waypoints") or "").split(";") if p]
                goals += wps + [(float(el.get("x")), float(el.get("y")))]
            if el.tag == "Queue":
                goals.append((float(el.get("x")), float(el.get("y"))))
        specs.append(AgentSpec(id=agent_id, group=1 if agent_id in (4, 5) else -1, start=starts[agent_id],
                               goals=tuple(goals), zone="pharmacy" if agent_id < 4 else "cafeteria",
                               tree=f"trees/agent_{agent_id}.xml",
                               behavior="Surprised" if agent_id == 1 else "Regular"))
    robot_path = tuple(tuple(map(float, p)) for p in planner.plan((28.0, 4.0), (45.0, 5.0)))
    Scenario(world="hospital", preset="normal", prompt="hand-built", seed=3, models={}, agents=tuple(specs),
             robot=RobotSpec(start=(28.0, 4.0), goal=(45.0, 5.0), path=robot_path)).save(bundle / "scenario.yaml")
    grid.save(bundle / "grid.npz")
    return bundle
