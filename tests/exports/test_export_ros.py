"""ROS 2 bag and Foxglove MCAP exports of a simulated bundle, read back with rosbags and mcap.

The bundle is the hand-built hospital scenario simulated for real (numba SFM, behavior trees); a
second bundle is derived from it with people leaving part-way, as in an evacuation.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import math
import shutil
import sys
from collections import defaultdict
from pathlib import Path

import numpy as np
import pytest
import yaml
from click.testing import CliRunner
from helpers.handmade import build_hospital_bundle

pytest.importorskip("rosbags")
pytest.importorskip("foxglove")
pytest.importorskip("mcap_protobuf")

from mcap.reader import make_reader  # noqa: E402
from mcap_protobuf.decoder import DecoderFactory  # noqa: E402
from rosbags.highlevel import AnyReader  # noqa: E402
from rosbags.interfaces import QosDurability  # noqa: E402
from rosbags.rosbag2 import Reader  # noqa: E402

from grove_tui.cli import main  # noqa: E402
from grove_tui.errors import GroveError, MissingExtraError  # noqa: E402
from grove_tui.exports import foxglove as fox  # noqa: E402
from grove_tui.exports import rosbag  # noqa: E402
from grove_tui.exports.hunav import export_hunav  # noqa: E402
from grove_tui.exports.nav2_map import read_pgm  # noqa: E402
from grove_tui.exports.rosbag import HUNAV_MSGS, export_rosbag, ros_typestore  # noqa: E402
from grove_tui.navigation.grid import OccupancyGrid  # noqa: E402
from grove_tui.scenario.model import Scenario  # noqa: E402
from grove_tui.services.jobs import read_jobs  # noqa: E402
from grove_tui.world import load_world  # noqa: E402

SIMULATED_SECONDS = 8.0  # the `simulated` fixture's run (tests/conftest.py)
LEAVERS = (2, 5)  # people who leave the derived bundle half-way


@pytest.fixture(scope="module")
def leaving(simulated, tmp_path_factory) -> Path:
    """The same run with agents 2 and 5 gone from the second half of the frames (and an event each)."""
    bundle = tmp_path_factory.mktemp("leaving") / "bundle"
    shutil.copytree(simulated, bundle)
    lines = (simulated / "trajectories.csv").read_text().splitlines()
    rows = np.loadtxt(lines[1:], delimiter=",", ndmin=2)
    half = np.median(np.unique(rows[:, 0]))
    keep = [line for line, row in zip(lines[1:], rows) if not (row[0] > half and int(row[2]) in LEAVERS)]
    (bundle / "trajectories.csv").write_text("\n".join([lines[0], *keep]) + "\n")
    t_half = float(rows[rows[:, 0] > half][0, 1])
    with (bundle / "events.jsonl").open("a") as handle:
        for agent in LEAVERS:
            handle.write(json.dumps({"t": t_half, "agent_id": agent, "kind": "evacuated", "detail": "exit"}) + "\n")
    return bundle


def csv_frames(bundle: Path) -> list[dict]:
    """Independent of the exporters' reader: the whole CSV at once, grouped by frame."""
    rows = np.loadtxt(bundle / "trajectories.csv", delimiter=",", skiprows=1, ndmin=2)
    frames = []
    for frame in np.unique(rows[:, 0]):
        chunk = rows[rows[:, 0] == frame]
        people = chunk[chunk[:, 2] != 0]
        robot = chunk[chunk[:, 2] == 0]
        frames.append({"t": chunk[0, 1], "ids": people[:, 2].astype(int).tolist(), "xy": people[:, 3:5],
                       "v": people[:, 5:7], "yaw": people[:, 7], "robot": robot[0, 3:8] if len(robot) else None})
    return frames


def event_count(bundle: Path) -> int:
    return sum(1 for line in (bundle / "events.jsonl").read_text().splitlines() if line.strip())


