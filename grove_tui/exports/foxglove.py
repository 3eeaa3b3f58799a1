"""A simulated bundle as one MCAP file with Foxglove's own schemas (protobuf, from `foxglove-sdk`), plus a
Foxglove layout written beside it, so opening the file in Foxglove shows the scenario in 3D at once.

Topics (frame `map`, log times = simulation time):

    /people               foxglove.SceneUpdate     every frame: a body and a heading arrow per person (group
                                                   colour); people who left are deleted
    /robot                foxglove.SceneUpdate     every frame the robot was recorded: its body and heading
    /tf                   foxglove.FrameTransforms every frame the robot was recorded: map -> base_link
    /world                foxglove.SceneUpdate     once: the Gazebo world's boxes (walls, furniture, obstacles,
                                                   exports/scene.py), zones with their names, doors and exits
    /map                  foxglove.Grid            once: the scene's static map (1 occupied, 0 free), the nav2
                                                   map and the bag's /map: not inflated, covering every goal
    /grove/planning_grid  foxglove.Grid            once: GROVE's planning grid (the building, inflated), hidden
    /paths                foxglove.SceneUpdate     once: the robot's planned path, each person's route, waypoints
                                                   and goals (spheres of the goal radius)
    /fields               foxglove.SceneUpdate     once, when the scenario has velocity fields: arrows
    /events               foxglove.Log             one per event of events.jsonl, when there are any

What is published once is logged at the start; Foxglove shows the latest message of each topic at
the playback time, so they stay visible through the run. The layout written beside the file lists the
topics this file has, and the event log only when it has events.

The file carries a metadata record `grove-tui` (written first, so it sits in the file's first bytes):
that is how a later export knows an existing .mcap is its own to replace. Any other file at `--out`,
and a layout file other than the one GROVE writes, is kept unless the user passes `--overwrite`.
"""

from __future__ import annotations

import contextlib
import json
import logging
import math
import os
import re
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Generic, Protocol, TypedDict, TypeVar, Unpack

import numpy as np

from grove_tui.errors import FoxgloveExportError, OutputError, missing_extra, require_extra
from grove_tui.exports.frames import ROS_EXTRA, Frame, SimulatedBundle, arrow_segments, field_arrows, group_rgba, \
    open_simulated_bundle
from grove_tui.exports.scene import goal_radius
from grove_tui.files import atomic_file, check_output_file

if TYPE_CHECKING:  # foxglove-sdk is the `ros` extra; the export imports it when it runs
    from foxglove import Context
    from foxglove.messages import (ArrowPrimitive, Color, CubePrimitive, CylinderPrimitive, Grid, KeyValuePair,
                                   LinePrimitive, Pose, SceneEntity, SceneUpdate, SpherePrimitive, TextPrimitive,
                                   Timestamp, Vector3)

    class _Primitives(TypedDict, total=False):
        """What a SceneEntity is drawn with (foxglove.messages.SceneEntity's keyword arguments)."""

        metadata: list[KeyValuePair]
        arrows: list[ArrowPrimitive]
        cubes: list[CubePrimitive]
        spheres: list[SpherePrimitive]
        cylinders: list[CylinderPrimitive]
        lines: list[LinePrimitive]
        texts: list[TextPrimitive]

    from grove_tui.navigation.grid import OccupancyGrid
    from grove_tui.scenario.events import SimEvent

Message = TypeVar("Message", contravariant=True)


class _Channel(Protocol, Generic[Message]):
    """A foxglove channel of one message type (SceneUpdateChannel logs SceneUpdate, GridChannel Grid...)."""

    def log(self, message: Message, *, log_time: int | None = None, sink_id: int | None = None) -> None: ...

LAYOUT_FILE = Path(__file__).with_name("foxglove_layout.json")
FRAME_ID = "map"
ROBOT_FRAME = "base_link"
PLANNING_GRID_TOPIC = "/grove/planning_grid"
PERSON_HEIGHT = 1.7
ROBOT_HEIGHT = 0.4
BOX_RGBA = {"wall": (0.25, 0.25, 0.27, 0.9), "furniture": (0.85, 0.81, 0.75, 1.0), "obstacle": (0.69, 0.66, 0.6, 1.0)}
MCAP_MAGIC = b"\x89MCAP0\r\n"
METADATA_NAME = "grove-tui"  # the metadata record that marks GROVE's own export
_OWN_MARK_WINDOW = 64 * 1024  # the record is written first: it lies within the file's first bytes


