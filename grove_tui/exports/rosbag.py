"""A simulated bundle as a ROS 2 bag (rosbag2, MCAP or sqlite3 storage), written without ROS by `rosbags`.

Topics (frame `map`, stamps = simulation time, message log times equal to the header stamps):

    /human_states         hunav_msgs/msg/Agents          every frame: the people, as HuNavSim's agent manager
    /robot_states         hunav_msgs/msg/Agent           every frame the robot was recorded
    /agent_markers        visualization_msgs/MarkerArray every frame: DELETEALL, then a body per person and the robot
    /tf                   tf2_msgs/msg/TFMessage         every frame: map -> base_link (the robot)
    /events               std_msgs/msg/String            one per event of events.jsonl, as a JSON object
    /map                  nav_msgs/msg/OccupancyGrid     once, latched: the scene's static map (exports/scene.py),
                                                         the nav2 map of `grove export hunav`: walls and furniture,
                                                         not inflated, over the extent that covers every goal
    /grove/planning_grid  nav_msgs/msg/OccupancyGrid     once, latched: GROVE's planning grid (the building only,
                                                         inflated by the largest body radius); not a robot's map
    /scenario_markers     visualization_msgs/MarkerArray once, latched: goals, routes, waypoints, fields, robot goal
    /plan                 nav_msgs/msg/Path              once, latched: the robot's planned path
    /goal_pose            geometry_msgs/PoseStamped      once: the robot's goal (HuNavSim's evaluator listens to it)

"Latched" topics are offered with a transient-local QoS profile in the bag's metadata, so `ros2 bag play`
republishes them the way a map server does and late subscribers (RViz) still get them.

`hunav_msgs` is HuNavSim's own package, in the version asked for (HUNAV_MSGS): 2.0 by default (Agent
with a nested AgentBehavior: type, configuration, duration, force factors...), 1.0 on request (Agent with
`uint8 behavior` and `behavior_state`). The .msg files of both are shipped verbatim in
`grove_tui/exports/msg/hunav_msgs/<version>/` and registered by name; each bag connection stores their
text (rosbag2's message definition), and the bag's metadata names the version and its source, so a
reader without hunav_msgs decodes it and a HuNavSim installation of that version replays it to its
evaluator. Every agent quantity (skin, behavior, goal radius, cyclic goals, radius) comes from
exports/scene.py, as in the agents YAML.

Speed: the per-frame messages of a crowd (Agents, MarkerArray) are byte templates. The layout of a
frame's message depends only on which people it lists, so it is built once per set of ids and each
frame only writes its numbers into place through numpy views. Tests check the bytes equal what
rosbags' own serializer makes of the same message.
"""

from __future__ import annotations

import json
import math
import os
import struct
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Final

import numpy as np

from grove_tui.errors import RosbagExportError, missing_extra, require_extra
from grove_tui.exports.frames import ROS_EXTRA, Frame, SimulatedBundle, arrow_segments, field_arrows, group_rgba, \
    open_simulated_bundle
from grove_tui.exports.scene import agent_radius, behavior_values, goal_radius, skin
from grove_tui.files import atomic_directory, check_output_dir, refuse_overlap
from grove_tui.scenario.model import AgentSpec

if TYPE_CHECKING:  # rosbags is the `ros` extra; the export imports it when it runs
    from rosbags.interfaces import Connection, Qos
    from rosbags.interfaces.typing import Typesdict
    from rosbags.typesys.store import Typestore

    from grove_tui.navigation.grid import OccupancyGrid
    from grove_tui.scenario.events import SimEvent

# A ROS message instance: rosbags builds its classes at run time from message definitions, so no static type names it.
Message = Any  # Any: rosbags generates message classes at run time

MSG_ROOT = Path(__file__).with_name("msg") / "hunav_msgs"


@dataclass(frozen=True)
class HunavMsgs:
    """One version of HuNavSim's hunav_msgs as shipped here: its .msg files and where they come from."""

    version: str
    source: str
    blobs: dict[str, str]  # file name -> git blob id of the shipped copy (tests prove it verbatim)

    @property
    def folder(self) -> Path:
        return MSG_ROOT / self.version

    def text(self, name: str) -> str:
        """The text of one shipped definition ("Agent.msg", ...)."""
        return (self.folder / name).read_text(encoding="utf-8")

    def types(self) -> dict[str, str]:
        """hunav_msgs/msg/<Type> -> its .msg text."""
        return {f"hunav_msgs/msg/{Path(name).stem}": self.text(name) for name in self.blobs}