def git_blob_id(data: bytes) -> str:
    return hashlib.sha1(b"blob %d\0" % len(data) + data).hexdigest()


def sections(msgdef: str) -> dict[str, str]:
    parts = msgdef.split("=" * 80 + "\n")
    out = {"": parts[0]}
    for part in parts[1:]:
        head, _, body = part.partition("\n")
        out[head.removeprefix("MSG: ")] = body
    return out


def read_bag(path: Path) -> tuple[dict[str, list], dict[str, list[int]], list]:
    """Messages per topic decoded by a reader that knows no hunav_msgs (the bag must carry them)."""
    messages: dict[str, list] = defaultdict(list)
    times: dict[str, list[int]] = defaultdict(list)
    with AnyReader([path]) as reader:
        connections = list(reader.connections)
        for connection, timestamp, raw in reader.messages():
            messages[connection.topic].append(reader.deserialize(raw, connection.msgtype))
            times[connection.topic].append(timestamp)
    return messages, times, connections


def test_shipped_hunav_msgs_are_huNavSims_files_of_both_versions():
    assert set(HUNAV_MSGS) == {"1.0", "2.0"} and rosbag.DEFAULT_HUNAV_MSGS == "2.0"
    for msgs in HUNAV_MSGS.values():
        assert sorted(p.name for p in msgs.folder.iterdir()) == sorted(msgs.blobs)
        for name, blob in msgs.blobs.items():
            assert git_blob_id((msgs.folder / name).read_bytes()) == blob, (msgs.version, name)
    assert "afa974340901e244ce15a97e8ebc37c0699a3e6f" in HUNAV_MSGS["1.0"].source
    # 1.0: the behavior is a number on the agent; 2.0: a nested AgentBehavior with HuNavSim's parameters
    assert "uint8 behavior\n" in HUNAV_MSGS["1.0"].text("Agent.msg")
    assert "hunav_msgs/AgentBehavior behavior" in HUNAV_MSGS["2.0"].text("Agent.msg")
    for key in ("configuration", "duration", "once", "vel", "dist", "social_force_factor", "goal_force_factor",
                "obstacle_force_factor", "other_force_factor"):
        assert f" {key}" in HUNAV_MSGS["2.0"].text("AgentBehavior.msg"), key


def stored_definitions(connection) -> dict[str, str]:
    """The hunav_msgs parts of a bag connection's stored definition, by type (main type first)."""
    parts = sections(connection.msgdef.data)
    main = connection.msgtype.replace("/msg/", "/")
    return {main if not name else name: text for name, text in parts.items()
            if (name or main).startswith("hunav_msgs/")}


def assert_definitions_are_the_msg_files(connection, version: str) -> None:
    shipped = {f"hunav_msgs/{Path(name).stem}": HUNAV_MSGS[version].text(name) for name in HUNAV_MSGS[version].blobs}
    stored = stored_definitions(connection)
    assert stored, connection.topic
    for name, text in stored.items():
        assert text.rstrip("\n") == shipped[name].rstrip("\n"), (version, name)
    # and the reader's types, built from what the bag stores, have exactly the .msg files' fields
    from rosbags.typesys import get_types_from_msg
    for name, text in stored.items():
        mine = get_types_from_msg(text, name.replace("/", "/msg/"))
        theirs = get_types_from_msg(shipped[name], name.replace("/", "/msg/"))
        assert mine == theirs, name


