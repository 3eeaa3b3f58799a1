"""Export benchmark (run by hand, not a test): a ten-minute, 200-person run as a ROS 2 bag and as a
Foxglove MCAP, against the straightforward way of writing the same bag with rosbags.

    PYTHONPATH=. python bench/rosbag.py [--people 200] [--minutes 10] [--keep DIR]

The bundle is the hospital world with `--people` agents spawned on free cells and a robot; its
trajectories.csv is made by GROVE's own TrajectoryRecorder at the simulator's 20 frames per second
(people walk towards their goal and turn back at walls; one in ten leaves early, so the set of people
changes during the run as it does in evacuations). Making it is not timed: the figures are the
exports alone, CSV parsing included. Target: the ROS 2 bag export under 30 s.

Peer, measured in the same run: rosbags' own path, one message object per person per frame given to
`Typestore.serialize_cdr` (what a script using rosbags' documented API does), timed on a sample of
frames for /human_states and /agent_markers and scaled to the whole run. Wall clock and process CPU
are both printed; on a shared machine the CPU figure is the fairer one. The last line holds the
headline figures as key=value pairs.
"""

from __future__ import annotations

import argparse
import os
import platform
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from grove_tui.crowd.recording import TrajectoryRecorder  # noqa: E402
from grove_tui.exports.frames import open_simulated_bundle  # noqa: E402
from grove_tui.navigation.grid import build_grid  # noqa: E402
from grove_tui.scenario.events import SimEvent, write_events  # noqa: E402
from grove_tui.scenario.model import AgentSpec, RobotSpec, Scenario  # noqa: E402
from grove_tui.world import load_world  # noqa: E402

FPS = 20.0
TREE = ('<root BTCPP_format="4" main_tree_to_execute="agent_{id}"><BehaviorTree ID="agent_{id}">'
        '<GoTo target="goal" x="{x:.2f}" y="{y:.2f}"/></BehaviorTree></root>')


