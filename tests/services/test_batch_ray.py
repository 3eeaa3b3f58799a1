"""`grove batch --ray`: a real local Ray (loopback, 2 workers) gives the bundles of the one-process
batch byte for byte; failures are recorded without stopping the batch; resume skips completed jobs;
dataset.sqlite indexes every scenario; workers that send their files back to the driver (--ray-return)
give the same bundles. Short jobs with the embedded model."""

from __future__ import annotations

import json
import os
import shutil
import sqlite3
from pathlib import Path

import pytest
from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.errors import EXIT_RUNTIME_FAILURE
from grove_tui.services.dataset import STATE_FILE, read_records

# One world and preset: each process (and each Ray worker) builds its pipeline once, which dominates a
# short batch on a loaded 2-core machine.
JOBS = [
    {"world": "hospital", "preset": "normal", "prompt": "a few visitors walk to the cafeteria", "seed": 1,
     "name": "visitors", "variations": 4},
    {"world": "hospital", "preset": "normal", "prompt": "Two nurses walk to the pharmacy", "name": "nurses",
     "variations": 2},
    # The hospital has no swimming pool: this job fails, the six others must still be written.
    {"world": "hospital", "preset": "normal", "prompt": "Ten people swim in the swimming pool", "name": "pool"},
]
GOOD = ["visitors-v000", "visitors-v001", "visitors-v002", "visitors-v003", "nurses-v000", "nurses-v001"]


@pytest.fixture(autouse=True)
def shared_index(monkeypatch):
    if os.environ.get("GROVE_TEST_CACHE_DIR"):
        monkeypatch.setenv("GROVE_CACHE_DIR", os.environ["GROVE_TEST_CACHE_DIR"])


def _files(bundle: Path) -> dict[str, bytes]:
    """Every file of the bundle but generation.json, whose stage timings differ from run to run."""
    return {str(p.relative_to(bundle)): p.read_bytes() for p in sorted(bundle.rglob("*"))
            if p.is_file() and p.name != "generation.json"}


def _batch(jobs: Path, out: Path, *extra: str):
    return CliRunner().invoke(main, ["batch", str(jobs), "--out", str(out), *extra], catch_exceptions=False)