@pytest.mark.parametrize("storage", ["mcap", "sqlite3"])
def test_rosbag_reads_back_with_the_run_in_it(simulated, tmp_path, storage):
    result = export_rosbag(simulated, tmp_path / "bag", storage=storage)
    frames = csv_frames(simulated)
    messages, times, connections = read_bag(result.directory)
    with_robot = sum(f["robot"] is not None for f in frames)
    counts = {topic: len(items) for topic, items in messages.items()}
    assert counts == result.counts == {
        "/human_states": len(frames), "/agent_markers": len(frames), "/robot_states": with_robot,
        "/tf": with_robot, "/events": event_count(simulated), "/map": 1, "/grove/planning_grid": 1,
        "/scenario_markers": 1, "/plan": 1, "/goal_pose": 1}
    for topic in ("/human_states", "/agent_markers", "/robot_states", "/tf"):
        assert all(b > a for a, b in zip(times[topic], times[topic][1:])), topic

    for frame, msg, ns in zip(frames, messages["/human_states"], times["/human_states"]):
        assert ns == round(frame["t"] * 1e9)
        assert (msg.header.stamp.sec, msg.header.stamp.nanosec) == divmod(ns, 10**9)
        assert msg.header.frame_id == "map"
        assert [a.id for a in msg.agents] == frame["ids"]
        xy = np.array([[a.position.position.x, a.position.position.y] for a in msg.agents])
        assert np.array_equal(xy, frame["xy"])  # float64 on both sides: exactly the CSV's numbers
        v = np.array([[a.velocity.linear.x, a.velocity.linear.y] for a in msg.agents])
        assert np.array_equal(v, frame["v"])
        assert np.allclose([a.yaw for a in msg.agents], frame["yaw"], atol=1e-6)
        heading = np.array([2 * math.atan2(a.position.orientation.z, a.position.orientation.w) for a in msg.agents])
        assert np.allclose(np.angle(np.exp(1j * (heading - frame["yaw"]))), 0, atol=1e-9)
        assert all(a.type == 1 and a.name == f"agent{a.id}" for a in msg.agents)

    scenario = Scenario.load(simulated / "scenario.yaml")
    agent1 = messages["/human_states"][0].agents[0]
    assert agent1.behavior.type == 3  # the hand-built agent 1 is Surprised: BEH_SURPRISED (hunav_msgs 2.0)
    goal = scenario.agents[0].goals[-1]
    assert [(g.position.x, g.position.y) for g in agent1.goals] == [goal]

    robot_frames = [f for f in frames if f["robot"] is not None]
    for frame, state, tf in zip(robot_frames, messages["/robot_states"], messages["/tf"]):
        x, y, vx, vy, yaw = frame["robot"]
        assert (state.type, state.position.position.x, state.position.position.y) == (2, x, y)
        assert (state.velocity.linear.x, state.velocity.linear.y) == (vx, vy)
        [transform] = tf.transforms
        assert (transform.header.frame_id, transform.child_frame_id) == ("map", "base_link")
        assert (transform.transform.translation.x, transform.transform.translation.y) == (x, y)

    for frame, array in zip(frames, messages["/agent_markers"]):
        first, *bodies = array.markers
        assert first.action == 3  # DELETEALL, so people who left disappear
        people = [m for m in bodies if m.ns == "people"]
        assert [m.id for m in people] == frame["ids"]
        assert np.array_equal([[m.pose.position.x, m.pose.position.y] for m in people], frame["xy"])

    grid = OccupancyGrid.load(simulated / "grid.npz")
    [planning] = messages["/grove/planning_grid"]  # GROVE's own grid, under its own name
    assert (planning.info.width, planning.info.height) == (grid.width, grid.height)
    assert math.isclose(planning.info.resolution, grid.resolution, rel_tol=1e-6)
    assert np.array_equal(planning.data.reshape(grid.height, grid.width) == 100, grid.occupied)
    [plan] = messages["/plan"]
    assert [(p.pose.position.x, p.pose.position.y) for p in plan.poses] == list(scenario.robot.path)
    scene = messages["/scenario_markers"][0].markers
    assert {m.ns for m in scene} >= {"goals", "routes", "waypoints", "robot_goal"}
    assert [json.loads(s.data)["kind"] for s in messages["/events"]] == \
        [json.loads(line)["kind"] for line in (simulated / "events.jsonl").read_text().splitlines() if line]

    by_topic = {c.topic: c for c in connections}
    assert set(stored_definitions(by_topic["/human_states"])) == {
        "hunav_msgs/Agents", "hunav_msgs/Agent", "hunav_msgs/AgentBehavior"}
    assert_definitions_are_the_msg_files(by_topic["/human_states"], "2.0")
    assert_definitions_are_the_msg_files(by_topic["/robot_states"], "2.0")
    durability = {topic: c.ext.offered_qos_profiles[0].durability for topic, c in by_topic.items()}
    assert durability["/map"] == durability["/scenario_markers"] == durability["/plan"] == \
        QosDurability.TRANSIENT_LOCAL
    assert durability["/human_states"] == QosDurability.VOLATILE