def make_bundle(root: Path, people: int, minutes: float, seed: int = 7) -> Path:
    world = load_world("hospital")
    grid = build_grid(world, 0.1)
    rng = np.random.default_rng(seed)
    free = grid.free_cells()
    cells = free[rng.choice(free.shape[0], size=2 * people + 2, replace=False)]
    points = np.array([grid.cell_to_world(int(r), int(c)) for r, c in cells])
    pt = lambda p: (float(p[0]), float(p[1]))  # noqa: E731  plain floats for the YAML
    starts, goals = points[:people], points[people:2 * people]
    (root / "trees").mkdir(parents=True, exist_ok=True)
    agents = []
    for k in range(people):
        agent_id = k + 1
        (root / "trees" / f"agent_{agent_id}.xml").write_text(TREE.format(id=agent_id, x=goals[k, 0], y=goals[k, 1]))
        agents.append(AgentSpec(id=agent_id, group=k % 40 if k % 3 == 0 else -1, start=pt(starts[k]),
                                goals=(pt(goals[k]),), zone="", tree=f"trees/agent_{agent_id}.xml"))
    robot = RobotSpec(start=pt(points[-2]), goal=pt(points[-1]), path=(pt(points[-2]), pt(points[-1])))
    Scenario(world="hospital", preset="normal", prompt=f"bench: {people} people for {minutes:g} minutes", seed=seed,
             models={}, agents=tuple(agents), robot=robot).save(root / "scenario.yaml")
    grid.save(root / "grid.npz")

    frames = int(minutes * 60 * FPS)
    leave = np.full(people, frames)
    early = rng.choice(people, size=people // 10, replace=False)
    leave[early] = rng.integers(frames // 10, frames, size=early.size)
    pos = starts.copy()
    heading = np.arctan2(goals[:, 1] - starts[:, 1], goals[:, 0] - starts[:, 0])
    robot_pos = np.array(robot.start, dtype=float)
    recorder = TrajectoryRecorder(FPS)
    ids = np.arange(1, people + 1)
    groups = np.array([a.group for a in agents])
    events = []
    dt = 1.0 / FPS
    for f in range(frames):
        heading += rng.normal(0.0, 0.05, people)
        vel = np.column_stack([np.cos(heading), np.sin(heading)])
        nxt = pos + vel * dt
        blocked = np.array([not grid.is_free(x, y) for x, y in nxt])
        heading[blocked] += np.pi
        pos[~blocked] = nxt[~blocked]
        here = leave > f
        robot_pos += 0.5 * dt * np.array([1.0, 0.0]) * (1 if (f // 400) % 2 == 0 else -1)
        t = (f + 1) * dt
        row_ids = np.r_[0, ids[here]]
        recorder.record_frame(t, row_ids, np.r_[robot_pos[0], pos[here, 0]], np.r_[robot_pos[1], pos[here, 1]],
                              np.r_[0.5, vel[here, 0]], np.r_[0.0, vel[here, 1]], np.r_[0.0, heading[here]],
                              np.r_[-1, groups[here]])
        for k in np.flatnonzero(leave == f + 1):
            events.append(SimEvent(t, int(ids[k]), "evacuated", "exit"))
    recorder.write_csv(root / "trajectories.csv")
    recorder.close()
    write_events(root / "events.jsonl", events)
    return root


def timed(fn):
    wall, cpu = time.perf_counter(), time.process_time()
    result = fn()
    return result, time.perf_counter() - wall, time.process_time() - cpu


def naive_rosbags(bundle_dir: Path, sample_frames: int) -> tuple[float, int]:
    """Seconds rosbags' own serializer takes per frame for /human_states + /agent_markers (mean over a sample)."""
    from grove_tui.exports.rosbag import FRAME_ID, PERSON_HEIGHT, ros_typestore

    store = ros_typestore()
    T = store.types
    bundle = open_simulated_bundle(bundle_dir)
    agents = {a.id: a for a in bundle.scenario.agents}
    total = 0.0
    done = 0
    for frame in bundle.frames():
        if done == sample_frames:
            break
        started = time.process_time()
        header = T["std_msgs/msg/Header"](stamp=T["builtin_interfaces/msg/Time"](sec=int(frame.t),
                                          nanosec=int(frame.t % 1 * 1e9)), frame_id=FRAME_ID)
        people, markers = [], []
        for k, i in enumerate(frame.ids.tolist()):
            spec = agents[i]
            pose = T["geometry_msgs/msg/Pose"](
                position=T["geometry_msgs/msg/Point"](x=frame.x[k], y=frame.y[k], z=0.0),
                orientation=T["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=np.sin(frame.yaw[k] / 2),
                                                              w=np.cos(frame.yaw[k] / 2)))
            V = T["geometry_msgs/msg/Vector3"]
            behavior = T["hunav_msgs/msg/AgentBehavior"](  # hunav_msgs 2.0, the export's default
                type=1, state=0, configuration=0, duration=40.0, once=True, vel=1.0, dist=0.0,
                social_force_factor=5.0, goal_force_factor=2.0, obstacle_force_factor=10.0, other_force_factor=20.0)
            people.append(T["hunav_msgs/msg/Agent"](
                id=i, type=1, skin=i % 5, name=f"agent{i}", group_id=spec.group,
                position=pose, yaw=frame.yaw[k],
                velocity=T["geometry_msgs/msg/Twist"](linear=V(x=frame.vx[k], y=frame.vy[k], z=0.0),
                                                      angular=V(x=0.0, y=0.0, z=0.0)),
                desired_velocity=spec.max_vel, radius=spec.radius, linear_vel=0.0, angular_vel=0.0,
                behavior=behavior, goals=[], cyclic_goals=True, goal_radius=spec.goal_radius, closest_obs=[]))
            markers.append(T["visualization_msgs/msg/Marker"](
                header=header, ns="people", id=i, type=3, action=0, pose=pose,
                scale=V(x=0.7, y=0.7, z=PERSON_HEIGHT), color=T["std_msgs/msg/ColorRGBA"](r=0.3, g=0.3, b=0.3, a=1.0),
                lifetime=T["builtin_interfaces/msg/Duration"](sec=0, nanosec=0), frame_locked=False, points=[],
                colors=[], texture_resource="",
                texture=T["sensor_msgs/msg/CompressedImage"](header=header, format="", data=np.zeros(0, np.uint8)),
                uv_coordinates=[], text="", mesh_resource="",
                mesh_file=T["visualization_msgs/msg/MeshFile"](filename="", data=np.zeros(0, np.uint8)),
                mesh_use_embedded_materials=False))
        store.serialize_cdr(T["hunav_msgs/msg/Agents"](header=header, agents=people), "hunav_msgs/msg/Agents")
        store.serialize_cdr(T["visualization_msgs/msg/MarkerArray"](markers=markers),
                            "visualization_msgs/msg/MarkerArray")
        total += time.process_time() - started
        done += 1
    return total / max(done, 1), done


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--people", type=int, default=200)
    parser.add_argument("--minutes", type=float, default=10.0)
    parser.add_argument("--sample", type=int, default=100, help="frames the naive peer is timed on")
    parser.add_argument("--keep", type=Path, default=None, help="keep the bundle and outputs in this folder")
    args = parser.parse_args()

    from grove_tui.exports.foxglove import export_foxglove
    from grove_tui.exports.rosbag import export_rosbag

    work = args.keep or Path(tempfile.mkdtemp(prefix="grove-bench-rosbag-"))
    work.mkdir(parents=True, exist_ok=True)
    print(f"# {platform.processor() or platform.machine()}, {os.cpu_count()} cpus, Python {platform.python_version()}")
    print(f"# load average before the run: {os.getloadavg()[0]:.2f} (other jobs on these cores raise every wall figure)")
    bundle = work / "bundle"
    if not (bundle / "trajectories.csv").is_file():
        _, wall, _ = timed(lambda: make_bundle(bundle, args.people, args.minutes))
        print(f"# made the bundle in {wall:.1f} s (not part of the figures)")
    csv = bundle / "trajectories.csv"
    rows = sum(1 for _ in csv.open("rb")) - 1
    print(f"# bundle: {args.people} people + robot, {args.minutes:g} min at {FPS:g} fps, {rows:,} rows, "
          f"{csv.stat().st_size / 2**20:.0f} MiB of CSV")

    results = {}
    for storage in ("mcap", "sqlite3"):
        out = work / f"bag_{storage}"
        shutil.rmtree(out, ignore_errors=True)
        result, wall, cpu = timed(lambda: export_rosbag(bundle, out, storage=storage))
        size = sum(p.stat().st_size for p in out.iterdir()) / 2**20
        results[storage] = (wall, cpu)
        print(f"rosbag {storage:<8} {wall:6.1f} s wall {cpu:6.1f} s cpu  {result.frames} frames, "
              f"{sum(result.counts.values()):,} messages, {size:.0f} MiB")
    out = work / "scene.mcap"
    result, fox_wall, fox_cpu = timed(lambda: export_foxglove(bundle, out))
    print(f"foxglove mcap    {fox_wall:6.1f} s wall {fox_cpu:6.1f} s cpu  {result.frames} frames, "
          f"{out.stat().st_size / 2**20:.0f} MiB")

    per_frame, sampled = naive_rosbags(bundle, args.sample)
    frames = result.frames
    naive = per_frame * frames
    ours_cpu = results["mcap"][1]
    print(f"rosbags serialize_cdr per message (peer): {per_frame * 1e3:.1f} ms cpu per frame on {sampled} frames "
          f"-> {naive:.0f} s cpu for the run's {frames} frames (/human_states and /agent_markers only)")
    print(f"# ours / peer: the whole export takes {ours_cpu / naive:.2f} of the cpu the peer spends on two topics")
    if args.keep is None:
        shutil.rmtree(work, ignore_errors=True)
    load = os.getloadavg()[0]
    print(f"rosbag_mcap_s={results['mcap'][0]:.1f} rosbag_sqlite3_s={results['sqlite3'][0]:.1f} "
          f"foxglove_s={fox_wall:.1f} peer_two_topics_cpu_s={naive:.0f} speedup_vs_peer={naive / ours_cpu:.1f} "
          f"under_30s={'yes' if results['mcap'][0] < 30 else 'no'} load={load:.2f}")


if __name__ == "__main__":
    main()
