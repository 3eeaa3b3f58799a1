"""Trajectory recording: flat memory on long runs, CSV columns, files PedPy loads."""

from __future__ import annotations

import csv
import tracemalloc

import numpy as np
import pytest

from grove_tui.crowd.crowd import Crowd
from grove_tui.crowd.recording import ROW_DTYPE, RecordingError, TrajectoryRecorder

pedpy = pytest.importorskip("pedpy")


def small_crowd() -> Crowd:
    walls = np.array([[0, 0, 10, 0], [10, 0, 10, 6], [10, 6, 0, 6], [0, 6, 0, 0]], dtype=float)
    crowd = Crowd(walls, dt=0.05)
    for k in range(4):
        crowd.add_agent((1.0 + k, 1.0 + k), goals=[(9.0, 3.0)], group=1 if k < 2 else -1)
    crowd.set_robot((5.0, 5.0), path=[(5.0, 5.0), (2.0, 5.0)])
    return crowd


def test_csv_has_the_contract_columns_robot_id_zero_and_agent_ids_from_one(tmp_path):
    crowd = small_crowd()
    recorder = TrajectoryRecorder(fps=20.0)
    for _ in range(10):
        crowd.step(1)
        recorder.record(crowd)
    out = recorder.write_csv(tmp_path / "traj.csv")
    with open(out, newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert list(rows[0].keys()) == ["frame", "t", "id", "x", "y", "vx", "vy", "yaw", "group"]
    assert len(rows) == 10 * 5
    assert {int(r["id"]) for r in rows} == {0, 1, 2, 3, 4}
    first = [r for r in rows if r["frame"] == "0"]
    robot = next(r for r in first if r["id"] == "0")
    assert float(robot["t"]) == pytest.approx(0.05)
    assert float(robot["x"]) == pytest.approx(crowd.robot_pos[0] + 0.8 * 0.05 * 9, abs=1e-3)
    agent2 = next(r for r in rows if r["frame"] == "9" and r["id"] == "2")
    assert float(agent2["x"]) == pytest.approx(crowd.pos[1, 0], abs=1e-4)
    assert int(agent2["group"]) == 1


def test_id_map_and_inactive_agents(tmp_path):
    crowd = small_crowd()
    crowd.set_active(2, False)
    recorder = TrajectoryRecorder(fps=20.0, id_map={0: 10, 1: 11, 3: 13}, include_robot=False)
    recorder.record(crowd)
    assert sorted(recorder.to_array()["id"].tolist()) == [10, 11, 13]
    with pytest.raises(RecordingError, match="robot's id 0"):
        TrajectoryRecorder(fps=20.0, id_map=[0])


def test_long_run_memory_stays_flat_and_the_whole_run_is_kept():
    recorder = TrajectoryRecorder(fps=20.0, capacity_rows=1000)
    ids = np.arange(1, 21)
    zeros = np.zeros(20)
    fixed = recorder.memory_bytes
    for frame in range(200):  # warm-up: the spill file exists, buffers have cycled
        recorder.record_frame(frame * 0.05, ids, zeros + frame, zeros, zeros, zeros, zeros, zeros - 1)
    tracemalloc.start()
    baseline = tracemalloc.take_snapshot()
    for frame in range(200, 5200):
        recorder.record_frame(frame * 0.05, ids, zeros + frame, zeros, zeros, zeros, zeros, zeros - 1)
    grown = sum(stat.size_diff for stat in tracemalloc.take_snapshot().compare_to(baseline, "filename"))
    tracemalloc.stop()
    assert recorder.memory_bytes == fixed == 1000 * ROW_DTYPE.itemsize
    assert grown < 200_000  # 100,000 rows would be 7.2 MB in memory
    assert len(recorder) == 5200 * 20
    rows = recorder.to_array()
    assert np.array_equal(np.unique(rows["frame"]), np.arange(5200))
    assert np.array_equal(rows["x"], rows["frame"].astype(float))
    recorder.close()


def test_ring_mode_keeps_the_newest_rows():
    recorder = TrajectoryRecorder(fps=10.0, capacity_rows=50, spill=False)
    ids = np.arange(1, 8)
    zeros = np.zeros(7)
    for frame in range(30):
        recorder.record_frame(frame * 0.1, ids, zeros + frame, zeros, zeros, zeros, zeros, zeros)
    rows = recorder.to_array()
    assert len(recorder) == 50 and recorder.dropped_rows == 30 * 7 - 50
    assert rows["frame"][-1] == 29 and np.all(np.diff(rows["frame"]) >= 0)
    assert rows["frame"][0] == 29 - (50 // 7)


def test_pedpy_loads_the_text_and_sqlite_files(tmp_path):
    crowd = small_crowd()
    recorder = TrajectoryRecorder(fps=20.0, capacity_rows=64)  # forces spilling
    for _ in range(40):
        crowd.step(1)
        recorder.record(crowd)
    txt = recorder.write_pedpy_txt(tmp_path / "traj.txt")
    data = pedpy.load_trajectory_from_txt(trajectory_file=txt)
    assert data.frame_rate == 20.0
    assert len(data.data) == 40 * 4
    assert set(data.data["id"]) == {1, 2, 3, 4}

    wkt = "POLYGON ((0 0, 10 0, 10 6, 0 6, 0 0))"
    db = recorder.write_jupedsim_sqlite(tmp_path / "traj.sqlite", wkt)
    data = pedpy.load_trajectory_from_jupedsim_sqlite(trajectory_file=db)
    assert data.frame_rate == 20.0
    assert len(data.data) == 40 * 4
    last = data.data[(data.data["frame"] == 39) & (data.data["id"] == 1)]
    assert float(last["x"].iloc[0]) == pytest.approx(crowd.pos[0, 0], abs=1e-9)
    area = pedpy.load_walkable_area_from_jupedsim_sqlite(trajectory_file=db)
    assert area.polygon.area == pytest.approx(60.0)
    with pytest.raises(RecordingError, match="WKT"):
        recorder.write_jupedsim_sqlite(tmp_path / "bad.sqlite", "")
    assert not (tmp_path / "bad.sqlite").exists()


def test_bad_recorder_input():
    with pytest.raises(RecordingError, match="fps"):
        TrajectoryRecorder(fps=0)
    recorder = TrajectoryRecorder(fps=5)
    with pytest.raises(RecordingError, match="shape"):
        recorder.record_frame(0.0, [1, 2], [0.0], [0.0], [0.0], [0.0], [0.0], [0])


def test_rows_from_reads_only_what_was_recorded_since_across_spill_and_buffer():
    recorder = TrajectoryRecorder(fps=20.0, capacity_rows=64)  # the buffer spills every ~9 frames
    ids = np.arange(1, 8)
    zeros = np.zeros(7)
    read: list[np.ndarray] = []
    start = 0
    for frame in range(100):
        recorder.record_frame(frame * 0.05, ids, zeros + frame, zeros, zeros, zeros, zeros, zeros)
        if frame % 3 == 0:
            read.append(recorder.rows_from(start))
            start = recorder.recorded_rows
    read.append(recorder.rows_from(start))
    assert np.array_equal(np.concatenate(read), recorder.to_array())
    assert recorder.rows_from(recorder.recorded_rows).shape == (0,)
    assert np.array_equal(recorder.rows_from(7 * 50)["frame"], np.repeat(np.arange(50, 100), 7))
    ring = TrajectoryRecorder(fps=10.0, capacity_rows=20, spill=False)
    for frame in range(10):
        ring.record_frame(frame * 0.1, ids, zeros + frame, zeros, zeros, zeros, zeros, zeros)
    assert np.array_equal(ring.rows_from(ring.recorded_rows - 7)["frame"], np.full(7, 9))
    with pytest.raises(RecordingError, match="dropped"):
        ring.rows_from(0)
