"""A small hand-built hospital bundle (five agents: a visitor, a two-person queue, a conversing pair),
written the way post-processing writes bundles, for tests of what consumes bundles."""

from __future__ import annotations

from pathlib import Path

from lxml import etree

from grove_tui.navigation.grid import build_grid
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.scenario.model import AgentSpec, RobotSpec, Scenario
from grove_tui.bt.format.xml import read_tree, write_tree
from grove_tui.generation.waypoints import plan_waypoints
from grove_tui.world import load_world


def inject_waypoints(xml: str, start, planner, start_label: str = "start") -> str:
    """`plan_waypoints` on a tree written as text: read and written back by the codec."""
    return write_tree(plan_waypoints(read_tree(xml), start, planner, start_label))


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


def build_evacuation_bundle(bundle: Path, world_name: str = "office", zone: str = "reception",
                            exit_name: str = "main_entrance", people: int = 8) -> Path:
    """`people` in `zone` evacuating through `exit_name` along one velocity field, written the way
    post-processing writes an emergency bundle (FollowVelocityField with the exit point, the field's
    .npz, the planned route as goals); a robot crosses the zone."""
    from grove_tui.navigation.velocity_field import build_velocity_field

    world = load_world(world_name)
    grid = build_grid(world, 0.1)
    planner = ThetaStarPlanner(grid)
    exit_point = tuple(map(float, world.roi(exit_name).point))
    x0, y0, x1, y1 = world.zone(zone).polygon.bounds
    starts = []
    k = 0
    while len(starts) < people:
        k += 1
        x = x0 + 1.0 + (k * 0.754877666) % 1.0 * (x1 - x0 - 2.0)  # a low-discrepancy spread over the zone
        y = y0 + 1.0 + (k * 0.569840291) % 1.0 * (y1 - y0 - 2.0)
        if grid.is_free(x, y) and all((x - a) ** 2 + (y - b) ** 2 > 0.8 for a, b in starts):
            starts.append((round(x, 2), round(y, 2)))
    route = planner.plan(starts[0], exit_point)
    field = build_velocity_field(grid, route, exit_point, planner=planner)
    (bundle / "trees").mkdir(parents=True, exist_ok=True)
    (bundle / "fields").mkdir(parents=True, exist_ok=True)
    field.save(bundle / "fields" / "group_0.npz")
    specs = []
    for agent_id, start in enumerate(starts, start=1):
        body = (f'<FollowVelocityField exit="{exit_name}" field="group_0" x="{exit_point[0]}" y="{exit_point[1]}"/>')
        (bundle / "trees" / f"agent_{agent_id}.xml").write_text(_tree(agent_id, body))
        goals = tuple(tuple(map(float, p)) for p in planner.plan(start, exit_point)[1:])
        specs.append(AgentSpec(id=agent_id, group=0, start=start, goals=goals, zone=zone,
                               tree=f"trees/agent_{agent_id}.xml", max_vel=1.3))
    robot_start, robot_goal = world.zone(zone).anchor, world.zone("main_corridor").anchor
    robot_path = tuple(tuple(map(float, p)) for p in planner.plan(robot_start, robot_goal))
    Scenario(world=world_name, preset="emergency", prompt=f"hand-built: {people} people leave {zone}", seed=5,
             models={}, agents=tuple(specs), robot=RobotSpec(start=robot_start, goal=robot_goal, path=robot_path),
             fields={"group_0": "fields/group_0.npz"}).save(bundle / "scenario.yaml")
    grid.save(bundle / "grid.npz")
    return bundle