@pytest.mark.slow
@pytest.mark.ray
@pytest.mark.timeout(2400)  # two batches of 7 jobs and a resume of 2; about 10 minutes at load average 12 on 2 cores
def test_ray_batch_matches_one_process_records_failures_and_resumes(tmp_path):
    # Here, not at module level: the resume test below needs no Ray and runs without the extra.
    ray = pytest.importorskip("ray", reason="the cluster extra is not installed (./install.sh cluster)")
    jobs = tmp_path / "jobs.jsonl"
    jobs.write_text("".join(json.dumps(job) + "\n" for job in JOBS), encoding="utf-8")

    single = _batch(jobs, tmp_path / "single")
    on_ray = _batch(jobs, tmp_path / "ray", "--ray", "--workers", "2")
    for result in (single, on_ray):
        assert result.exit_code == EXIT_RUNTIME_FAILURE, result.output  # one job failed, the batch went on
        assert "6/7 scenarios generated" in result.stderr
    assert not ray.is_initialized(), "the batch shuts down the Ray it started"

    for name in GOOD:
        reference = _files(tmp_path / "single" / name)
        assert "scenario.yaml" in reference and any(key.startswith("trees/") for key in reference)
        assert _files(tmp_path / "ray" / name) == reference, name
        report = json.loads((tmp_path / "ray" / name / "generation.json").read_text(encoding="utf-8"))
        if name.startswith("visitors"):
            assert report["variation"]["index"] == int(name[-3:])
            assert report["variation"]["parent_prompt"] == JOBS[0]["prompt"]

    for out in (tmp_path / "single", tmp_path / "ray"):
        records = read_records(out)
        assert {n for n, r in records.items() if r["status"] == "ok"} == set(GOOD)
        failed = records["pool"]
        assert failed["status"] == "failed" and "swimming pool" in failed["message"]
        assert failed["exit_code"] in (2, 3) and not (out / "pool").exists()
        with sqlite3.connect(out / "dataset.sqlite") as db:
            rows = dict(db.execute("SELECT name, status FROM scenarios").fetchall())
            variations = db.execute("SELECT variation, variations, parent_seed FROM scenarios "
                                    "WHERE name = 'visitors-v002'").fetchone()
        assert rows == {**{name: "ok" for name in GOOD}, "pool": "failed"}
        assert variations == (2, 4, 1)

    summary = CliRunner().invoke(main, ["dataset", "summary", str(tmp_path / "ray")])
    assert summary.exit_code == 0, summary.output
    assert "scenarios: 7 (ok 6, failed 1, pending 0)" in summary.stdout
    assert "failed pool" in summary.stdout

    # Resume on Ray, the worker sending its files back (--ray-return, as workers without the driver's
    # file system do): the bundle removed here and the failed job run again, the five others are not
    # written again, and the returned bundle is the one-process bundle byte for byte. One worker: a
    # second would only load another model copy for the failing job, which fails before the model.
    # visitors-v000 is the first job of its process in both runs, so this compares the transfer alone;
    # whether a job's bundle depends on the jobs its worker ran before is the comparison above.
    gone = "visitors-v000"
    shutil.rmtree(tmp_path / "ray" / gone)
    kept = [name for name in GOOD if name != gone]
    stamps = {name: (tmp_path / "ray" / name / "scenario.yaml").stat().st_mtime_ns for name in kept}
    resumed = _batch(jobs, tmp_path / "ray", "--ray", "--workers", "1", "--resume", "--ray-return")
    assert resumed.exit_code == EXIT_RUNTIME_FAILURE, resumed.output
    assert "resume: 5 completed job(s) skipped, 2 to run" in resumed.stderr
    assert {name: (tmp_path / "ray" / name / "scenario.yaml").stat().st_mtime_ns for name in kept} == stamps
    assert _files(tmp_path / "ray" / gone) == _files(tmp_path / "single" / gone)
    assert not list((tmp_path / "ray").glob(".grove-ray-probe-*")), "the driver removes its probe file"
    assert len((tmp_path / "ray" / STATE_FILE).read_text(encoding="utf-8").splitlines()) == 9
    assert {n for n, r in read_records(tmp_path / "ray").items() if r["status"] == "ok"} == set(GOOD)


@pytest.mark.slow
def test_resume_reruns_only_jobs_whose_inputs_changed(tmp_path):
    jobs = tmp_path / "jobs.jsonl"
    first = [{"world": "residential", "preset": "normal", "prompt": "Two children walk to the kitchen", "name": "a"},
             {"world": "residential", "preset": "normal", "prompt": "Two children walk to the kitchen", "name": "b"}]
    jobs.write_text("".join(json.dumps(job) + "\n" for job in first), encoding="utf-8")
    out = tmp_path / "out"
    assert _batch(jobs, out).exit_code == 0
    stamp_a = (out / "a" / "scenario.yaml").stat().st_mtime_ns
    old_b = (out / "b" / "scenario.yaml").read_bytes()

    first[1]["seed"] = 9  # b's inputs change; a's do not
    jobs.write_text("".join(json.dumps(job) + "\n" for job in first), encoding="utf-8")
    resumed = _batch(jobs, out, "--resume")
    assert resumed.exit_code == 0, resumed.output
    assert "resume: 1 completed job(s) skipped, 1 to run" in resumed.stderr
    assert (out / "a" / "scenario.yaml").stat().st_mtime_ns == stamp_a
    assert (out / "b" / "scenario.yaml").read_bytes() != old_b
    assert f"ok {out / 'b'}" in resumed.stdout and f"ok {out / 'a'}" not in resumed.stdout
