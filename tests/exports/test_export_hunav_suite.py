"""Every case of eval/suite.yaml, generated with the embedded model and exported for HuNavSim, passes
the emulation of HuNavSim 2.0's loader (parameter names and types, non-empty integer goal lists,
global_goals ids that exist), and every tree loads in BehaviorTree.CPP 4 with exactly HuNavSim's node
IDs and declared ports and reaches a final state that HuNavSim's per-step ticking does not undo.

Simulated, every case's trajectories pass PedPy's `is_trajectory_valid` against the exported walkable
area, and every goal of its agents YAML (evacuees' muster points outside included) lies inside the
exported Gazebo world's ground plane and the nav2 map, on free ground (issue 30).

Slow (one real generation per case, about 40 s each on 2 shared cores; the run is well under a second).
"""

from __future__ import annotations

from helpers.paths import REPO

import pytest
import yaml
from helpers.hunavsim_factory import HunavSimFactory
from lxml import etree

from grove_tui.analysis.evaluation import load_suite
from grove_tui.bt.format.hunav_compat import HUNAV_NODES
from grove_tui.exports.hunav import export_hunav
from grove_tui.exports.hunav_loader_check import check_hunav_export
from grove_tui.exports.nav2_map import read_pgm
from grove_tui.exports.trajectories import export_trajectories
from grove_tui.generation.pipeline import GenerationPipeline
from grove_tui.generation.presets import load_preset
from grove_tui.scenario.bundle import write_bundle
from grove_tui.services.session import GroveSession
from grove_tui.world import load_world

pytestmark = pytest.mark.slow
pytest.importorskip("behaviortreepy")

SUITE = REPO / "eval" / "suite.yaml"
CASES = load_suite(SUITE)


def _spread(cases):
    """The default run exports one emergency case (fields lowered to routes out of the door, the most
    lowering); queues and walks are exported from hand-built bundles in test_export_hunav*.py.
    Every case of the suite with `python -m pytest -m long`."""
    sampled = next(c.id for c in cases if c.preset == "emergency")
    return [pytest.param(c, id=c.id, marks=() if c.id == sampled else pytest.mark.long) for c in cases]


SIM_SECONDS = 30.0  # the sampled evacuation has everyone out by then


def _trajectories_validate_and_goals_are_in_the_scene(bundle, export, out) -> None:
    pedpy = pytest.importorskip("pedpy")
    GroveSession().simulate(bundle, SIM_SECONDS)
    sqlite = next(p for p in export_trajectories(bundle, out) if p.suffix == ".sqlite")
    traj = pedpy.load_trajectory_from_jupedsim_sqlite(trajectory_file=sqlite)
    walkable = pedpy.load_walkable_area_from_jupedsim_sqlite(trajectory_file=sqlite)
    invalid = pedpy.get_invalid_trajectory(traj_data=traj, walkable_area=walkable)
    assert invalid.empty, f"{len(invalid)} of {len(traj.data)} positions outside the walkable area"
    params = yaml.safe_load(export.agents_yaml.read_text())["hunav_loader"]["ros__parameters"]
    description = yaml.safe_load(export.map_yaml.read_text())
    occupied = read_pgm((export.map_yaml.parent / description["image"]).read_bytes())[::-1] == 0
    x0, y0 = description["origin"][:2]
    r = description["resolution"]
    root = etree.fromstring(export.world_file.read_bytes())
    ground = next(m for m in root.iter("model") if m.get("name") == "ground_plane")
    cx, cy = map(float, ground.findtext("pose").split()[:2])
    sx, sy = map(float, ground.find("link/visual/geometry/plane/size").text.split())
    for goal in params["global_goals"].values():
        x, y = goal["x"], goal["y"]
        assert abs(x - cx) < sx / 2 and abs(y - cy) < sy / 2, (x, y)
        row, col = int((y - y0) // r), int((x - x0) // r)
        assert 0 <= row < occupied.shape[0] and 0 <= col < occupied.shape[1], (x, y)
        assert not occupied[row, col], (x, y)


@pytest.mark.parametrize("case", _spread(CASES))
def test_suite_case_export_loads_in_hunavsim(case, llm, retriever, tmp_path):
    pipeline = GenerationPipeline(load_world(case.world), load_preset(case.preset), None, llm, retriever)
    bundle = write_bundle(pipeline.run(case.prompt, seed=case.seed), tmp_path / "bundle")
    export = export_hunav(bundle, tmp_path / "hunav")
    assert check_hunav_export(export.agents_yaml) == []
    params = yaml.safe_load(export.agents_yaml.read_text())["hunav_loader"]["ros__parameters"]
    assert all(params[name]["goals"] for name in params["agents"])
    _trajectories_validate_and_goals_are_in_the_scene(bundle, export, tmp_path / "trajectories")
    if case.preset == "emergency":
        events = (bundle / "events.jsonl").read_text()
        assert '"evacuated"' in events, "nobody left: the walkable-area check proved nothing"
    for path in export.trees:
        factory = HunavSimFactory()
        tree = factory.load(path.read_text())
        statuses, routine = [], []
        for _ in range(400):
            statuses.append(tree.tick_once().name)
            routine.append(sum(n for name, n in factory.ticks.items()
                               if name != "StopAndWaitTimerAction" and HUNAV_NODES[name].category == "action"))
        # the root never completes, so BT.CPP never resets it
        assert set(statuses) == {"RUNNING"}, path.name
        root = etree.fromstring(path.read_bytes())
        loops = [el for el in root.iter("Repeat", "KeepRunningUntilFailure", "RetryUntilSuccessful")
                 if el.get("name") != "hold_final_state"]
        if not loops:  # a routine that does not loop by design ends, and stays ended
            assert routine[-1] == routine[-50], f"{path.name} restarts its routine"
