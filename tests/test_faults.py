"""kill -9 at a write point leaves the old state or the new, never a torn file; the next run leaves no staging.

A sample in CI (one child process per kill, about 5 s each on a busy 2-core machine): a bundle replaced by
`import hunav` killed after the swap, `simulate` killed before it, `grove metrics` killed between writing and
renaming metrics.json, and the batch's record append and index write. `python bench/hostile.py --faults`
kills generate, batch (state append and index included), import, simulate, metrics and every export at every
write point and checks the same (docs/HOSTILE.md holds a run); the `long` test below does that sweep for the
commands that need no model.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from helpers.faults import killed, run_grove, snapshot, staging_left, sweep, whole_json_lines
from helpers.hunav_files import params, write_scenario

from grove_tui.services.session import GroveSession

SIMULATED_SECONDS = 2.0  # the `simulated` fixture's run (tests/conftest.py)


@pytest.mark.slow
def test_import_killed_after_the_swap_leaves_the_new_bundle_and_the_next_run_no_staging(tmp_path):
    from grove_tui.services.session import GroveSession
    import_hunav = GroveSession().import_hunav

    older = params()
    older["agent1"]["max_vel"] = 0.9
    old_yaml = write_scenario(tmp_path / "old", older)
    new_yaml = write_scenario(tmp_path / "new")
    out = tmp_path / "out" / "bundle"
    import_hunav(old_yaml, out)
    old = snapshot(out)
    import_hunav(new_yaml, tmp_path / "reference")
    new = snapshot(tmp_path / "reference")
    for point in ("dir:bundle:staged", "dir:bundle:exchanged"):
        done = run_grove(["import", "hunav", new_yaml, "--out", out], kill_at=point)
        assert killed(done), done.stderr[-1000:]
        assert snapshot(out) in (old, new), point
        assert staging_left(out.parent)  # what kill -9 leaves: the staging folder (new, or the old bundle)
        import_hunav(old_yaml, out)  # the next run
        assert snapshot(out) == old and staging_left(out.parent) == [], point


@pytest.mark.slow
def test_simulate_killed_before_the_swap_keeps_the_old_run(simulated, tmp_path):
    bundle = tmp_path / "bundle"
    shutil.copytree(simulated, bundle)
    old = snapshot(bundle)
    done = run_grove(["simulate", bundle, "--seconds", "1"], kill_at="dir:bundle:staged")
    assert killed(done), done.stderr[-1000:]
    assert snapshot(bundle) == old and staging_left(tmp_path)
    GroveSession().simulate(bundle, 1.0)
    assert staging_left(tmp_path) == [] and snapshot(bundle) != old


@pytest.mark.slow
def test_metrics_killed_before_the_rename_keeps_the_old_file(simulated, tmp_path):
    bundle = tmp_path / "bundle"
    shutil.copytree(simulated, bundle)
    (bundle / "metrics.json").write_text('{"robot": {}, "crowd": {"old": 1}}\n')
    old = (bundle / "metrics.json").read_bytes()
    done = run_grove(["metrics", bundle], kill_at="file:metrics.json:written")
    assert killed(done), done.stderr[-1000:]
    assert (bundle / "metrics.json").read_bytes() == old and staging_left(bundle)
    from grove_tui.analysis.bundle_metrics import bundle_metrics

    bundle_metrics(bundle)
    assert staging_left(bundle) == [] and "old" not in json.loads((bundle / "metrics.json").read_text())["crowd"]


_APPEND = """
from pathlib import Path
from grove_tui.services.dataset import JobRecord, append_record
out = Path(sys.argv[4])
for n in range(1, 4):
    append_record(out, JobRecord(f"job-{n}", n, f"h{n}", "ok", agents=n))
"""
_INDEX = """
from pathlib import Path
from grove_tui.services.dataset import write_index
write_index(Path(sys.argv[4]), [])
"""


@pytest.mark.parametrize("point, occurrence", [("append:batch-state.jsonl:before", 2),
                                               ("append:batch-state.jsonl:after", 3)])
def test_the_batch_record_append_killed_keeps_whole_lines(tmp_path, point, occurrence):
    from grove_tui.services.dataset import STATE_FILE, JobRecord, append_record, read_records

    out = tmp_path / "out"
    done = run_grove([out], kill_at=point, occurrence=occurrence, body=_APPEND)
    assert killed(done), done.stderr[-1000:]
    assert whole_json_lines(out / STATE_FILE)
    before = read_records(out)
    append_record(out, JobRecord("job-9", 9, "h9", "ok"))  # the next run's record
    after = read_records(out)
    assert set(after) == set(before) | {"job-9"} and whole_json_lines(out / STATE_FILE)


def test_the_index_write_killed_keeps_the_old_index_and_the_next_run_cleans_up(tmp_path):
    from grove_tui.services.dataset import INDEX_FILE, write_index

    out = tmp_path / "out"
    out.mkdir()
    write_index(out, [])
    old = (out / INDEX_FILE).read_bytes()
    done = run_grove([out], kill_at="file:dataset.sqlite:written", body=_INDEX)
    assert killed(done), done.stderr[-1000:]
    assert (out / INDEX_FILE).read_bytes() == old and staging_left(out)
    write_index(out, [])
    assert staging_left(out) == [] and sorted(p.name for p in out.iterdir()) == [INDEX_FILE]


@pytest.mark.slow
@pytest.mark.long
@pytest.mark.parametrize("command", ["import", "simulate", "metrics", "trajectories", "hunav", "rosbag", "foxglove"])
def test_every_write_point_of_the_commands_without_a_model(simulated, tmp_path, command):
    """The sweep bench/hostile.py --faults runs, for one command: kill at every point, then run again."""
    if command in ("rosbag", "foxglove"):
        pytest.importorskip("rosbags" if command == "rosbag" else "foxglove")
    bundle = tmp_path / "bundle"
    shutil.copytree(simulated, bundle)
    out = tmp_path / "out"
    yaml_path = write_scenario(tmp_path / "scenario")
    args = {"import": ["import", "hunav", yaml_path, "--out", out / "imported"],
            "simulate": ["simulate", bundle, "--seconds", "1"], "metrics": ["metrics", bundle],
            "trajectories": ["export", "trajectories", bundle, "--out", out / "traj"],
            "hunav": ["export", "hunav", bundle, "--out", out / "hunav"],
            "rosbag": ["export", "rosbag", bundle, "--out", out / "bag"],
            "foxglove": ["export", "foxglove", bundle, "--out", out / "run.mcap"]}[command]
    results = sweep(args, [bundle] if command in ("simulate", "metrics") else [out])
    assert results and all(r["killed"] for r in results)
    assert [r for r in results if r["state"] != "old or new" or not r["next_run_clean"]] == []
