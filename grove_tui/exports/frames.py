"""A simulated bundle read for the streaming exports (ROS 2 bag, Foxglove MCAP): its scenario, world,
grid, fields and events in memory, its trajectories one frame at a time.

trajectories.csv grows with run length and crowd size (a ten-minute run of 200 people is 2.4 million
rows), so it is parsed in blocks of lines and handed out frame by frame: memory stays flat however
long the run.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from grove_tui.crowd.recording import CSV_COLUMNS, ROBOT_ID
from grove_tui.errors import StreamExportError
from grove_tui.navigation.grid import OccupancyGrid
from grove_tui.navigation.velocity_field import VelocityField
from grove_tui.exports.scene import Scene, scene_of
from grove_tui.scenario.bundle import MAX_TRAJECTORY_BYTES, bundle_member, load_bundle, load_bundle_world
from grove_tui.scenario.events import EVENTS_FILE, MAX_EVENTS_BYTES, SimEvent, read_events
from grove_tui.scenario.model import Scenario
from grove_tui.world import World

TRAJECTORIES_FILE = "trajectories.csv"
BLOCK_BYTES = 4 << 20  # lines parsed at a time; bounds memory, large enough to keep numpy busy
ROS_EXTRA = "pip install 'grove-tui[ros]'"  # what the missing-dependency errors tell the user


@dataclass(frozen=True)
class Frame:
    """One recorded instant: the people present (in file order) and the robot, if it was recorded."""

    index: int
    t: float
    ids: np.ndarray  # (N,) int64 person ids
    x: np.ndarray
    y: np.ndarray
    vx: np.ndarray
    vy: np.ndarray
    yaw: np.ndarray
    group: np.ndarray  # (N,) int64, -1 for none
    robot: np.ndarray | None  # x, y, vx, vy, yaw


@dataclass(frozen=True)
class SimulatedBundle:
    path: Path
    scenario: Scenario
    world: World
    grid: OccupancyGrid  # GROVE's planning grid (grid.npz), inflated
    fields: dict[str, VelocityField]
    events: list[SimEvent]
    trajectories: Path
    scene: Scene  # what every export says about the scene: extent, static map, boxes (exports/scene.py)

    def frames(self) -> Iterator[Frame]:
        return iter_frames(self.trajectories)


def open_simulated_bundle(bundle_dir: str | Path) -> SimulatedBundle:
    """The parts of a simulated bundle an export needs; a bundle never simulated is refused up front."""
    root = Path(bundle_dir)
    scenario, trees, fields, grid = load_bundle(root)
    csv = root / TRAJECTORIES_FILE
    if not os.path.lexists(csv):
        raise StreamExportError(f"{csv}: no trajectories yet; simulate first: grove simulate {root}")
    # Inside the bundle, a regular file (not a pipe, not a link to /dev/zero), bounded.
    bundle_member(root, TRAJECTORIES_FILE, "trajectory file", MAX_TRAJECTORY_BYTES)
    world = load_bundle_world(root, scenario)
    events_path = root / EVENTS_FILE
    events = []
    if os.path.lexists(events_path):
        events = sorted(read_events(bundle_member(root, EVENTS_FILE, "event log", MAX_EVENTS_BYTES)),
                        key=lambda e: e.t)
    _check_header(csv)
    documents = {agent.id: trees[agent.tree] for agent in scenario.agents}
    return SimulatedBundle(root, scenario, world, grid, fields, events, csv, scene_of(world, scenario, documents))


def _check_header(path: Path) -> None:
    with path.open("rb") as handle:
        header = handle.readline().decode("utf-8", "replace").strip()
    if header != ",".join(CSV_COLUMNS):
        raise StreamExportError(f"{path}: header must be {','.join(CSV_COLUMNS)}, got {header[:80]!r}")


def _rows(path: Path) -> Iterator[np.ndarray]:
    """(R, 9) float64 blocks of the CSV's rows, in file order."""
    line = 1
    with path.open("rb") as handle:
        handle.readline()
        while True:
            lines = handle.readlines(BLOCK_BYTES)
            if not lines:
                return
            try:
                block = np.loadtxt(lines, delimiter=",", dtype=np.float64, ndmin=2)
            except ValueError as exc:
                raise StreamExportError(f"{path}: bad row after line {line}: {exc}") from None
            if block.shape[1] != len(CSV_COLUMNS):
                raise StreamExportError(f"{path}: rows after line {line} have {block.shape[1]} columns, "
                                        f"expected {len(CSV_COLUMNS)}")
            if not np.isfinite(block).all():
                bad = line + 1 + int(np.flatnonzero(~np.isfinite(block).all(axis=1))[0])
                raise StreamExportError(f"{path}:{bad}: not a finite number")
            line += len(lines)
            yield block