HUNAV_MSGS = {
    # robotics-upo/hunav_sim, branch humble (HuNavSim 1.0), commit of 2023-10-10; the .msg files last
    # changed in 2b4a780 (2022-07-06).
    "1.0": HunavMsgs("1.0", "robotics-upo/hunav_sim@afa974340901e244ce15a97e8ebc37c0699a3e6f (humble, HuNavSim 1.0)",
                     {"Agent.msg": "8b5c7944e5ced2ea05ed10a1bef9787a1be62e4d",
                      "Agents.msg": "e029b25d84c4eb1bbe0bef856a8ec10b37653da5"}),
    # HuNavSim 2.0 (robotics-upo/hunav_sim master: hunav_msgs/CMakeLists.txt@1576ef2 generates Agent, Agents
    # and AgentBehavior; hunav_gazebo_wrapper WorldGenerator.cpp@4e0ac91 fills every AgentBehavior field).
    # The files as the public code index holds them, vendored unchanged in Lady-Lex/arena-evaluation@b1afa1a.
    "2.0": HunavMsgs("2.0", "robotics-upo/hunav_sim 2.0 (master; hunav_msgs/CMakeLists.txt@1576ef2), "
                     "files as vendored in Lady-Lex/arena-evaluation@b1afa1a2701b345c98e0e708e597c5b880daa8c9",
                     {"Agent.msg": "d4685d22c960fabc66e728a52b5fc44a83212105",
                      "AgentBehavior.msg": "a38b55415cf98ec06994b40487ebe23efcd5248c",
                      "Agents.msg": "49500db5a3ae79f24ebbcad54a7ce7499ca49f49"}),
}
DEFAULT_HUNAV_MSGS = "2.0"
EXPORT_MARKER = ".grove-rosbag-export"
STORAGES = ("mcap", "sqlite3")
BAG_VERSION: Final = 8  # rosbag2 metadata version 8: QoS as Humble writes it; Jazzy reads it too
FRAME_ID = "map"
ROBOT_FRAME = "base_link"
PLANNING_GRID_TOPIC = "/grove/planning_grid"
PERSON_HEIGHT = 1.7
ROBOT_HEIGHT = 0.4
PERSON, ROBOT = 1, 2  # hunav_msgs/Agent type constants
SEPARATOR = "=" * 80


@dataclass(frozen=True)
class RosbagExport:
    directory: Path
    storage: str
    frames: int
    counts: dict[str, int]  # messages per topic
    hunav_msgs: str = DEFAULT_HUNAV_MSGS  # the hunav_msgs version of /human_states and /robot_states


ROSBAGS_MODULES = ("rosbags.rosbag2", "rosbags.typesys", "rosbags.interfaces")


def missing_dependency() -> str | None:
    """Why this export cannot run here (its optional dependency is not installed), or None."""
    if missing_extra(ROSBAGS_MODULES) is None:
        return None
    return f"the ROS 2 bag export needs rosbags: {ROS_EXTRA}"


def _rosbags() -> None:
    require_extra("the ROS 2 bag export", "rosbags", ROSBAGS_MODULES, ROS_EXTRA)


def hunav_msgs(version: str) -> HunavMsgs:
    """The shipped hunav_msgs of `version`; RosbagExportError (exit 2) for one GROVE does not ship."""
    try:
        return HUNAV_MSGS[version]
    except KeyError:
        raise RosbagExportError(f"hunav_msgs version {version!r}: GROVE ships {', '.join(HUNAV_MSGS)}",
                                hint="Use --hunav-msgs 2.0 (HuNavSim 2.0, the default) or 1.0.") from None


def ros_typestore(version: str = DEFAULT_HUNAV_MSGS) -> Typestore:
    """ROS 2 Humble's message types plus HuNavSim's hunav_msgs of `version`, registered from the shipped .msg text."""
    _rosbags()
    from rosbags.typesys import Stores, get_types_from_msg, get_typestore

    store = get_typestore(Stores.ROS2_HUMBLE)
    types: Typesdict = {}  # message name -> parsed field definitions
    for msgtype, text in hunav_msgs(version).types().items():
        types.update(get_types_from_msg(text, msgtype))
    store.register(types)
    return store


def _sections(msgdef: str) -> list[tuple[str, str]]:
    """(type name, text) of each part of a ROS 2 message definition; the first part's name is ''."""
    parts = msgdef.split(SEPARATOR + "\n")
    out = [("", parts[0])]
    for part in parts[1:]:
        head, _, body = part.partition("\n")
        out.append((head.removeprefix("MSG: ").strip(), body))
    return out


def hunav_msgdef(store: Typestore, msgtype: str, version: str = DEFAULT_HUNAV_MSGS) -> str:
    """The definition a bag records for a hunav_msgs type: HuNavSim's .msg text verbatim for hunav_msgs
    parts (comments and constants included, as rosbag2 stores it), the generated text for the rest."""
    generated, _ = store.generate_msgdef(msgtype, ros_version=2)
    own = {name.replace("/msg/", "/"): text for name, text in hunav_msgs(version).types().items()}
    main = msgtype.replace("/msg/", "/")
    pieces = []
    for name, text in _sections(generated):
        verbatim = own.get(name or main, text)
        if verbatim and not verbatim.endswith("\n"):
            verbatim += "\n"  # the next part's separator starts on a line of its own
        pieces.append(verbatim if not name else f"{SEPARATOR}\nMSG: {name}\n{verbatim}")
    return "".join(pieces)