@pytest.mark.parametrize("version", ["2.0", "1.0"])
def test_bag_bytes_are_what_rosbags_serializes(simulated, leaving, tmp_path, version):
    """The crowd topics are written from byte templates: they must equal rosbags' own serialization
    under the hunav_msgs of the bag's version."""
    store = ros_typestore(version)
    for bundle in (simulated, leaving):
        result = export_rosbag(bundle, tmp_path / bundle.parent.name, hunav_msgs_version=version)
        checked = 0
        with Reader(result.directory) as reader:
            for connection, _timestamp, raw in reader.messages():
                message = store.deserialize_cdr(raw, connection.msgtype)
                assert bytes(store.serialize_cdr(message, connection.msgtype)) == bytes(raw), connection.topic
                checked += 1
        assert checked == sum(result.counts.values())


def test_hunav_msgs_1_0_is_an_option_and_its_definitions_are_stored(simulated, tmp_path):
    result = CliRunner().invoke(main, ["export", "rosbag", str(simulated), "--out", str(tmp_path / "bag"),
                                       "--hunav-msgs", "1.0"])
    assert result.exit_code == 0, result.output
    messages, _, connections = read_bag(tmp_path / "bag")
    by_topic = {c.topic: c for c in connections}
    assert set(stored_definitions(by_topic["/human_states"])) == {"hunav_msgs/Agents", "hunav_msgs/Agent"}
    assert_definitions_are_the_msg_files(by_topic["/human_states"], "1.0")
    assert_definitions_are_the_msg_files(by_topic["/robot_states"], "1.0")
    agent1 = messages["/human_states"][0].agents[0]
    assert (agent1.behavior, agent1.behavior_state) == (3, 0)  # Surprised, as a 1.0 number
    custom = yaml.safe_load((tmp_path / "bag" / "metadata.yaml").read_text())["rosbag2_bagfile_information"]["custom_data"]
    assert custom["hunav_msgs.version"] == "1.0" and "afa97434" in custom["hunav_msgs.source"]
    bad = CliRunner().invoke(main, ["export", "rosbag", str(simulated), "--out", str(tmp_path / "b2"),
                                    "--hunav-msgs", "3.0"])
    assert bad.exit_code == 2 and not (tmp_path / "b2").exists()


def test_rosbag_follows_people_who_leave(leaving, tmp_path):
    result = export_rosbag(leaving, tmp_path / "bag")
    frames = csv_frames(leaving)
    messages, times, _ = read_bag(result.directory)
    assert len(messages["/human_states"]) == len(frames)
    for frame, msg in zip(frames, messages["/human_states"]):
        assert [a.id for a in msg.agents] == frame["ids"]
        assert np.array_equal([[a.position.position.x, a.position.position.y] for a in msg.agents], frame["xy"])
    assert not set(LEAVERS) & {a.id for a in messages["/human_states"][-1].agents}
    assert len(messages["/events"]) == event_count(leaving)
    everything = sorted((t, topic) for topic, ts in times.items() for t in ts)
    assert everything[0][0] == min(times["/human_states"][0], times["/events"][0])