def iter_frames(path: str | Path) -> Iterator[Frame]:
    """The frames of a trajectories.csv in order, parsed a block at a time."""
    path = Path(path)
    carry: np.ndarray | None = None
    last_frame = -1
    last_t = -np.inf
    for block in _rows(path):
        if carry is not None:
            block = np.concatenate([carry, block])
        frame_col = block[:, 0]
        if np.any(np.diff(frame_col) < 0) or frame_col[0] < last_frame:
            raise StreamExportError(f"{path}: rows are not in frame order (the recorder writes them in order; "
                                    "was the file edited?)")
        # The last frame may continue in the next block: keep it back.
        cut = int(np.searchsorted(frame_col, frame_col[-1], side="left"))
        carry = block[cut:]
        ready = block[:cut]
        for frame in _split(ready, path):
            if frame.t < last_t:
                raise StreamExportError(f"{path}: time goes backwards at frame {frame.index}")
            last_t = frame.t
            yield frame
        last_frame = int(frame_col[-1])
    if carry is not None and carry.size:
        for frame in _split(carry, path):
            if frame.t < last_t:
                raise StreamExportError(f"{path}: time goes backwards at frame {frame.index}")
            yield frame


def _split(rows: np.ndarray, path: Path) -> Iterator[Frame]:
    if rows.shape[0] == 0:
        return
    frames = rows[:, 0]
    starts = np.flatnonzero(np.r_[True, frames[1:] != frames[:-1]])
    ends = np.r_[starts[1:], rows.shape[0]]
    for start, end in zip(starts.tolist(), ends.tolist()):
        chunk = rows[start:end]
        ids = chunk[:, 2].astype(np.int64)
        is_robot = ids == ROBOT_ID
        robot = None
        if is_robot.any():
            robot = chunk[np.flatnonzero(is_robot)[0], [3, 4, 5, 6, 7]]
            chunk = chunk[~is_robot]
            ids = ids[~is_robot]
        if np.unique(ids).size != ids.size:
            raise StreamExportError(f"{path}: frame {int(frames[start])} lists a person twice")
        yield Frame(index=int(frames[start]), t=float(rows[start, 1]), ids=ids, x=chunk[:, 3], y=chunk[:, 4],
                    vx=chunk[:, 5], vy=chunk[:, 6], yaw=chunk[:, 7], group=chunk[:, 8].astype(np.int64),
                    robot=robot)


def group_rgba(group: int, alpha: float = 1.0) -> tuple[float, float, float, float]:
    """The picture's colour of a group (grey for people on their own), as RGBA in 0..1."""
    from grove_tui.exports.pictures import GROUP_COLOURS, SOLO_COLOUR

    hexa = SOLO_COLOUR if group < 0 else GROUP_COLOURS[group % len(GROUP_COLOURS)]
    return (int(hexa[1:3], 16) / 255, int(hexa[3:5], 16) / 255, int(hexa[5:7], 16) / 255, alpha)


def field_arrows(field: VelocityField, spacing: float = 1.5, length: float = 0.6) -> np.ndarray:
    """(K, 2, 2) arrow shafts (tail, head) on a `spacing` lattice of the field's reachable cells."""
    h, w = field.vectors.shape[:2]
    stride = max(1, int(round(spacing / field.resolution)))
    rows = np.arange(stride // 2, h, stride)
    cols = np.arange(stride // 2, w, stride)
    rr, cc = np.meshgrid(rows, cols, indexing="ij")
    u = field.vectors[rr, cc, 0].ravel().astype(np.float64)
    v = field.vectors[rr, cc, 1].ravel().astype(np.float64)
    keep = (u != 0) | (v != 0)
    x = field.origin[0] + (cc.ravel()[keep] + 0.5) * field.resolution
    y = field.origin[1] + (rr.ravel()[keep] + 0.5) * field.resolution
    tail = np.column_stack([x, y])
    head = tail + length * np.column_stack([u[keep], v[keep]])
    return np.stack([tail, head], axis=1)


def arrow_segments(arrows: np.ndarray, head: float = 0.2) -> np.ndarray:
    """(3K, 2, 2) line segments that draw each arrow: the shaft and two barbs at the head."""
    tail, tip = arrows[:, 0], arrows[:, 1]
    d = tip - tail
    norm = np.maximum(np.hypot(d[:, 0], d[:, 1]), 1e-9)[:, None]
    back = -d / norm * head
    left = back @ np.array([[np.cos(0.5), np.sin(0.5)], [-np.sin(0.5), np.cos(0.5)]])
    right = back @ np.array([[np.cos(-0.5), np.sin(-0.5)], [-np.sin(-0.5), np.cos(-0.5)]])
    return np.concatenate([arrows, np.stack([tip, tip + left], axis=1), np.stack([tip, tip + right], axis=1)])