# --------------------------------------------------------------------------------------- CDR templates

class _Cdr:
    """Little-endian CDR as ROS 2 writes it: each value aligned to its size, counted from the end of the
    4-byte encapsulation header. Returns the payload offset of each value, for templates to fill in."""

    def __init__(self) -> None:
        self.buf = bytearray(b"\x00\x01\x00\x00")

    def _put(self, fmt: str, value: float | int) -> int:
        size = struct.calcsize(fmt)
        self.buf.extend(b"\x00" * ((-(len(self.buf) - 4)) % size))
        offset = len(self.buf) - 4
        self.buf.extend(struct.pack(fmt, value))
        return offset

    def u8(self, v: int) -> int:
        return self._put("<B", v)

    def i8(self, v: int) -> int:
        return self._put("<b", v)

    def i32(self, v: int) -> int:
        return self._put("<i", v)

    def u32(self, v: int) -> int:
        return self._put("<I", v)

    def f32(self, v: float) -> int:
        return self._put("<f", v)

    def f64(self, v: float) -> int:
        return self._put("<d", v)

    def string(self, text: str) -> None:
        data = text.encode("utf-8") + b"\x00"
        self.u32(len(data))
        self.buf.extend(data)

    def header(self, frame_id: str) -> int:
        """std_msgs/Header with a zero stamp; the offset of its `sec` (`nanosec` follows at +4)."""
        offset = self.i32(0)
        self.u32(0)
        self.string(frame_id)
        return offset

    def pose(self, x: float, y: float, z: float, yaw: float) -> tuple[int, int, int, int]:
        """geometry_msgs/Pose; offsets of position x, y and orientation z, w."""
        ox = self.f64(x)
        oy = self.f64(y)
        self.f64(z)
        self.f64(0.0)
        self.f64(0.0)
        oqz = self.f64(math.sin(yaw / 2))
        oqw = self.f64(math.cos(yaw / 2))
        return ox, oy, oqz, oqw


@dataclass(frozen=True)
class _Static:
    """What a body keeps from frame to frame: from the scenario (exports/scene.py), not the trajectories."""

    id: int
    kind: int
    name: str
    group: int
    radius: float
    max_vel: float
    goal: tuple[float, float] | None
    skin: int = 0
    goal_radius: float = 0.0
    cyclic_goals: bool = False
    behavior: dict[str, float | int | bool] = field(default_factory=dict)  # hunav_msgs/AgentBehavior's fields (scene.behavior_values)


_SLOTS_U32 = frozenset({"sec", "nanosec"})  # stamps; every other slot is a float
_SLOTS_32 = _SLOTS_U32 | {"yaw", "linear_vel", "angular_vel"}  # 4-byte slots; the rest are float64