def test_mcap_file_order_is_time_order(simulated, tmp_path):
    result = export_rosbag(simulated, tmp_path / "bag")
    with (result.directory / "bag.mcap").open("rb") as handle:
        log_times = [m.log_time for _s, _c, m in make_reader(handle).iter_messages(log_time_order=False)]
    assert len(log_times) == sum(result.counts.values())
    assert all(b >= a for a, b in zip(log_times, log_times[1:]))


def test_rosbag_output_is_all_or_nothing_and_never_replaces_other_folders(simulated, tmp_path):
    mine = tmp_path / "notes"
    mine.mkdir()
    (mine / "keep.txt").write_text("mine")
    with pytest.raises(GroveError, match="not a GROVE ROS 2 bag export"):
        export_rosbag(simulated, mine)
    assert [p.name for p in mine.iterdir()] == ["keep.txt"]
    first = export_rosbag(simulated, tmp_path / "bag")
    again = export_rosbag(simulated, tmp_path / "bag", storage="sqlite3")  # an earlier export is replaced
    assert sorted(p.name for p in again.directory.iterdir()) == [".grove-rosbag-export", "bag.db3", "metadata.yaml"]
    assert first.counts == again.counts
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bag", "notes"]  # no staging left behind


def test_exports_refuse_a_bundle_never_simulated(tmp_path):
    bundle = build_hospital_bundle(tmp_path / "fresh")
    with pytest.raises(GroveError, match=r"simulate first: grove simulate"):
        export_rosbag(bundle, tmp_path / "bag")
    with pytest.raises(GroveError, match=r"simulate first: grove simulate"):
        fox.export_foxglove(bundle, tmp_path / "scene.mcap")
    for args in (["rosbag", str(bundle), "--out", str(tmp_path / "b2")],
                 ["foxglove", str(bundle), "--out", str(tmp_path / "s2.mcap")]):
        result = CliRunner().invoke(main, ["export", *args])
        assert result.exit_code == 2 and "simulate first: grove simulate" in result.output
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fresh"]


def test_a_missing_optional_dependency_names_the_extra(simulated, tmp_path, monkeypatch):
    from grove_tui.services import backend

    for name in [m for m in sys.modules if m == "rosbags" or m.startswith("rosbags.")
                 or m == "foxglove" or m.startswith("foxglove.")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "rosbags", None)  # an import of rosbags now fails, as when not installed
    monkeypatch.setitem(sys.modules, "foxglove", None)
    assert "pip install 'grove-tui[ros]'" in rosbag.missing_dependency()
    assert "pip install 'grove-tui[ros]'" in fox.missing_dependency()
    with pytest.raises(MissingExtraError, match="needs rosbags") as caught:
        export_rosbag(simulated, tmp_path / "bag")
    assert caught.value.hint == "pip install 'grove-tui[ros]'" and caught.value.exit_code == 2
    with pytest.raises(MissingExtraError, match="needs foxglove-sdk") as caught:
        fox.export_foxglove(simulated, tmp_path / "scene.mcap")
    assert caught.value.hint == "pip install 'grove-tui[ros]'"
    result = CliRunner().invoke(main, ["export", "rosbag", str(simulated), "--out", str(tmp_path / "b")])
    assert result.exit_code == 2 and "grove-tui[ros]" in result.output

    class Run:  # what the app's export step holds after simulating
        pass

    ctx = backend.ExportContext(generated=None, simulation=Run(), out_dir=tmp_path / "app")
    shutil.copytree(simulated, ctx.bundle)
    backend.export_rosbag_files(ctx)
    backend.export_foxglove_files(ctx)
    assert [(f.kind, f.note) for f in ctx.files] == [
        ("rosbag", "not written: " + rosbag.missing_dependency()),
        ("foxglove", "not written: " + fox.missing_dependency())]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["app"]
    assert sorted(p.name for p in (tmp_path / "app").iterdir()) == ["bundle"]


