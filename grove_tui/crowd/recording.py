"""Trajectory recording with flat memory, and writers for CSV, PedPy text and JuPedSim sqlite.

Rows are held in a fixed-size buffer. With `spill=True` (default) a full buffer is appended to an
anonymous temporary file, so the whole run is kept on disk while memory stays constant; with
`spill=False` the buffer is a ring that keeps only the newest rows.
"""

from __future__ import annotations

import contextlib
import hashlib
import math
import os
import sqlite3
import tempfile
from collections.abc import Iterator, Mapping, Sequence
from pathlib import Path
from typing import IO, TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from grove_tui.files import atomic_file
from grove_tui.errors import RecordingError

if TYPE_CHECKING:
    from grove_tui.crowd.crowd import Crowd

ROW_DTYPE = np.dtype([
    ("frame", np.int64), ("t", np.float64), ("id", np.int64), ("x", np.float64), ("y", np.float64),
    ("vx", np.float64), ("vy", np.float64), ("yaw", np.float64), ("group", np.int64),
])
CSV_COLUMNS = ("frame", "t", "id", "x", "y", "vx", "vy", "yaw", "group")
ROBOT_ID = 0
JUPEDSIM_SQLITE_VERSION = 2


class TrajectoryRecorder:
    """Frames of (id, position, velocity, yaw, group); robot id 0, agent ids index + 1 unless mapped."""

    def __init__(self, fps: float, *, capacity_rows: int = 65536, spill: bool = True,
                 id_map: Mapping[int, int] | Sequence[int] | None = None, include_robot: bool = True) -> None:
        if not (isinstance(fps, (int, float)) and math.isfinite(fps) and fps > 0):
            raise RecordingError(f"TrajectoryRecorder fps must be a positive number, got {fps!r}")
        if capacity_rows < 1:
            raise RecordingError(f"TrajectoryRecorder capacity_rows must be >= 1, got {capacity_rows!r}")
        self.fps = float(fps)
        self.capacity_rows = int(capacity_rows)
        self.spill = bool(spill)
        self.include_robot = include_robot
        self._id_lookup: np.ndarray | None = None
        if id_map is not None:
            self.set_id_map(id_map)
        self._buffer = np.zeros(self.capacity_rows, dtype=ROW_DTYPE)
        self._start = 0          # ring mode: index of the oldest buffered row
        self._count = 0          # rows in the buffer
        self._spilled = 0        # rows in the spill file
        self._dropped = 0        # ring mode: rows overwritten
        self._spill_file: IO[bytes] | None = None
        self.frames = 0

    def set_id_map(self, id_map: Mapping[int, int] | Sequence[int]) -> None:
        """Scenario ids per agent index (index -> id); unmapped indices keep index + 1."""
        pairs = id_map.items() if isinstance(id_map, Mapping) else enumerate(id_map)
        items = [(int(k), int(v)) for k, v in pairs]
        size = max((k for k, _ in items), default=-1) + 1
        lookup = np.arange(1, size + 1, dtype=np.int64)
        for k, v in items:
            if v == ROBOT_ID:
                raise RecordingError(f"id map gives agent {k} the robot's id 0")
            lookup[k] = v
        self._id_lookup = lookup

    # ------------------------------------------------------------------ recording

    def _agent_ids(self, indices: np.ndarray) -> np.ndarray:
        ids = indices.astype(np.int64) + 1
        if self._id_lookup is not None:
            mapped = indices < self._id_lookup.shape[0]
            ids[mapped] = self._id_lookup[indices[mapped]]
        return ids

    def record(self, crowd: Crowd) -> int:
        """Append the crowd's current state (active agents, then the robot) as one frame; returns the frame."""
        active = np.flatnonzero(crowd.active)
        ids = self._agent_ids(active)
        x = crowd.pos[active, 0]
        y = crowd.pos[active, 1]
        vx = crowd.vel[active, 0]
        vy = crowd.vel[active, 1]
        yaw = crowd.yaw[active]
        group = crowd.group[active].astype(np.int64)
        rp = crowd.robot_pos if self.include_robot else None  # None without a robot too
        rv = crowd.robot_vel if self.include_robot else None
        if rp is not None and rv is not None:
            ids = np.concatenate([[ROBOT_ID], ids])
            x = np.concatenate([[rp[0]], x])
            y = np.concatenate([[rp[1]], y])
            vx = np.concatenate([[rv[0]], vx])
            vy = np.concatenate([[rv[1]], vy])
            yaw = np.concatenate([[crowd.robot_yaw], yaw])
            group = np.concatenate([[-1], group])
        return self.record_frame(crowd.time, ids, x, y, vx, vy, yaw, group)

    def record_frame(self, t: float, ids: ArrayLike, x: ArrayLike, y: ArrayLike, vx: ArrayLike, vy: ArrayLike,
                     yaw: ArrayLike, group: ArrayLike) -> int:
        """Append one frame of equally long per-person columns; returns its frame number."""
        columns = [np.asarray(c) for c in (ids, x, y, vx, vy, yaw, group)]
        n = columns[0].shape[0]
        if any(c.shape != (n,) for c in columns):
            raise RecordingError(f"record_frame columns must all have shape ({n},), got {[c.shape for c in columns]}")
        rows = np.empty(n, dtype=ROW_DTYPE)
        rows["frame"] = self.frames
        rows["t"] = float(t)
        for name, column in zip(("id", "x", "y", "vx", "vy", "yaw", "group"), columns):
            rows[name] = column
        self._append(rows)
        self.frames += 1
        return self.frames - 1

    def _append(self, rows: np.ndarray) -> None:
        cap = self.capacity_rows
        offset = 0
        while offset < rows.shape[0]:
            if self._count == cap:
                if self.spill:
                    self._flush()
                else:
                    # Ring: drop the oldest rows to make room.
                    drop = min(rows.shape[0] - offset, cap)
                    self._start = (self._start + drop) % cap
                    self._count -= drop
                    self._dropped += drop
            room = cap - self._count
            take = min(room, rows.shape[0] - offset)
            end = (self._start + self._count) % cap
            first = min(take, cap - end)
            self._buffer[end:end + first] = rows[offset:offset + first]
            if take > first:
                self._buffer[: take - first] = rows[offset + first:offset + take]
            self._count += take
            offset += take

    def _flush(self) -> None:
        if self._count == 0:
            return
        if self._spill_file is None:
            self._spill_file = tempfile.TemporaryFile(prefix="grove-trajectory-")
        self._spill_file.seek(0, os.SEEK_END)
        for chunk in self._buffered_chunks():
            self._spill_file.write(chunk.tobytes())
        self._spilled += self._count
        self._start = 0
        self._count = 0

    def _buffered_chunks(self) -> Iterator[np.ndarray]:
        cap = self.capacity_rows
        first = min(self._count, cap - self._start)
        if first:
            yield self._buffer[self._start:self._start + first]
        if self._count > first:
            yield self._buffer[: self._count - first]

    # ------------------------------------------------------------------ reading

    def __len__(self) -> int:
        """Rows retained (spilled plus buffered)."""
        return self._spilled + self._count

    @property
    def dropped_rows(self) -> int:
        return self._dropped

    @property
    def memory_bytes(self) -> int:
        """Bytes held in memory by the row buffer: fixed at construction."""
        return int(self._buffer.nbytes)

    def chunks(self, chunk_rows: int = 65536) -> Iterator[np.ndarray]:
        """All retained rows in recording order, as structured arrays of at most chunk_rows rows."""
        if self._spill_file is not None and self._spilled:
            self._spill_file.flush()
            row_bytes = ROW_DTYPE.itemsize
            for start in range(0, self._spilled, chunk_rows):
                count = min(chunk_rows, self._spilled - start)
                self._spill_file.seek(start * row_bytes)
                data = self._spill_file.read(count * row_bytes)
                yield np.frombuffer(data, dtype=ROW_DTYPE)
        for chunk in self._buffered_chunks():
            for start in range(0, chunk.shape[0], chunk_rows):
                yield chunk[start:start + chunk_rows]

    @property
    def recorded_rows(self) -> int:
        """Rows recorded since the start, dropped ones included: where `rows_from` would start next."""
        return self._dropped + self._spilled + self._count

    def rows_from(self, start: int) -> np.ndarray:
        """A copy of the rows recorded from row `start` on (counted as `recorded_rows` counts them).

        Reads only those rows from the spill file, so following a long run (the app's live counters)
        costs the new rows each time, not the whole run. Rows a ring buffer dropped cannot be read.
        """
        if start < self._dropped:
            raise RecordingError(f"rows before {self._dropped} were dropped by the ring buffer; asked from {start}")
        index = start - self._dropped
        parts: list[np.ndarray] = []
        if index < self._spilled and self._spill_file is not None:
            self._spill_file.flush()
            row_bytes = ROW_DTYPE.itemsize
            self._spill_file.seek(index * row_bytes)
            parts.append(np.frombuffer(self._spill_file.read((self._spilled - index) * row_bytes), dtype=ROW_DTYPE))
            index = self._spilled
        skip = index - self._spilled
        for chunk in self._buffered_chunks():
            if skip >= chunk.shape[0]:
                skip -= chunk.shape[0]
                continue
            parts.append(chunk[skip:].copy())
            skip = 0
        return np.concatenate(parts) if parts else np.zeros(0, dtype=ROW_DTYPE)

    def to_array(self) -> np.ndarray:
        """Every retained row in one array (memory grows with the run: for tests and small runs)."""
        parts = list(self.chunks())
        return np.concatenate(parts) if parts else np.zeros(0, dtype=ROW_DTYPE)

    def close(self) -> None:
        if self._spill_file is not None:
            self._spill_file.close()
            self._spill_file = None

    def __del__(self) -> None:
        with contextlib.suppress(Exception):
            self.close()

    # ------------------------------------------------------------------ writers

    def write_csv(self, path: str | os.PathLike[str]) -> Path:
        """frame,t,id,x,y,vx,vy,yaw,group with one row per person per frame."""
        fmt = "%d,%.4f,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%d"
        with atomic_file(path) as tmp, open(tmp, "w", encoding="utf-8", newline="\n") as out:
            out.write(",".join(CSV_COLUMNS) + "\n")
            for chunk in self.chunks():
                table = np.column_stack([chunk[name].astype(np.float64) for name in CSV_COLUMNS])
                np.savetxt(out, table, fmt=fmt, delimiter=",")
        return Path(path)

    def write_pedpy_txt(self, path: str | os.PathLike[str], include_robot: bool = False) -> Path:
        """PedPy's text format (`pedpy.load_trajectory_from_txt`): id frame x y z in metres."""
        with atomic_file(path) as tmp, open(tmp, "w", encoding="utf-8", newline="\n") as out:
            out.write(f"# framerate: {self.fps:g}\n# written by GROVE-TUI\n# id frame x/m y/m z/m\n")
            for chunk in self.chunks():
                if not include_robot:
                    chunk = chunk[chunk["id"] != ROBOT_ID]
                if chunk.shape[0] == 0:
                    continue
                table = np.column_stack([chunk["id"].astype(np.float64), chunk["frame"].astype(np.float64),
                                         chunk["x"], chunk["y"], np.zeros(chunk.shape[0])])
                np.savetxt(out, table, fmt="%d %d %.4f %.4f %.4f")
        return Path(path)

    def write_jupedsim_sqlite(self, path: str | os.PathLike[str], walkable_wkt: str,
                              include_robot: bool = False) -> Path:
        """JuPedSim's sqlite trajectory schema (version 2), loadable with
        `pedpy.load_trajectory_from_jupedsim_sqlite` and `load_walkable_area_from_jupedsim_sqlite`."""
        if not isinstance(walkable_wkt, str) or not walkable_wkt.strip():
            raise RecordingError("write_jupedsim_sqlite needs the walkable area as a WKT string")
        geometry_hash = _stable_hash(walkable_wkt)
        with atomic_file(path) as tmp:
            connection = sqlite3.connect(tmp)
            try:
                cur = connection.cursor()
                cur.execute("CREATE TABLE trajectory_data (frame INTEGER NOT NULL, id INTEGER NOT NULL, "
                            "pos_x REAL NOT NULL, pos_y REAL NOT NULL, ori_x REAL NOT NULL, ori_y REAL NOT NULL)")
                cur.execute("CREATE TABLE metadata (key TEXT NOT NULL UNIQUE PRIMARY KEY, value TEXT NOT NULL)")
                cur.execute("CREATE TABLE frame_data (frame INTEGER NOT NULL, geometry_hash INTEGER NOT NULL)")
                cur.execute("CREATE TABLE geometry (hash INTEGER NOT NULL UNIQUE PRIMARY KEY, wkt TEXT NOT NULL)")
                cur.execute("INSERT INTO geometry (hash, wkt) VALUES (?, ?)", (geometry_hash, walkable_wkt))
                bounds = [math.inf, math.inf, -math.inf, -math.inf]
                last_frame = -1
                for chunk in self.chunks():
                    if not include_robot:
                        chunk = chunk[chunk["id"] != ROBOT_ID]
                    if chunk.shape[0] == 0:
                        continue
                    ori_x = np.cos(chunk["yaw"])
                    ori_y = np.sin(chunk["yaw"])
                    cur.executemany(
                        "INSERT INTO trajectory_data VALUES (?, ?, ?, ?, ?, ?)",
                        zip(chunk["frame"].tolist(), chunk["id"].tolist(), chunk["x"].tolist(),
                            chunk["y"].tolist(), ori_x.tolist(), ori_y.tolist()))
                    frames = np.unique(chunk["frame"])
                    frames = frames[frames > last_frame]
                    cur.executemany("INSERT INTO frame_data VALUES (?, ?)",
                                    ((int(f), geometry_hash) for f in frames))
                    if frames.size:
                        last_frame = int(frames[-1])
                    bounds = [min(bounds[0], float(chunk["x"].min())), min(bounds[1], float(chunk["y"].min())),
                              max(bounds[2], float(chunk["x"].max())), max(bounds[3], float(chunk["y"].max()))]
                metadata = {"version": str(JUPEDSIM_SQLITE_VERSION), "fps": f"{self.fps:g}"}
                if math.isfinite(bounds[0]):
                    metadata.update(xmin=repr(bounds[0]), ymin=repr(bounds[1]),
                                    xmax=repr(bounds[2]), ymax=repr(bounds[3]))
                cur.executemany("INSERT INTO metadata VALUES (?, ?)", metadata.items())
                cur.execute("CREATE INDEX frame_id_idx ON trajectory_data (frame, id)")
                connection.commit()
            finally:
                connection.close()
        return Path(path)


def _stable_hash(text: str) -> int:
    """A 63-bit hash that is the same in every process (Python's hash() is salted)."""
    return int.from_bytes(hashlib.sha256(text.encode("utf-8")).digest()[:8], "big") >> 1