class _Template:
    """Serialized bytes of one message with the offsets where each frame's numbers go."""

    def __init__(self, cdr: _Cdr, slots: dict[str, list[int]]) -> None:
        self.data = bytes(cdr.buf)
        self.slots = {k: np.asarray(v, dtype=np.int64) for k, v in slots.items()}
        for name, offsets in self.slots.items():
            size = 4 if name in _SLOTS_32 else 8
            if offsets.size and np.any(offsets % size):
                raise AssertionError(f"CDR slot {name} is not aligned")  # a bug in the layout code, never input
            self.slots[name] = offsets // size

    def fill(self, values: dict[str, np.ndarray | float | int]) -> memoryview:
        buf = bytearray(self.data)
        words = (len(buf) - 4) // 4
        f64 = np.frombuffer(buf, dtype="<f8", count=words // 2, offset=4)
        f32 = np.frombuffer(buf, dtype="<f4", count=words, offset=4)
        u32 = np.frombuffer(buf, dtype="<u4", count=words, offset=4)
        for name, value in values.items():
            index = self.slots[name]
            if name in _SLOTS_U32:
                u32[index] = value
            elif name in _SLOTS_32:
                f32[index] = value
            else:
                f64[index] = value
        return memoryview(buf)


def _agent_fields(cdr: _Cdr, body: _Static, slots: dict[str, list[int]], version: str) -> None:
    """hunav_msgs/Agent in the field order of HuNavSim's Agent.msg of `version`, zeros where each frame writes."""
    behavior = body.behavior
    cdr.i32(body.id)
    cdr.u8(body.kind)
    cdr.u8(body.skin)
    if version == "1.0":
        cdr.u8(int(behavior.get("type", 0)))
        cdr.string(body.name)
        cdr.u8(0)  # behavior_state: BEH_NO_ACTIVE (reactions are not recorded in trajectories)
    else:
        cdr.string(body.name)
    cdr.i8(body.group)
    for key, offset in zip(("x", "y", "qz", "qw"), cdr.pose(0.0, 0.0, 0.0, 0.0)):
        slots[key].append(offset)
    slots["yaw"].append(cdr.f32(0.0))
    slots["vx"].append(cdr.f64(0.0))
    slots["vy"].append(cdr.f64(0.0))
    cdr.f64(0.0)
    cdr.f64(0.0)
    cdr.f64(0.0)
    slots["wz"].append(cdr.f64(0.0))
    cdr.f32(body.max_vel)
    cdr.f32(body.radius)
    slots["linear_vel"].append(cdr.f32(0.0))
    slots["angular_vel"].append(cdr.f32(0.0))
    if version != "1.0":  # hunav_msgs/AgentBehavior behavior
        cdr.u8(int(behavior.get("type", 0)))
        cdr.u8(0)  # state: BEH_NO_ACTIVE (reactions are not recorded in trajectories)
        cdr.u8(int(behavior.get("configuration", 0)))
        cdr.f32(float(behavior.get("duration", 0.0)))
        cdr.u8(1 if behavior.get("once") else 0)
        for key in ("vel", "dist", "social_force_factor", "goal_force_factor", "obstacle_force_factor",
                    "other_force_factor"):
            cdr.f32(float(behavior.get(key, 0.0)))
    goals = [] if body.goal is None else [body.goal]
    cdr.u32(len(goals))
    for gx, gy in goals:
        cdr.pose(gx, gy, 0.0, 0.0)
    cdr.u8(1 if body.cyclic_goals else 0)
    cdr.f32(body.goal_radius)
    cdr.u32(0)  # closest_obs: not recorded


def _slots(*names: str) -> dict[str, list[int]]:
    return {name: [] for name in names}


_AGENT_SLOTS = ("x", "y", "qz", "qw", "yaw", "vx", "vy", "wz", "linear_vel", "angular_vel")


def agents_template(bodies: Sequence[_Static], version: str = DEFAULT_HUNAV_MSGS) -> _Template:
    cdr = _Cdr()
    slots = _slots("sec", "nanosec", *_AGENT_SLOTS)
    sec = cdr.header(FRAME_ID)
    slots["sec"].append(sec)
    slots["nanosec"].append(sec + 4)
    cdr.u32(len(bodies))
    for body in bodies:
        _agent_fields(cdr, body, slots, version)
    return _Template(cdr, slots)


def agent_template(body: _Static, version: str = DEFAULT_HUNAV_MSGS) -> _Template:
    cdr = _Cdr()
    slots = _slots(*_AGENT_SLOTS)
    _agent_fields(cdr, body, slots, version)
    return _Template(cdr, slots)


def _marker(cdr: _Cdr, slots: dict[str, list[int]], *, ns: str, marker_id: int, kind: int, action: int,
            scale: tuple[float, float, float], rgba: tuple[float, float, float, float], z: float) -> None:
    """visualization_msgs/Marker (Humble's definition), its stamp and pose left for each frame."""
    sec = cdr.header(FRAME_ID)
    slots["sec"] += [sec]
    slots["nanosec"] += [sec + 4]
    cdr.string(ns)
    cdr.i32(marker_id)
    cdr.i32(kind)
    cdr.i32(action)
    x, y, qz, qw = cdr.pose(0.0, 0.0, z, 0.0)
    if action == 0:
        slots["x"].append(x)
        slots["y"].append(y)
        slots["qz"].append(qz)
        slots["qw"].append(qw)
    for v in scale:
        cdr.f64(v)
    for v in rgba:
        cdr.f32(v)
    cdr.i32(0)  # lifetime: until replaced
    cdr.u32(0)
    cdr.u8(0)  # frame_locked
    cdr.u32(0)  # points
    cdr.u32(0)  # colors
    cdr.string("")  # texture_resource
    cdr.header("")  # texture: an empty sensor_msgs/CompressedImage
    cdr.string("")
    cdr.u32(0)
    cdr.u32(0)  # uv_coordinates
    cdr.string("")  # text
    cdr.string("")  # mesh_resource
    cdr.string("")  # mesh_file.filename
    cdr.u32(0)  # mesh_file.data
    cdr.u8(0)  # mesh_use_embedded_materials


CYLINDER, DELETEALL, ADD = 3, 3, 0


def bodies_template(bodies: Sequence[_Static]) -> _Template:
    """MarkerArray: DELETEALL (people who left vanish), then one cylinder per body, the robot dark grey."""
    cdr = _Cdr()
    slots = _slots("sec", "nanosec", "x", "y", "qz", "qw")
    cdr.u32(len(bodies) + 1)
    _marker(cdr, slots, ns="", marker_id=0, kind=0, action=DELETEALL, scale=(0, 0, 0), rgba=(0, 0, 0, 0), z=0.0)
    for body in bodies:
        person = body.kind == PERSON
        height = PERSON_HEIGHT if person else ROBOT_HEIGHT
        rgba = group_rgba(body.group) if person else (0.15, 0.15, 0.15, 1.0)
        _marker(cdr, slots, ns="people" if person else "robot", marker_id=body.id, kind=CYLINDER, action=ADD,
                scale=(2 * body.radius, 2 * body.radius, height), rgba=rgba, z=height / 2)
    return _Template(cdr, slots)


# --------------------------------------------------------------------------------------------- export

def _stamp(ns: int) -> tuple[int, int]:
    return ns // 1_000_000_000, ns % 1_000_000_000


def _ns(t: float) -> int:
    return int(round(t * 1e9))


def _wrap(a: np.ndarray) -> np.ndarray:
    return (a + np.pi) % (2 * np.pi) - np.pi


class _Turn:
    """Yaw rate per id from consecutive frames (the CSV records yaw, not its rate); 0 on first sight."""

    def __init__(self) -> None:
        self.yaw: dict[int, float] = {}
        self.last: np.ndarray = np.empty(0)
        self.last_ids: np.ndarray = np.empty(0, dtype=np.int64)
        self.t = math.nan

    def rate(self, t: float, ids: np.ndarray, yaw: np.ndarray) -> np.ndarray:
        out = np.zeros(ids.size)
        dt = t - self.t
        if self.last_ids.size and dt > 0:
            if np.array_equal(ids, self.last_ids):
                out = _wrap(yaw - self.last) / dt
            else:
                where = {int(i): k for k, i in enumerate(self.last_ids)}
                for k, i in enumerate(ids.tolist()):
                    j = where.get(i)
                    if j is not None:
                        out[k] = _wrap(yaw[k] - self.last[j]) / dt
        self.last, self.last_ids, self.t = yaw.copy(), ids.copy(), t
        return out


class _Cached:
    """The last template and the bodies it was built for: the set changes seldom (people leave), so
    one entry is enough and memory stays flat."""

    def __init__(self, build: Callable[[tuple[int, ...], bool], _Template]) -> None:
        self.build = build
        self.key: tuple[bytes, bool] | None = None
        self.template: _Template | None = None

    def get(self, ids: np.ndarray, robot: bool = False) -> _Template:
        key = (ids.tobytes(), robot)
        if key != self.key or self.template is None:
            self.template = self.build(tuple(ids.tolist()), robot)
            self.key = key
        return self.template


def _bodies(bundle: SimulatedBundle) -> tuple[dict[int, _Static], _Static | None]:
    people: dict[int, _Static] = {}
    for agent in bundle.scenario.agents:
        if not -128 <= agent.group <= 127:
            raise RosbagExportError(f"{bundle.path / 'scenario.yaml'}: agent {agent.id} is in group {agent.group}; "
                                    "hunav_msgs/Agent's group_id is an int8 (-128..127)")
        people[agent.id] = _Static(agent.id, PERSON, f"agent{agent.id}", agent.group, agent_radius(agent),
                                   agent.max_vel, _final_goal(agent), skin=skin(agent), goal_radius=goal_radius(agent),
                                   cyclic_goals=agent.cyclic_goals, behavior=behavior_values(agent))
    robot = bundle.scenario.robot
    body = None if robot is None else _Static(0, ROBOT, "robot", -1, robot.radius, robot.max_vel, robot.goal)
    return people, body


def _final_goal(agent: AgentSpec) -> tuple[float, float] | None:
    return agent.goals[-1] if agent.goals else None


def is_rosbag_export(path: Path) -> bool:
    """A folder `export_rosbag` wrote (the only kind of non-empty folder it replaces without --overwrite)."""
    return (path / EXPORT_MARKER).is_file()


def export_rosbag(bundle_dir: str | Path, out_dir: str | Path, *, storage: str = "mcap",
                  overwrite: bool = False, hunav_msgs_version: str = DEFAULT_HUNAV_MSGS) -> RosbagExport:
    """Write the simulated bundle as a ROS 2 bag folder `out_dir` (complete, or not at all), its people
    as hunav_msgs of `hunav_msgs_version` ("2.0", HuNavSim 2.0, or "1.0")."""
    if storage not in STORAGES:
        raise RosbagExportError(f"storage must be one of {', '.join(STORAGES)}, got {storage!r}")
    hunav_msgs(hunav_msgs_version)
    _rosbags()
    out = check_output_dir(out_dir, owned=is_rosbag_export, what="GROVE ROS 2 bag export", overwrite=overwrite)
    refuse_overlap(out, bundle_dir, "the bundle being exported")
    bundle = open_simulated_bundle(bundle_dir)
    store = ros_typestore(hunav_msgs_version)
    with atomic_directory(out, owned=is_rosbag_export, what="GROVE ROS 2 bag export", overwrite=overwrite) as stage:
        # rosbags names the storage file after the bag folder: write it in a sub-folder of the final
        # name, then lift its files into the staging folder that takes the output's place.
        inner = stage / out.name
        frames, counts = _write_bag(bundle, store, inner, storage, hunav_msgs_version)
        for entry in os.listdir(inner):
            os.replace(inner / entry, stage / entry)
        os.rmdir(inner)
        (stage / EXPORT_MARKER).write_text("written by grove export rosbag\n", encoding="utf-8")
    return RosbagExport(out, storage, frames, counts, hunav_msgs_version)


def _qos(latched: bool) -> Qos:
    from rosbags.interfaces import Qos, QosDurability, QosHistory, QosLiveliness, QosReliability, QosTime

    default = QosTime(sec=0, nsec=0)
    return Qos(history=QosHistory.KEEP_LAST, depth=1 if latched else 10, reliability=QosReliability.RELIABLE,
               durability=QosDurability.TRANSIENT_LOCAL if latched else QosDurability.VOLATILE,
               deadline=default, lifespan=default, liveliness=QosLiveliness.AUTOMATIC,
               liveliness_lease_duration=default, avoid_ros_namespace_conventions=False)


def _write_bag(bundle: SimulatedBundle, store: Typestore, path: Path, storage: str,
               version: str = DEFAULT_HUNAV_MSGS) -> tuple[int, dict[str, int]]:
    from rosbags.rosbag2 import CompressionFormat, CompressionMode, StoragePlugin, Writer

    people, robot_body = _bodies(bundle)

    def person(i: int) -> _Static:
        try:
            return people[i]
        except KeyError:
            raise RosbagExportError(f"{bundle.trajectories}: person {i} is not an agent of "
                                    f"{bundle.path / 'scenario.yaml'}; simulate the bundle again") from None

    agents = _Cached(lambda ids, _robot: agents_template([person(i) for i in ids], version))
    bodies = _Cached(lambda ids, robot: bodies_template([person(i) for i in ids]
                                                        + ([robot_body] if robot and robot_body else [])))
    robot_agent = None if robot_body is None else agent_template(robot_body, version)
    people_turn, robot_turn = _Turn(), _Turn()

    frames = bundle.frames()
    first = next(frames, None)
    if first is None:
        raise RosbagExportError(f"{bundle.trajectories}: no trajectory rows")
    events = bundle.events
    start = min([_ns(first.t)] + [_ns(e.t) for e in events[:1]])

    writer = Writer(path, version=BAG_VERSION,
                    storage_plugin=StoragePlugin.MCAP if storage == "mcap" else StoragePlugin.SQLITE3)
    if storage == "mcap":
        writer.set_compression(CompressionMode.STORAGE, CompressionFormat.ZSTD)
    scenario = bundle.scenario
    for key, value in (("grove.world", scenario.world), ("grove.preset", scenario.preset),
                       ("grove.prompt", scenario.prompt), ("grove.seed", str(scenario.seed)),
                       ("grove.map", "/map: the scene's static map (walls, furniture), not inflated; the nav2 map "
                                     "of grove export hunav"),
                       ("grove.planning_grid", f"{PLANNING_GRID_TOPIC}: GROVE's planning grid, the building only, "
                                               f"inflated by {bundle.grid.inflation:g} m"),
                       ("hunav_msgs.version", version), ("hunav_msgs.source", hunav_msgs(version).source)):
        writer.set_custom_data(key, value)

    with writer:
        def connect(topic: str, msgtype: str, latched: bool = False) -> Connection:
            qos = [_qos(latched)]
            if msgtype.startswith("hunav_msgs/"):
                return writer.add_connection(topic, msgtype, msgdef=hunav_msgdef(store, msgtype, version),
                                             rihs01=store.hash_rihs01(msgtype), offered_qos_profiles=qos)
            return writer.add_connection(topic, msgtype, typestore=store, offered_qos_profiles=qos)

        human_states = connect("/human_states", "hunav_msgs/msg/Agents")
        agent_markers = connect("/agent_markers", "visualization_msgs/msg/MarkerArray")
        if robot_body is not None:
            robot_states = connect("/robot_states", "hunav_msgs/msg/Agent")
            tf = connect("/tf", "tf2_msgs/msg/TFMessage")
        event_topic = connect("/events", "std_msgs/msg/String")
        for topic, msgtype, latched, data in _static_messages(bundle, store, start):
            writer.write(connect(topic, msgtype, latched), start, data)

        pending = iter(events)
        event = next(pending, None)
        count = 0
        frame: Frame | None = first
        while frame is not None:
            ns = _ns(frame.t)
            while event is not None and _ns(event.t) <= ns:
                writer.write(event_topic, max(_ns(event.t), start), _event_message(store, event))
                event = next(pending, None)
            sec, nanosec = _stamp(ns)
            qz, qw = np.sin(frame.yaw / 2), np.cos(frame.yaw / 2)
            rate = people_turn.rate(frame.t, frame.ids, frame.yaw)
            writer.write(human_states, ns, agents.get(frame.ids).fill({
                "sec": sec, "nanosec": nanosec, "x": frame.x, "y": frame.y, "qz": qz, "qw": qw, "yaw": frame.yaw,
                "vx": frame.vx, "vy": frame.vy, "wz": rate, "linear_vel": np.hypot(frame.vx, frame.vy),
                "angular_vel": rate}))
            x, y = frame.x, frame.y
            robot = frame.robot is not None and robot_agent is not None
            if frame.robot is not None and robot_agent is not None:
                rx, ry, rvx, rvy, ryaw = (float(v) for v in frame.robot)
                rrate = float(robot_turn.rate(frame.t, _ROBOT_IDS, np.array([ryaw]))[0])
                writer.write(robot_states, ns, robot_agent.fill({
                    "x": rx, "y": ry, "qz": math.sin(ryaw / 2), "qw": math.cos(ryaw / 2), "yaw": ryaw, "vx": rvx,
                    "vy": rvy, "wz": rrate, "linear_vel": math.hypot(rvx, rvy), "angular_vel": rrate}))
                writer.write(tf, ns, _transform(store, sec, nanosec, rx, ry, ryaw))
                x, y = np.append(x, rx), np.append(y, ry)
                qz, qw = np.append(qz, math.sin(ryaw / 2)), np.append(qw, math.cos(ryaw / 2))
            writer.write(agent_markers, ns, bodies.get(frame.ids, robot).fill({
                "sec": sec, "nanosec": nanosec, "x": x, "y": y, "qz": qz, "qw": qw}))
            count += 1
            frame = next(frames, None)
        while event is not None:
            writer.write(event_topic, max(_ns(event.t), start), _event_message(store, event))
            event = next(pending, None)
    counts = {c.topic: writer.counts[c.id] for c in writer.connections}
    return count, counts


_ROBOT_IDS = np.zeros(1, dtype=np.int64)


def _header(store: Typestore, ns: int, frame_id: str = FRAME_ID) -> Message:
    T = store.types
    sec, nanosec = _stamp(ns)
    return T["std_msgs/msg/Header"](stamp=T["builtin_interfaces/msg/Time"](sec=sec, nanosec=nanosec),
                                    frame_id=frame_id)


def _pose(store: Typestore, x: float, y: float, z: float = 0.0, yaw: float = 0.0) -> Message:
    T = store.types
    return T["geometry_msgs/msg/Pose"](
        position=T["geometry_msgs/msg/Point"](x=float(x), y=float(y), z=float(z)),
        orientation=T["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=math.sin(yaw / 2), w=math.cos(yaw / 2)))


def _transform(store: Typestore, sec: int, nanosec: int, x: float, y: float, yaw: float) -> memoryview:
    T = store.types
    stamped = T["geometry_msgs/msg/TransformStamped"](
        header=_header(store, sec * 1_000_000_000 + nanosec), child_frame_id=ROBOT_FRAME,
        transform=T["geometry_msgs/msg/Transform"](
            translation=T["geometry_msgs/msg/Vector3"](x=x, y=y, z=0.0),
            rotation=T["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=math.sin(yaw / 2), w=math.cos(yaw / 2))))
    return store.serialize_cdr(T["tf2_msgs/msg/TFMessage"](transforms=[stamped]), "tf2_msgs/msg/TFMessage")


def _event_message(store: Typestore, event: SimEvent) -> memoryview:
    text = json.dumps({"t": event.t, "agent_id": event.agent_id, "kind": event.kind, "detail": event.detail})
    return store.serialize_cdr(store.types["std_msgs/msg/String"](data=text), "std_msgs/msg/String")


def _map_message(grid: OccupancyGrid, store: Typestore, ns: int) -> memoryview:
    """nav_msgs/OccupancyGrid of `grid` (100 occupied, 0 free)."""
    T = store.types
    sec, nanosec = _stamp(ns)
    info = T["nav_msgs/msg/MapMetaData"](
        map_load_time=T["builtin_interfaces/msg/Time"](sec=sec, nanosec=nanosec), resolution=float(grid.resolution),
        width=grid.width, height=grid.height, origin=_pose(store, grid.origin[0], grid.origin[1]))
    # Row-major from the lower-left cell, as nav_msgs wants and the grid is stored.
    data = np.where(grid.occupied, 100, 0).astype(np.int8).ravel()
    return store.serialize_cdr(T["nav_msgs/msg/OccupancyGrid"](header=_header(store, ns), info=info, data=data),
                               "nav_msgs/msg/OccupancyGrid")


def _scene_markers(bundle: SimulatedBundle, store: Typestore, ns: int) -> memoryview:
    """Goals (spheres), routes with their waypoints, velocity fields (arrows) and the robot's goal."""
    T = store.types
    Marker, Point, Color = (T["visualization_msgs/msg/Marker"], T["geometry_msgs/msg/Point"],
                            T["std_msgs/msg/ColorRGBA"])
    Vector3 = T["geometry_msgs/msg/Vector3"]

    def marker(ns_name: str, marker_id: int, kind: int, rgba: Sequence[float], scale: Sequence[float],
               points: Sequence[Sequence[float]] | np.ndarray = (), pose: Message = None) -> Message:
        return Marker(
            header=_header(store, ns), ns=ns_name, id=marker_id, type=kind, action=ADD,
            pose=pose if pose is not None else _pose(store, 0.0, 0.0),
            scale=Vector3(x=float(scale[0]), y=float(scale[1]), z=float(scale[2])),
            color=Color(r=float(rgba[0]), g=float(rgba[1]), b=float(rgba[2]), a=float(rgba[3])),
            lifetime=T["builtin_interfaces/msg/Duration"](sec=0, nanosec=0), frame_locked=False,
            points=[Point(x=float(p[0]), y=float(p[1]), z=float(p[2]) if len(p) > 2 else 0.05) for p in points],
            colors=[], texture_resource="",
            texture=T["sensor_msgs/msg/CompressedImage"](header=_header(store, 0, ""), format="",
                                                         data=np.zeros(0, dtype=np.uint8)),
            uv_coordinates=[], text="", mesh_resource="",
            mesh_file=T["visualization_msgs/msg/MeshFile"](filename="", data=np.zeros(0, dtype=np.uint8)),
            mesh_use_embedded_materials=False)

    SPHERE, LINE_STRIP, LINE_LIST, SPHERE_LIST = 2, 4, 5, 7
    markers = []
    for agent in bundle.scenario.agents:
        rgba = group_rgba(agent.group)
        size = 2 * goal_radius(agent)  # the goal's disc, as agents YAML and hunav_msgs/Agent say
        if agent.goals:
            gx, gy = agent.goals[-1]
            markers.append(marker("goals", agent.id, SPHERE, rgba, (size, size, size),
                                  pose=_pose(store, gx, gy, size / 2)))
            markers.append(marker("routes", agent.id, LINE_STRIP, group_rgba(agent.group, 0.6), (0.04, 0, 0),
                                  points=[agent.start, *agent.goals]))
        if len(agent.goals) > 1:
            markers.append(marker("waypoints", agent.id, SPHERE_LIST, rgba, (size, size, size),
                                  points=agent.goals[:-1]))
    for k, (field_id, field) in enumerate(sorted(bundle.fields.items())):
        segments = arrow_segments(field_arrows(field)).reshape(-1, 2)
        markers.append(marker(f"field/{field_id}", k, LINE_LIST, (0.5, 0.55, 0.55, 0.7), (0.03, 0, 0),
                              points=segments))
    robot = bundle.scenario.robot
    if robot is not None:
        markers.append(marker("robot_goal", 0, SPHERE, (0.0, 0.0, 0.0, 1.0), (0.4, 0.4, 0.4),
                              pose=_pose(store, robot.goal[0], robot.goal[1], 0.2)))
    return store.serialize_cdr(T["visualization_msgs/msg/MarkerArray"](markers=markers),
                               "visualization_msgs/msg/MarkerArray")


def _static_messages(bundle: SimulatedBundle, store: Typestore, ns: int) -> list[tuple[str, str, bool, memoryview]]:
    """(topic, type, latched, data) of what is published once, at the start."""
    T = store.types
    out = [("/map", "nav_msgs/msg/OccupancyGrid", True, _map_message(bundle.scene.static_map, store, ns)),
           (PLANNING_GRID_TOPIC, "nav_msgs/msg/OccupancyGrid", True, _map_message(bundle.grid, store, ns)),
           ("/scenario_markers", "visualization_msgs/msg/MarkerArray", True, _scene_markers(bundle, store, ns))]
    robot = bundle.scenario.robot
    if robot is not None:
        path = list(robot.path) or [robot.start, robot.goal]
        poses = []
        for k, (x, y) in enumerate(path):
            # Each pose faces along its leg; the last one keeps the final leg's heading.
            a, b = (path[k], path[k + 1]) if k + 1 < len(path) else (path[max(k - 1, 0)], path[k])
            heading = math.atan2(b[1] - a[1], b[0] - a[0])
            poses.append(T["geometry_msgs/msg/PoseStamped"](header=_header(store, ns),
                                                            pose=_pose(store, x, y, yaw=heading)))
        out.append(("/plan", "nav_msgs/msg/Path", True, store.serialize_cdr(
            T["nav_msgs/msg/Path"](header=_header(store, ns), poses=poses), "nav_msgs/msg/Path")))
        goal = T["geometry_msgs/msg/PoseStamped"](header=_header(store, ns), pose=_pose(store, *robot.goal))
        out.append(("/goal_pose", "geometry_msgs/msg/PoseStamped", False,
                    store.serialize_cdr(goal, "geometry_msgs/msg/PoseStamped")))
    return out