def read_mcap(path: Path) -> tuple[dict[str, list], dict[str, list[int]], dict[str, str]]:
    messages: dict[str, list] = defaultdict(list)
    times: dict[str, list[int]] = defaultdict(list)
    schemas: dict[str, str] = {}
    with path.open("rb") as handle:
        reader = make_reader(handle, decoder_factories=[DecoderFactory()])
        for schema, channel, message, decoded in reader.iter_decoded_messages(log_time_order=False):
            messages[channel.topic].append(decoded)
            times[channel.topic].append(message.log_time)
            schemas[channel.topic] = schema.name
    return messages, times, schemas


def test_foxglove_mcap_reads_back_with_the_run_in_it(simulated, tmp_path):
    result = fox.export_foxglove(simulated, tmp_path / "scene.mcap")
    assert result.layout == tmp_path / "scene.layout.json"
    assert result.layout.read_text() == fox.layout_for(set(result.counts))
    frames = csv_frames(simulated)
    messages, times, schemas = read_mcap(result.mcap)
    with_robot = sum(f["robot"] is not None for f in frames)
    assert {t: len(m) for t, m in messages.items()} == result.counts == {
        "/people": len(frames), "/robot": with_robot, "/tf": with_robot, "/events": event_count(simulated),
        "/world": 1, "/map": 1, "/grove/planning_grid": 1, "/paths": 1}
    assert schemas == {"/people": "foxglove.SceneUpdate", "/robot": "foxglove.SceneUpdate",
                       "/tf": "foxglove.FrameTransforms", "/events": "foxglove.Log", "/world": "foxglove.SceneUpdate",
                       "/map": "foxglove.Grid", "/grove/planning_grid": "foxglove.Grid",
                       "/paths": "foxglove.SceneUpdate"}
    everything = [t for ts in times.values() for t in ts]
    assert min(everything) == min(times["/world"]) == min(times["/map"])  # the scene is there from the start
    for topic in ("/people", "/robot", "/tf"):
        assert all(b > a for a, b in zip(times[topic], times[topic][1:])), topic

    for frame, update, ns in zip(frames, messages["/people"], times["/people"]):
        assert ns == round(frame["t"] * 1e9)
        assert [e.id for e in update.entities] == [f"agent{i}" for i in frame["ids"]]
        assert all(e.timestamp.seconds * 10**9 + e.timestamp.nanos == ns and e.frame_id == "map"
                   for e in update.entities)
        xy = [[e.cylinders[0].pose.position.x, e.cylinders[0].pose.position.y] for e in update.entities]
        assert np.array_equal(xy, frame["xy"])
        q = [e.arrows[0].pose.orientation for e in update.entities]
        heading = np.array([2 * math.atan2(o.z, o.w) for o in q])
        assert np.allclose(np.angle(np.exp(1j * (heading - frame["yaw"]))), 0, atol=1e-9)
    for frame, update, tf in zip([f for f in frames if f["robot"] is not None], messages["/robot"], messages["/tf"]):
        [robot] = update.entities
        position = robot.cylinders[0].pose.position
        assert (position.x, position.y) == tuple(frame["robot"][:2])
        [transform] = tf.transforms
        assert (transform.parent_frame_id, transform.child_frame_id) == ("map", "base_link")
        assert (transform.translation.x, transform.translation.y) == tuple(frame["robot"][:2])

    grid = OccupancyGrid.load(simulated / "grid.npz")
    [planning] = messages["/grove/planning_grid"]
    assert (planning.column_count, planning.row_stride, planning.cell_stride) == (grid.width, grid.width, 1)
    cells = np.frombuffer(planning.data, dtype=np.uint8).reshape(grid.height, grid.width)
    assert np.array_equal(cells.astype(bool), grid.occupied)
    assert (planning.pose.position.x, planning.pose.position.y) == grid.origin

    world = load_world("hospital")
    [scene] = messages["/world"]
    ids = [e.id for e in scene.entities]
    walls = world.room_walls()
    lengths = np.hypot(walls[:, 2] - walls[:, 0], walls[:, 3] - walls[:, 1])
    assert len(scene.entities[ids.index("walls")].cubes) == int((lengths > 1e-9).sum())
    furniture = [e for e in scene.entities if e.id.startswith(("furniture/", "obstacle/"))]
    assert len(furniture) == len(world.entities()) + len(world.obstacles)
    assert all(len(e.cubes) == 1 for e in furniture)
    assert sum(i.startswith("zones/") for i in ids) == len(world.zones)
    [paths] = messages["/paths"]
    robot_path = next(e for e in paths.entities if e.id == "robot_path").lines[0].points
    scenario = Scenario.load(simulated / "scenario.yaml")
    assert [(p.x, p.y) for p in robot_path] == list(scenario.robot.path)
    assert sum(e.id.startswith("routes/") for e in paths.entities) == sum(bool(a.goals) for a in scenario.agents)