@dataclass(frozen=True)
class FoxgloveExport:
    mcap: Path
    layout: Path
    frames: int
    counts: dict[str, int]  # messages per topic


FOXGLOVE_MODULES = ("foxglove", "foxglove.channels", "foxglove.messages")


def missing_dependency() -> str | None:
    """Why this export cannot run here (its optional dependency is not installed), or None."""
    if missing_extra(FOXGLOVE_MODULES) is None:
        return None
    return f"the Foxglove export needs foxglove-sdk: {ROS_EXTRA}"


def _foxglove() -> None:
    """foxglove-sdk can be imported, or MissingExtraError names the extra that installs it."""
    require_extra("the Foxglove MCAP export", "foxglove-sdk", FOXGLOVE_MODULES, ROS_EXTRA)


def layout_path_for(mcap: Path) -> Path:
    """Where the layout goes: beside the MCAP, `<name>.layout.json`."""
    return mcap.with_name(mcap.stem + ".layout.json")


def is_grove_mcap(path: Path) -> bool:
    """An MCAP file `grove export foxglove` wrote (its `grove-tui` metadata record near the start)."""
    try:
        with open(path, "rb") as handle:
            head = handle.read(_OWN_MARK_WINDOW)
    except OSError:
        return False
    return head.startswith(MCAP_MAGIC) and METADATA_NAME.encode() in head


def is_grove_layout(path: Path) -> bool:
    """A layout GROVE writes, unchanged (one the user edited in Foxglove is theirs): the shipped layout
    for exactly the topics it lists (`layout_for`)."""
    limit = len(shipped_layout().encode("utf-8")) + 1  # no layout GROVE writes is longer than the shipped one
    try:
        with open(path, "rb") as handle:
            data = handle.read(limit)
        layout = json.loads(data)
        content = layout["content"]
        panels = [item["content"] for item in content["items"]] if content.get("type") == "split" else [content]
        topics = set(panels[0]["config"]["topics"])
        if any(panel.get("config", {}).get("topicToRender") == "/events" for panel in panels[1:]):
            topics.add("/events")
    except (OSError, ValueError, KeyError, TypeError, IndexError, AttributeError):
        return False
    return data == layout_for(topics).encode("utf-8")


def build_layout() -> str:
    """The shipped layout, made with foxglove-sdk's layout model: a 3D view from above with every topic
    of the export, and the event log beside it."""
    _foxglove()
    import foxglove.layouts as fl

    scene = fl.BaseRendererSceneUpdateTopicSettings
    three_d = fl.ThreeDeePanel(title="Scenario", config=fl.ThreeDeeConfig(
        follow_tf=FRAME_ID, follow_mode="follow-none",
        camera_state=fl.ThreeDeeCameraState(perspective=True, distance=60.0, phi=35.0, theta_offset=0.0),
        layers={"grid": fl.BaseRendererGridLayerSettings(visible=False)},
        topics={
            "/map": fl.BaseRendererGridTopicSettings(visible=True, color_mode="gradient",
                                                    gradient=("#f4f1eaff", "#6b6357ff"), min_value=0.0,
                                                    max_value=1.0, draw_behind=True,
                                                    interpolation_method="nearestNeighbor"),
        PLANNING_GRID_TOPIC: fl.BaseRendererGridTopicSettings(visible=False, color_mode="gradient",
                                                              gradient=("#ffffff00", "#c0392b80"), min_value=0.0,
                                                              max_value=1.0, draw_behind=True,
                                                              interpolation_method="nearestNeighbor"),
            "/world": scene(visible=True),
            "/paths": scene(visible=True),
            "/fields": scene(visible=True),
            "/people": scene(visible=True),
            "/robot": scene(visible=True),
        }))
    log = fl.LogPanel(title="Events", config=fl.LogConfig(topic_to_render="/events", show_name=True))
    layout = fl.Layout(content=fl.SplitContainer(direction="row", items=[
        fl.SplitItem(proportion=3, content=three_d),
        fl.SplitItem(proportion=1, content=log),
    ]))
    return json.dumps(json.loads(layout.to_json()), indent=2) + "\n"


def shipped_layout() -> str:
    return LAYOUT_FILE.read_text(encoding="utf-8")


