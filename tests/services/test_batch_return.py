"""A Ray worker without the driver's file system sends a job's files back and the driver writes them
(services.cluster): what the driver writes is what the worker wrote, atomically, within a size bound,
and nothing outside the job's own names. No Ray needed: these are the two ends of the transfer; the
Ray test (test_batch_ray.py) runs them through real actors."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from grove_tui.errors import BundleError, OutputError, RuntimeFailure
from grove_tui.exports.hunav import export_hunav
from grove_tui.files import relative_file, write_files_atomic
from grove_tui.scenario.bundle import load_bundle, write_bundle_files
from grove_tui.services.cluster import BatchWorker, collect_job_files, write_returned_files
from helpers.handmade import build_hospital_bundle


def _tree(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


@pytest.fixture(scope="module")
def job_folder(tmp_path_factory) -> Path:
    """What a worker's private folder holds after a job with a HuNavSim export: NAME/ and NAME.hunav/."""
    local = tmp_path_factory.mktemp("worker")
    build_hospital_bundle(local / "visit-v001")
    export_hunav(local / "visit-v001", local / "visit-v001.hunav")
    return local


def test_returned_files_are_written_as_the_worker_wrote_them(job_folder, tmp_path):
    files = collect_job_files(job_folder)
    assert {rel.split("/")[0] for rel, _ in files} == {"visit-v001", "visit-v001.hunav"}
    out = tmp_path / "out"
    out.mkdir()
    write_returned_files(out, "visit-v001", files, overwrite=False)
    assert _tree(out) == _tree(job_folder)
    scenario, trees, _fields, _grid = load_bundle(out / "visit-v001")
    assert len(scenario.agents) == 5 and len(trees) == 5

    # Again over the old bundle (a rerun of the job): replaced in one swap, no staging folder left.
    write_returned_files(out, "visit-v001", files, overwrite=False)
    assert _tree(out) == _tree(job_folder)
    assert sorted(p.name for p in out.iterdir()) == ["visit-v001", "visit-v001.hunav"]


def test_the_driver_refuses_files_that_are_not_the_jobs(job_folder, tmp_path):
    files = collect_job_files(job_folder)
    with pytest.raises(RuntimeFailure, match="not job 'other'"):
        write_returned_files(tmp_path, "other", files, overwrite=False)
    exports_only = tuple((rel, data) for rel, data in files if rel.startswith("visit-v001.hunav/"))
    with pytest.raises(RuntimeFailure, match="no bundle"):
        write_returned_files(tmp_path, "visit-v001", exports_only, overwrite=False)
    with pytest.raises(OutputError, match="plain relative file path"):
        write_returned_files(tmp_path, "visit-v001", (("visit-v001/../escape.txt", b"x"),) + files, overwrite=False)
    assert not (tmp_path / "escape.txt").exists() and not (tmp_path / "visit-v001").exists()


def test_a_folder_that_is_not_a_bundle_is_kept_unless_overwrite(job_folder, tmp_path):
    files = collect_job_files(job_folder)
    mine = tmp_path / "visit-v001"
    mine.mkdir()
    (mine / "notes.txt").write_text("my notes", encoding="utf-8")
    with pytest.raises(OutputError, match="is not a scenario bundle"):
        write_returned_files(tmp_path, "visit-v001", files, overwrite=False)
    assert (mine / "notes.txt").read_text(encoding="utf-8") == "my notes"
    write_returned_files(tmp_path, "visit-v001", files, overwrite=True)
    assert not (mine / "notes.txt").exists() and (mine / "scenario.yaml").is_file()


def test_the_worker_bounds_what_it_sends_and_sends_only_regular_files(job_folder, tmp_path):
    total = sum(p.stat().st_size for p in job_folder.rglob("*") if p.is_file())
    assert len(collect_job_files(job_folder, limit=total)) == len(_tree(job_folder))
    with pytest.raises(RuntimeFailure, match="exceed the"):
        collect_job_files(job_folder, limit=total - 1)
    local = tmp_path / "worker"
    (local / "job").mkdir(parents=True)
    (local / "job" / "scenario.yaml").write_text("x", encoding="utf-8")
    os.symlink("/etc/hostname", local / "job" / "link.txt")
    with pytest.raises(RuntimeFailure, match="link.txt: the job wrote something other than a regular file"):
        collect_job_files(local)


def test_a_bundle_sent_as_bytes_needs_its_scenario_file(tmp_path):
    with pytest.raises(BundleError, match="no scenario.yaml"):
        write_bundle_files({"grid.npz": b""}, tmp_path / "b")
    assert not (tmp_path / "b").exists()


@pytest.mark.parametrize("rel", ["", "/etc/passwd", "a/../b", "./a", "a//b", "a\\b", "a/"])
def test_relative_file_refuses_paths_that_leave_or_blur_the_folder(rel):
    with pytest.raises(OutputError):
        relative_file(rel)


def test_write_files_atomic_refuses_a_name_used_as_file_and_folder(tmp_path):
    with pytest.raises(OutputError, match="named twice"):
        write_files_atomic(tmp_path / "t", {"a": b"1", "a/b": b"2"}, owned=lambda _p: True)
    assert not (tmp_path / "t").exists() and list(tmp_path.iterdir()) == []


@pytest.mark.slow  # the actor body starts loading its models at once (a real llama.cpp worker)
def test_a_worker_sees_the_drivers_folder_only_by_the_probe_token(tmp_path):
    worker = BatchWorker(None, None, None)  # an actor starts warming up its session at once
    try:
        probe = tmp_path / ".grove-ray-probe-1"
        probe.write_text("token-1", encoding="ascii")
        assert worker.sees(str(probe), "token-1")
        assert not worker.sees(str(probe), "token-2"), "another driver's probe"
        assert not worker.sees(str(tmp_path / "elsewhere" / probe.name), "token-1"), "a folder it does not have"
    finally:  # a warm-up left running would load models into the tests after this one
        worker.session.stop_warm_up(worker.warming)
        worker.session.close()


def test_ray_return_without_ray_is_a_usage_error(tmp_path):
    from click.testing import CliRunner

    from grove_tui.cli import main

    jobs = tmp_path / "jobs.jsonl"
    jobs.write_text('{"world": "hospital", "preset": "normal", "prompt": "Two nurses walk"}\n', encoding="utf-8")
    result = CliRunner().invoke(main, ["batch", str(jobs), "--out", str(tmp_path / "out"), "--ray-return"])
    assert result.exit_code == 2
    assert "--ray-return sends files from Ray workers: use it with --ray" in result.output
    assert not (tmp_path / "out").exists()