def test_foxglove_deletes_people_who_leave(leaving, tmp_path):
    result = fox.export_foxglove(leaving, tmp_path / "scene.mcap")
    messages, _, _ = read_mcap(result.mcap)
    frames = csv_frames(leaving)
    deleted = [(k, d.id) for k, update in enumerate(messages["/people"]) for d in update.deletions]
    first_without = next(k for k, f in enumerate(frames) if LEAVERS[0] not in f["ids"])
    assert deleted == [(first_without, f"agent{i}") for i in LEAVERS]
    for frame, update in zip(frames, messages["/people"]):
        assert [e.id for e in update.entities] == [f"agent{i}" for i in frame["ids"]]


def test_a_scenario_without_robot_has_no_robot_topics(simulated, tmp_path):
    bundle = tmp_path / "bundle"
    shutil.copytree(simulated, bundle)
    scenario = Scenario.load(bundle / "scenario.yaml")
    dataclasses.replace(scenario, robot=None).save(bundle / "scenario.yaml")
    lines = (bundle / "trajectories.csv").read_text().splitlines()
    (bundle / "trajectories.csv").write_text("\n".join([lines[0]] + [x for x in lines[1:] if x.split(",")[2] != "0"]))
    frames = len(csv_frames(bundle))
    bag = export_rosbag(bundle, tmp_path / "bag")
    assert bag.counts == {"/human_states": frames, "/agent_markers": frames, "/events": event_count(bundle),
                          "/map": 1, "/grove/planning_grid": 1, "/scenario_markers": 1}
    messages, _, _ = read_bag(bag.directory)
    assert all(m.ns == "people" for array in messages["/agent_markers"] for m in array.markers[1:])
    mcap = fox.export_foxglove(bundle, tmp_path / "scene.mcap")
    assert mcap.counts == {"/people": frames, "/events": event_count(bundle), "/world": 1, "/map": 1,
                           "/grove/planning_grid": 1, "/paths": 1}