def layout_for(topics: set[str]) -> str:
    """The shipped layout with only the 3D topics this file has, and without the event log panel
    when it has no /events: Foxglove shows an empty panel, or a topic that never comes, otherwise."""
    layout = json.loads(shipped_layout())
    items = layout["content"]["items"]
    three_d = items[0]["content"]
    three_d["config"]["topics"] = {topic: settings for topic, settings in three_d["config"]["topics"].items()
                                   if topic in topics}
    if "/events" not in topics:
        layout["content"] = three_d
    return json.dumps(layout, indent=2) + "\n"


def _ns(t: float) -> int:
    return int(round(t * 1e9))


class _Scene:
    """Builders for foxglove.messages values, with the constant parts made once."""

    def __init__(self) -> None:
        _foxglove()
        from foxglove import messages as m

        self.m = m
        self.identity = m.Quaternion(x=0.0, y=0.0, z=0.0, w=1.0)
        self._colours: dict[tuple[float, ...], Color] = {}
        self._sizes: dict[tuple[float, ...], Vector3] = {}

    def colour(self, rgba: tuple[float, float, float, float]) -> Color:
        key = tuple(round(c, 4) for c in rgba)
        if key not in self._colours:
            self._colours[key] = self.m.Color(r=key[0], g=key[1], b=key[2], a=key[3])
        return self._colours[key]

    def size(self, x: float, y: float, z: float) -> Vector3:
        key = (x, y, z)
        if key not in self._sizes:
            self._sizes[key] = self.m.Vector3(x=x, y=y, z=z)
        return self._sizes[key]

    def pose(self, x: float, y: float, z: float = 0.0, yaw: float = 0.0) -> Pose:
        m = self.m
        orientation = self.identity if yaw == 0.0 else m.Quaternion(x=0.0, y=0.0, z=math.sin(yaw / 2),
                                                                    w=math.cos(yaw / 2))
        return m.Pose(position=m.Vector3(x=x, y=y, z=z), orientation=orientation)

    def stamp(self, ns: int) -> Timestamp:
        return self.m.Timestamp(ns // 1_000_000_000, ns % 1_000_000_000)

    def line(self, kind: str, points: Sequence[Sequence[float]] | np.ndarray, rgba: tuple[float, float, float, float],
             thickness: float, z: float = 0.02) -> LinePrimitive:
        m = self.m
        return m.LinePrimitive(type=getattr(m.LinePrimitiveLineType, kind), pose=self.pose(0.0, 0.0),
                               thickness=thickness, scale_invariant=False,
                               points=[m.Point3(x=float(p[0]), y=float(p[1]), z=z) for p in points],
                               color=self.colour(rgba))

    def entity(self, ns: int, entity_id: str, **primitives: Unpack[_Primitives]) -> SceneEntity:
        return self.m.SceneEntity(timestamp=self.stamp(ns), frame_id=FRAME_ID, id=entity_id, **primitives)

    def bodies(self, x: list[float], y: list[float], yaw: np.ndarray, looks: list[tuple[Color, Vector3, float]],
               height: float) -> list[tuple[CylinderPrimitive, ArrowPrimitive]]:
        """A standing cylinder and an arrow on the ground showing where it faces, per body.

        `looks` holds each body's (colour, size, radius), made once; this runs for every person in every
        frame, so it builds the foxglove values directly and takes sines in one numpy call."""
        m = self.m
        Vector3, Pose, Quaternion = m.Vector3, m.Pose, m.Quaternion
        qz = np.sin(yaw / 2).tolist()
        qw = np.cos(yaw / 2).tolist()
        identity = self.identity
        out = []
        for k, (colour, size, radius) in enumerate(looks):
            cylinder = m.CylinderPrimitive(pose=Pose(position=Vector3(x=x[k], y=y[k], z=height / 2),
                                                     orientation=identity),
                                           size=size, bottom_scale=1.0, top_scale=1.0, color=colour)
            arrow = m.ArrowPrimitive(pose=Pose(position=Vector3(x=x[k], y=y[k], z=0.05),
                                               orientation=Quaternion(x=0.0, y=0.0, z=qz[k], w=qw[k])),
                                     shaft_length=radius + 0.15, shaft_diameter=0.06, head_length=0.2,
                                     head_diameter=0.18, color=colour)
            out.append((cylinder, arrow))
        return out

    def look(self, rgba: tuple[float, float, float, float], radius: float, height: float) -> tuple[Color, Vector3, float]:
        return self.colour(rgba), self.size(2 * radius, 2 * radius, height), radius


def _world_update(bundle: SimulatedBundle, scene: _Scene, ns: int) -> SceneUpdate:
    """The Gazebo world's boxes (walls, furniture, obstacles: the same sizes and heights as the SDF),
    zones with their names, doors and exits."""
    m = scene.m
    world = bundle.world
    entities = []
    walls = []
    for box in bundle.scene.boxes:
        cube = m.CubePrimitive(pose=scene.pose(box.x, box.y, box.height / 2, box.yaw),
                               size=scene.size(box.length, box.width, box.height),
                               color=scene.colour(BOX_RGBA[box.kind]))
        if box.kind == "wall":
            walls.append(cube)
        else:
            entities.append(scene.entity(ns, f"{box.kind}/{box.name.split('_', 1)[1]}", cubes=[cube]))
    if walls:
        entities.insert(0, scene.entity(ns, "walls", cubes=walls))
    for zone in world.zones:
        cx, cy = zone.centroid
        entities.append(scene.entity(
            ns, f"zones/{zone.name}", lines=[scene.line("LineLoop", zone.boundary, (0.54, 0.5, 0.44, 0.6), 0.04)],
            texts=[m.TextPrimitive(pose=scene.pose(cx, cy, 0.1), billboard=True, font_size=14.0,
                                   scale_invariant=True, color=scene.colour((0.3, 0.28, 0.24, 1.0)),
                                   text=zone.name.replace("_", " "))]))
    for door in world.doors():
        rgba = (0.75, 0.22, 0.17, 1.0) if door.exit else (0.15, 0.68, 0.38, 1.0)
        a, b = door.opening
        entities.append(scene.entity(ns, f"doors/{door.name}", lines=[scene.line("LineList", [a, b], rgba, 0.15)]))
    return m.SceneUpdate(entities=entities)


def _paths_update(bundle: SimulatedBundle, scene: _Scene, ns: int) -> SceneUpdate:
    m = scene.m
    entities = []
    for agent in bundle.scenario.agents:
        if not agent.goals:
            continue
        rgba = group_rgba(agent.group)
        colour = scene.colour(rgba)
        size = 2 * goal_radius(agent)  # each goal's disc, as agents YAML and hunav_msgs/Agent say
        spheres = [m.SpherePrimitive(pose=scene.pose(x, y, size / 2), size=scene.size(size, size, size), color=colour)
                   for x, y in agent.goals]
        entities.append(scene.entity(
            ns, f"routes/agent{agent.id}", spheres=spheres,
            lines=[scene.line("LineStrip", [agent.start, *agent.goals], group_rgba(agent.group, 0.6), 0.04)],
            metadata=[m.KeyValuePair(key="behavior", value=agent.behavior),
                      m.KeyValuePair(key="group", value=str(agent.group))]))
    robot = bundle.scenario.robot
    if robot is not None:
        path = list(robot.path) or [robot.start, robot.goal]
        entities.append(scene.entity(
            ns, "robot_path", lines=[scene.line("LineStrip", path, (0.0, 0.0, 0.0, 1.0), 0.08, z=0.04)],
            spheres=[m.SpherePrimitive(pose=scene.pose(*robot.goal, 0.2), size=scene.size(0.4, 0.4, 0.4),
                                       color=scene.colour((0.0, 0.0, 0.0, 1.0)))]))
    return m.SceneUpdate(entities=entities)


def _fields_update(bundle: SimulatedBundle, scene: _Scene, ns: int) -> SceneUpdate:
    entities = []
    for field_id, field in sorted(bundle.fields.items()):
        segments = arrow_segments(field_arrows(field)).reshape(-1, 2)
        entities.append(scene.entity(ns, f"fields/{field_id}",
                                     lines=[scene.line("LineList", segments, (0.5, 0.55, 0.55, 0.8), 0.03)]))
    return scene.m.SceneUpdate(entities=entities)


def _grid(grid: OccupancyGrid, scene: _Scene, ns: int) -> Grid:
    """foxglove.Grid of an occupancy grid, one uint8 per cell (1 occupied), row 0 the smallest y."""
    m = scene.m
    return m.Grid(timestamp=scene.stamp(ns), frame_id=FRAME_ID, pose=scene.pose(*grid.origin),
                  column_count=grid.width, cell_size=m.Vector2(x=grid.resolution, y=grid.resolution),
                  row_stride=grid.width, cell_stride=1,
                  fields=[m.PackedElementField(name="occupied", offset=0, type=m.PackedElementFieldNumericType.Uint8)],
                  data=grid.occupied.astype(np.uint8).tobytes())


def export_foxglove(bundle_dir: str | Path, out_path: str | Path, *, overwrite: bool = False) -> FoxgloveExport:
    """Write `out_path` (.mcap) and its layout beside it; both complete, or neither is touched.

    An existing file at either path is replaced only when GROVE wrote it (`is_grove_mcap`,
    `is_grove_layout`) or with `overwrite`; links, folders and special files never.
    """
    out = Path(out_path)
    if out.suffix.lower() != ".mcap":
        raise FoxgloveExportError(f"{out}: a Foxglove export is an .mcap file (name it *.mcap)")
    layout = layout_path_for(out)
    mcap_guard = dict(owned=is_grove_mcap, what="GROVE Foxglove export", overwrite=overwrite)
    layout_guard = dict(owned=is_grove_layout, what="GROVE Foxglove layout", overwrite=overwrite)
    # Both checked before anything is written: a refused layout must not cost the user's .mcap either.
    out = check_output_file(out, **mcap_guard)  # type: ignore[arg-type]
    layout = check_output_file(layout, **layout_guard)  # type: ignore[arg-type]
    _foxglove()
    bundle = open_simulated_bundle(bundle_dir)
    with atomic_file(out, **mcap_guard) as tmp_mcap, atomic_file(layout, **layout_guard) as tmp_layout:  # type: ignore[arg-type]
        frames, counts = _write_mcap(bundle, tmp_mcap, out)
        tmp_layout.write_text(layout_for(set(counts)), encoding="utf-8")
    return FoxgloveExport(out, layout, frames, counts)


class _WriteFailures(logging.Handler):
    """foxglove-sdk reports a failed write (a full disk) by logging it, once per message, and raises
    only when the file is closed: catch the first report, keep the thousands after it off stderr,
    and let the writer stop at once with one error."""

    def __init__(self) -> None:
        super().__init__(logging.ERROR)
        self.first: str | None = None
        self.reason: str | None = None  # the operating system's words, when a report carries them

    def emit(self, record: logging.LogRecord) -> None:
        text = record.getMessage()
        if self.first is None:
            self.first = text
        if self.reason is None:
            found = re.search(r'message: "([^"]+)"', text)
            if found:
                self.reason = found.group(1)


@contextlib.contextmanager
def _watch_writes() -> Iterator[_WriteFailures]:
    logger = logging.getLogger("foxglove")
    watch = _WriteFailures()
    propagate = logger.propagate
    logger.addHandler(watch)
    logger.propagate = False
    try:
        yield watch
    finally:
        logger.removeHandler(watch)
        logger.propagate = propagate


def _write_failure(out: Path, watch: _WriteFailures, raised: str = "") -> OutputError:
    """One line for what foxglove-sdk said (the operating system's words when it passed them on)."""
    detail = watch.reason or watch.first or raised
    found = re.search(r'message: "([^"]+)"', detail)
    reason = found.group(1) if found else (detail.splitlines() or ["unknown error"])[0][:160]
    reason = reason.removeprefix("FoxgloveError: ")
    try:  # the SDK does not always pass the system's reason on: say so when the disk is the cause
        space = os.statvfs(out.parent)
        if space.f_bavail * space.f_frsize < 1 << 20:
            reason = f"No space left on device ({reason})"
    except OSError:
        pass
    return OutputError(f"{out}: cannot write it: {reason}")


def _write_mcap(bundle: SimulatedBundle, path: Path, out: Path) -> tuple[int, dict[str, int]]:
    with _watch_writes() as watch:
        try:
            return _write_frames(bundle, path, out, watch)
        except RuntimeError as exc:  # foxglove-sdk's FoxgloveError, raised when closing a failed file
            if watch.first is None and "FoxgloveError" not in str(exc):
                raise
            raise _write_failure(out, watch, str(exc)) from None


def _write_frames(bundle: SimulatedBundle, path: Path, out: Path, watch: _WriteFailures) -> tuple[int, dict[str, int]]:
    import foxglove
    from foxglove import channels as ch

    scene = _Scene()
    m = scene.m
    context = foxglove.Context()
    frames = bundle.frames()
    first = next(frames, None)
    if first is None:
        raise FoxgloveExportError(f"{bundle.trajectories}: no trajectory rows")
    events = bundle.events
    start = min([_ns(first.t)] + [_ns(e.t) for e in events[:1]])
    counts: dict[str, int] = {}

    writer = foxglove.open_mcap(path, allow_overwrite=True, context=context)
    writer.write_metadata(METADATA_NAME, {"writer": "grove export foxglove", "bundle": bundle.path.name})
    try:
        # Each foxglove channel class logs its own message type (SceneUpdate, Grid, Log...).
        def channel(kind: Callable[..., _Channel[Message]], topic: str) -> Callable[[Message, int], None]:
            made = kind(topic, context=context)
            counts[topic] = 0

            def log(message: Message, ns: int) -> None:
                made.log(message, log_time=ns)
                counts[topic] += 1
            return log

        people_log = channel(ch.SceneUpdateChannel, "/people")
        if bundle.scenario.robot is not None:
            robot_log = channel(ch.SceneUpdateChannel, "/robot")
            tf_log = channel(ch.FrameTransformsChannel, "/tf")
        event_log = channel(ch.LogChannel, "/events")

        def log_event(event: SimEvent) -> None:
            ns = max(_ns(event.t), start)
            event_log(m.Log(timestamp=scene.stamp(ns), level=m.LogLevel.Info, name=event.kind,
                            message=f"agent {event.agent_id}: {event.kind} {event.detail}".strip()), ns)

        channel(ch.SceneUpdateChannel, "/world")(_world_update(bundle, scene, start), start)
        channel(ch.GridChannel, "/map")(_grid(bundle.scene.static_map, scene, start), start)
        channel(ch.GridChannel, PLANNING_GRID_TOPIC)(_grid(bundle.grid, scene, start), start)
        channel(ch.SceneUpdateChannel, "/paths")(_paths_update(bundle, scene, start), start)
        if bundle.fields:
            channel(ch.SceneUpdateChannel, "/fields")(_fields_update(bundle, scene, start), start)

        people = {a.id: scene.look(group_rgba(a.group), a.radius, PERSON_HEIGHT) for a in bundle.scenario.agents}
        names = {a.id: f"agent{a.id}" for a in bundle.scenario.agents}
        robot = bundle.scenario.robot
        robot_look = None if robot is None else scene.look((0.15, 0.15, 0.15, 1.0), robot.radius, ROBOT_HEIGHT)
        pending = iter(events)
        event = next(pending, None)
        shown: set[int] = set()
        count = 0
        frame: Frame | None = first
        while frame is not None:
            ns = _ns(frame.t)
            while event is not None and _ns(event.t) <= ns:
                log_event(event)
                event = next(pending, None)
            stamp = scene.stamp(ns)
            ids = frame.ids.tolist()
            try:
                looks = [people[i] for i in ids]
            except KeyError as exc:
                raise FoxgloveExportError(f"{bundle.trajectories}: person {exc.args[0]} is not an agent of "
                                          f"{bundle.path / 'scenario.yaml'}; simulate the bundle again") from None
            bodies = scene.bodies(frame.x.tolist(), frame.y.tolist(), frame.yaw, looks, PERSON_HEIGHT)
            entities = [m.SceneEntity(timestamp=stamp, frame_id=FRAME_ID, id=names[i], cylinders=[cylinder],
                                      arrows=[arrow]) for i, (cylinder, arrow) in zip(ids, bodies)]
            here = set(ids)
            deletions = [m.SceneEntityDeletion(timestamp=stamp, type=m.SceneEntityDeletionType.MatchingId,
                                               id=names[i]) for i in sorted(shown - here)]
            shown = here
            people_log(m.SceneUpdate(deletions=deletions, entities=entities), ns)
            if frame.robot is not None and robot_look is not None:
                rx, ry, _rvx, _rvy, ryaw = (float(v) for v in frame.robot)
                [(cylinder, arrow)] = scene.bodies([rx], [ry], np.array([ryaw]), [robot_look], ROBOT_HEIGHT)
                robot_log(m.SceneUpdate(entities=[m.SceneEntity(timestamp=stamp, frame_id=FRAME_ID, id="robot",
                                                                cylinders=[cylinder], arrows=[arrow])]), ns)
                tf_log(m.FrameTransforms(transforms=[m.FrameTransform(
                    timestamp=stamp, parent_frame_id=FRAME_ID, child_frame_id=ROBOT_FRAME,
                    translation=m.Vector3(x=rx, y=ry, z=0.0),
                    rotation=m.Quaternion(x=0.0, y=0.0, z=math.sin(ryaw / 2), w=math.cos(ryaw / 2)))]), ns)
            count += 1
            if watch.first is not None:
                raise _write_failure(out, watch)
            frame = next(frames, None)
        while event is not None:
            log_event(event)
            event = next(pending, None)
    finally:
        writer.close()
    return count, {topic: n for topic, n in counts.items() if n}
