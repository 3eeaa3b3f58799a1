"""Issue 30, one truth per quantity: the agents YAML and trees, the Gazebo world, the nav2 map, the ROS 2
bag and the Foxglove MCAP of one bundle say the same goal radius, agent radius, skin, behavior, map and
extent; where two maps must differ (GROVE's inflated planning grid), each says what it is. The
evacuation's trajectories validate in PedPy.

Two real runs: the hand-built hospital (queue, conversation, a Surprised agent, a robot) and a hand-built
office evacuation (a velocity field, muster points outside).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml
from helpers.handmade import build_evacuation_bundle
from lxml import etree

from grove_tui.exports.hunav import export_hunav
from grove_tui.exports.nav2_map import read_pgm
from grove_tui.exports.trajectories import export_trajectories
from grove_tui.navigation.grid import OccupancyGrid
from grove_tui.services.session import GroveSession

pytest.importorskip("rosbags")
pytest.importorskip("foxglove")
pytest.importorskip("mcap_protobuf")

from mcap.reader import make_reader  # noqa: E402
from mcap_protobuf.decoder import DecoderFactory  # noqa: E402
from rosbags.highlevel import AnyReader  # noqa: E402

from grove_tui.exports.foxglove import export_foxglove  # noqa: E402
from grove_tui.exports.rosbag import export_rosbag  # noqa: E402

F32 = 1e-6  # hunav_msgs and foxglove carry float32 sizes


def _exports(bundle: Path, out: Path) -> dict:
    hunav = export_hunav(bundle, out / "hunav")
    bag = export_rosbag(bundle, out / "bag")
    mcap = export_foxglove(bundle, out / "scene.mcap")
    params = yaml.safe_load(hunav.agents_yaml.read_text())["hunav_loader"]["ros__parameters"]
    messages: dict[str, list] = {}
    with AnyReader([bag.directory]) as reader:
        for connection, _t, raw in reader.messages():
            messages.setdefault(connection.topic, []).append(reader.deserialize(raw, connection.msgtype))
    fox: dict[str, list] = {}
    with mcap.mcap.open("rb") as handle:
        for _s, channel, _m, decoded in make_reader(handle, decoder_factories=[DecoderFactory()]).iter_decoded_messages():
            fox.setdefault(channel.topic, []).append(decoded)
    metadata = yaml.safe_load((bag.directory / "metadata.yaml").read_text())["rosbag2_bagfile_information"]
    return {"bundle": bundle, "hunav": hunav, "params": params, "bag": messages, "mcap": fox,
            "custom": metadata["custom_data"]}


SIMULATED_SECONDS = 8.0  # the `simulated` fixture's run of the hand-built hospital (tests/conftest.py)


@pytest.fixture(scope="module")
def hospital_run(simulated, tmp_path_factory) -> dict:
    return _exports(simulated, tmp_path_factory.mktemp("hospital_out"))


@pytest.fixture(scope="module")
def evacuation_run(tmp_path_factory) -> dict:
    bundle = build_evacuation_bundle(tmp_path_factory.mktemp("evacuation") / "bundle")
    GroveSession().simulate(bundle, 25.0)
    return _exports(bundle, tmp_path_factory.mktemp("evacuation_out"))


RUNS = [pytest.param("hospital_run", id="hospital"), pytest.param("evacuation_run", id="evacuation")]


def _agents(run) -> dict[int, dict]:
    params = run["params"]
    return {params[name]["id"]: params[name] for name in params["agents"]}


@pytest.mark.slow
@pytest.mark.parametrize("which", RUNS)
def test_goal_radius_is_one_value_in_agents_yaml_trees_bag_and_mcap(which, request):
    run = request.getfixturevalue(which)
    agents = _agents(run)
    for agent_id, entry in agents.items():
        radius = entry["goal_radius"]
        tree = run["hunav"].directory / f"{run['params']['yaml_base_name']}__agent_{agent_id}_bt.xml"
        tolerances = {float(el.get("tolerance")) for el in etree.fromstring(tree.read_bytes()).iter("GoTo")}
        assert tolerances <= {radius}, (agent_id, tolerances, radius)
    first = run["bag"]["/human_states"][0].agents
    assert first and all(abs(a.goal_radius - agents[a.id]["goal_radius"]) < F32 for a in first)
    markers = [m for m in run["bag"]["/scenario_markers"][0].markers if m.ns == "goals"]
    assert markers and all(abs(m.scale.x / 2 - agents[m.id]["goal_radius"]) < F32 for m in markers)
    routes = [e for e in run["mcap"]["/paths"][0].entities if e.id.startswith("routes/")]
    for entity in routes:
        radius = agents[int(entity.id.removeprefix("routes/agent"))]["goal_radius"]
        assert entity.spheres and all(abs(s.size.x / 2 - radius) < F32 for s in entity.spheres)


@pytest.mark.parametrize("which", RUNS)
def test_agent_radius_skin_behavior_and_cyclic_goals_match_between_agents_yaml_and_bag(which, request):
    run = request.getfixturevalue(which)
    agents = _agents(run)
    people = {p.id: p for msg in run["bag"]["/human_states"] for p in msg.agents}
    assert set(people) == set(agents)
    bodies = {m.id: m for msg in run["bag"]["/agent_markers"][:1] for m in msg.markers if m.ns == "people"}
    cylinders = {e.id: e.cylinders[0] for e in run["mcap"]["/people"][0].entities}
    numbers = {"Regular": 1, "Impassive": 2, "Surprised": 3, "Scared": 4, "Curious": 5, "Threatening": 6}
    for agent_id, entry in agents.items():
        person = people[agent_id]
        assert abs(person.radius - entry["radius"]) < F32 and abs(person.desired_velocity - entry["max_vel"]) < F32
        assert (person.skin, person.group_id, person.cyclic_goals) == (entry["skin"], entry["group_id"],
                                                                      entry["cyclic_goals"])
        block, behavior = entry["behavior"], person.behavior
        assert behavior.type == numbers[block["type"]] and behavior.configuration == block["configuration"]
        for key in ("duration", "vel", "dist", "goal_force_factor", "obstacle_force_factor", "social_force_factor",
                    "other_force_factor"):
            assert abs(getattr(behavior, key) - block[key]) < 1e-5, key
        assert behavior.once == block["once"]
        if agent_id in bodies:
            assert abs(bodies[agent_id].scale.x / 2 - entry["radius"]) < 1e-9
        if f"agent{agent_id}" in cylinders:
            assert abs(cylinders[f"agent{agent_id}"].size.x / 2 - entry["radius"]) < F32


@pytest.mark.parametrize("which", RUNS)
def test_bag_mcap_and_nav2_maps_are_one_static_map_over_the_worlds_extent(which, request):
    run = request.getfixturevalue(which)
    description = yaml.safe_load(run["hunav"].map_yaml.read_text())
    nav2 = read_pgm((run["hunav"].map_yaml.parent / description["image"]).read_bytes())[::-1] == 0
    [bag_map] = run["bag"]["/map"]
    assert (bag_map.info.width, bag_map.info.height) == (nav2.shape[1], nav2.shape[0])
    assert abs(bag_map.info.resolution - description["resolution"]) < F32
    assert (bag_map.info.origin.position.x, bag_map.info.origin.position.y) == tuple(description["origin"][:2])
    assert np.array_equal(bag_map.data.reshape(nav2.shape) == 100, nav2)
    assert set(np.unique(bag_map.data)) <= {0, 100}
    [fox_map] = run["mcap"]["/map"]
    cells = np.frombuffer(fox_map.data, dtype=np.uint8).reshape(nav2.shape)
    assert np.array_equal(cells.astype(bool), nav2)
    assert (fox_map.pose.position.x, fox_map.pose.position.y) == tuple(description["origin"][:2])
    # the Gazebo world's ground plane spans exactly the map
    root = etree.fromstring(run["hunav"].world_file.read_bytes())
    ground = next(m for m in root.iter("model") if m.get("name") == "ground_plane")
    cx, cy = map(float, ground.findtext("pose").split()[:2])
    sx, sy = map(float, ground.find("link/visual/geometry/plane/size").text.split())
    r = description["resolution"]
    assert (cx - sx / 2, cy - sy / 2) == pytest.approx(tuple(description["origin"][:2]), abs=1e-6)
    assert (sx, sy) == pytest.approx((nav2.shape[1] * r, nav2.shape[0] * r), abs=1e-6)


@pytest.mark.parametrize("which", RUNS)
def test_the_planning_grid_is_published_under_its_own_name_and_says_what_it_is(which, request):
    run = request.getfixturevalue(which)
    grid = OccupancyGrid.load(run["bundle"] / "grid.npz")
    [planning] = run["bag"]["/grove/planning_grid"]
    assert np.array_equal(planning.data.reshape(grid.height, grid.width) == 100, grid.occupied)
    assert f"inflated by {grid.inflation:g} m" in run["custom"]["grove.planning_grid"]
    assert "not inflated" in run["custom"]["grove.map"]
    assert run["custom"]["hunav_msgs.version"] == "2.0"
    [static] = run["bag"]["/map"]
    # the static map is not the inflated grid: inside the building it blocks far fewer cells
    assert (static.data == 100).sum() < (planning.data == 100).sum()


def test_evacuation_trajectories_validate_in_pedpy_and_every_goal_is_inside_world_and_map(evacuation_run, tmp_path):
    pedpy = pytest.importorskip("pedpy")
    paths = export_trajectories(evacuation_run["bundle"], tmp_path)
    sqlite = next(p for p in paths if p.suffix == ".sqlite")
    traj = pedpy.load_trajectory_from_jupedsim_sqlite(trajectory_file=sqlite)
    walkable = pedpy.load_walkable_area_from_jupedsim_sqlite(trajectory_file=sqlite)
    events = [line for line in (evacuation_run["bundle"] / "events.jsonl").read_text().splitlines() if '"evacuated"' in line]
    assert events, "nobody got out: the check would prove nothing"
    assert pedpy.is_trajectory_valid(traj_data=traj, walkable_area=walkable)
    [bag_map] = evacuation_run["bag"]["/map"]
    x0, y0, r = bag_map.info.origin.position.x, bag_map.info.origin.position.y, bag_map.info.resolution
    x1, y1 = x0 + bag_map.info.width * r, y0 + bag_map.info.height * r
    goals = evacuation_run["params"]["global_goals"].values()
    assert all(x0 < g["x"] < x1 and y0 < g["y"] < y1 for g in goals)