def test_velocity_fields_are_drawn_as_arrows(simulated, tmp_path):
    from grove_tui.navigation.velocity_field import VelocityField

    bundle = tmp_path / "bundle"
    shutil.copytree(simulated, bundle)
    vectors = np.zeros((40, 60, 2), dtype=np.float32)
    vectors[5:35, 5:55, 0] = 1.0  # a field pushing east over a 3 m x 5 m patch
    VelocityField(origin=(28.0, 0.5), resolution=0.1, vectors=vectors, exit=(34.0, 2.0)).save(bundle / "fields/f0.npz")
    scenario = Scenario.load(bundle / "scenario.yaml")
    dataclasses.replace(scenario, fields={"f0": "fields/f0.npz"}).save(bundle / "scenario.yaml")
    messages, _, _ = read_mcap(fox.export_foxglove(bundle, tmp_path / "scene.mcap").mcap)
    [fields] = messages["/fields"]
    [entity] = fields.entities
    points = entity.lines[0].points
    assert entity.id == "fields/f0" and len(points) % 6 == 0 and len(points) > 0  # shaft + two barbs per arrow
    shafts = np.array([[p.x, p.y] for p in points]).reshape(-1, 2, 2)[: len(points) // 6]
    assert np.allclose(shafts[:, 1, 1] - shafts[:, 0, 1], 0) and np.all(shafts[:, 1, 0] > shafts[:, 0, 0])
    bag, _, _ = read_bag(export_rosbag(bundle, tmp_path / "bag").directory)
    assert any(m.ns == "field/f0" and len(m.points) == len(points) for m in bag["/scenario_markers"][0].markers)


def test_the_shipped_layout_is_foxglove_sdks_layout_model():
    layout = json.loads(fox.shipped_layout())
    assert fox.shipped_layout() == fox.build_layout()
    panel = layout["content"]["items"][0]["content"]
    assert panel["panelType"] == "ThreeDee"
    assert set(panel["config"]["topics"]) == {"/map", "/grove/planning_grid", "/world", "/paths", "/fields",
                                              "/people", "/robot"}
    assert panel["config"]["topics"]["/map"]["visible"] and not panel["config"]["topics"]["/grove/planning_grid"]["visible"]


def test_each_layout_lists_only_the_topics_its_file_has(simulated, tmp_path):
    """Issue 30: the hospital run has no velocity fields, so its layout has no /fields; a file without
    events has no event log panel."""
    result = fox.export_foxglove(simulated, tmp_path / "scene.mcap")
    layout = json.loads(result.layout.read_text())
    panel = layout["content"]["items"][0]["content"]
    assert "/fields" not in result.counts and set(panel["config"]["topics"]) <= set(result.counts)
    assert layout["content"]["items"][1]["content"]["config"]["topicToRender"] == "/events" in result.counts
    quiet = tmp_path / "quiet"
    shutil.copytree(simulated, quiet)
    (quiet / "events.jsonl").write_text("")
    result = fox.export_foxglove(quiet, tmp_path / "quiet.mcap")
    layout = json.loads(result.layout.read_text())
    assert "/events" not in result.counts
    assert layout["content"]["panelType"] == "ThreeDee"  # the 3D view alone, no empty log panel
    assert set(layout["content"]["config"]["topics"]) <= set(result.counts)


def test_foxglove_output_must_be_an_mcap_file_and_is_all_or_nothing(simulated, tmp_path):
    with pytest.raises(GroveError, match=r"\.mcap"):
        fox.export_foxglove(simulated, tmp_path / "scene.json")
    folder = tmp_path / "taken.mcap"
    folder.mkdir()
    with pytest.raises(GroveError, match="is a folder"):
        fox.export_foxglove(simulated, folder)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["taken.mcap"]


def test_batch_jobs_take_an_export_list(tmp_path):
    jobs = tmp_path / "jobs.jsonl"
    base = {"world": "hospital", "preset": "normal", "prompt": "people walk"}
    jobs.write_text("\n".join(json.dumps({**base, **extra}) for extra in (
        {"simulate": 30, "export": ["rosbag", "foxglove"], "name": "a"},
        {"export": ["hunav"], "name": "b"},
        {"export": ["rosbag"], "name": "c"},
        {"simulate": 30, "export": ["rosbg"], "name": "d"},
        {"simulate": 30, "export": "rosbag", "name": "e"},
        {"simulate": 30, "export": ["foxglove", "foxglove"], "name": "f"},
    )) + "\n")
    good, problems = read_jobs(jobs)
    assert [(j.name, j.exports) for j in good] == [("a", ("rosbag", "foxglove")), ("b", ("hunav",))]
    assert [str(p) for p in problems] == [
        'line 3: export rosbag needs a simulated run: add "simulate": SECONDS',
        "line 4: unknown export 'rosbg' (did you mean 'rosbag'?) (formats: hunav, trajectories, rosbag, foxglove)",
        "line 5: export must be a list of format names like [\"rosbag\"], got 'rosbag'",
        "line 6: export lists foxglove more than once",
    ]
