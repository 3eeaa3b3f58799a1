"""`grove batch --ray`: a real Ray cluster started with `ray start --head` on loopback (2 CPUs, 2 workers)
gives the bundles of the one-process batch byte for byte; failures are recorded without stopping the
batch; resume skips completed jobs; dataset.sqlite indexes every scenario; workers that send their files
back to the driver (--ray-return) give the same bundles; the cluster's workers import the driver's
grove_tui, not the environment's install. Short jobs with the embedded model."""

from __future__ import annotations

import json
import os
import secrets
import shutil
import signal
import socket
import sqlite3
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest
from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.errors import EXIT_RUNTIME_FAILURE
from grove_tui.services.cluster import package_fingerprint
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


pytestmark = pytest.mark.usefixtures("shared_index")  # tests/conftest.py


def _files(bundle: Path) -> dict[str, bytes]:
    """Every file of the bundle but generation.json, whose stage timings differ from run to run."""
    return {str(p.relative_to(bundle)): p.read_bytes() for p in sorted(bundle.rglob("*"))
            if p.is_file() and p.name != "generation.json"}


def _batch(jobs: Path, out: Path, *extra: str):
    return CliRunner().invoke(main, ["batch", str(jobs), "--out", str(out), *extra], catch_exceptions=False)


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


# `ray start` on a loaded 2-core machine takes 10-20 s; past this the cluster is not coming up.
CLUSTER_START_SECONDS = 240


@contextmanager
def loopback_cluster(cpus: int) -> Iterator[tuple[str, dict[str, str]]]:
    """A Ray head started with `ray start --head` on 127.0.0.1, stopped on exit even on failure.

    Yields its address and the environment a driver needs to join it. Ray reads these variables when
    it is imported, so drivers run as processes of their own, as `grove batch` runs for a user.
    Not `ray stop` afterwards: it stops every Ray process of the machine, other people's runs included.
    `ray start --block` stays in the foreground as the cluster's parent, so ending that process (and
    the process group it leads) stops this cluster and nothing else.
    """
    # Ray's unix sockets live under the temp dir and their paths must stay under 108 bytes.
    temp_dir = tempfile.mkdtemp(prefix="grove-ray-")
    port = _free_port()
    env = {key: value for key, value in os.environ.items() if key not in ("PYTHONPATH", "RAY_ADDRESS")}
    env.update({
        # Ray rewrites 127.0.0.1 into the machine's routable address unless it runs as a one-node
        # cluster, which this switch (named for Windows and macOS, read everywhere) makes it; then the
        # GCS and the raylet listen on loopback only.
        "RAY_ENABLE_WINDOWS_OR_OSX_CLUSTER": "0",
        # Ray 2.60 starts clusters with token authentication: this cluster's token, for it and its drivers.
        "RAY_AUTH_MODE": "token", "RAY_AUTH_TOKEN": secrets.token_hex(32)})
    log_path = Path(temp_dir) / "ray-start.log"
    command = [str(Path(sys.executable).parent / "ray"), "start", "--head", "--block",
               "--node-ip-address", "127.0.0.1", "--port", str(port), "--num-cpus", str(cpus),
               "--include-dashboard", "false", "--disable-usage-stats", "--temp-dir", temp_dir,
               # Fixed defaults (10001, 52365, 8265) would collide with another cluster on this machine.
               "--ray-client-server-port", str(_free_port()), "--dashboard-agent-listen-port", str(_free_port()),
               "--dashboard-port", str(_free_port())]
    # The cluster starts without the driver's PYTHONPATH: its workers would import whatever grove_tui
    # this environment has installed, unless the batch gives them its own (what the test checks).
    with log_path.open("wb") as log:
        head = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, cwd=temp_dir, env=env,
                                start_new_session=True)
    try:
        deadline = time.monotonic() + CLUSTER_START_SECONDS
        while b"Ray runtime started" not in log_path.read_bytes():
            if head.poll() is not None or time.monotonic() > deadline:
                pytest.fail(f"ray start did not come up:\n{log_path.read_text(errors='replace')[-3000:]}")
            time.sleep(0.5)
        yield f"127.0.0.1:{port}", env
    finally:
        head.terminate()  # the head drains, then stops its GCS, raylet and workers
        try:
            head.wait(timeout=90)
        except subprocess.TimeoutExpired:
            pass
        try:  # whatever of this cluster outlived its parent (start_new_session: the group is the cluster's)
            os.killpg(head.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        head.wait()
        shutil.rmtree(temp_dir, ignore_errors=True)


def _grove(env: dict[str, str], cwd: Path, *args: str) -> subprocess.CompletedProcess[str]:
    """`python -m grove_tui ARGS` as a user runs it, importing this checkout's grove_tui."""
    driver_env = {**env, "PYTHONPATH": CHECKOUT}
    return subprocess.run([sys.executable, "-m", "grove_tui", *args], cwd=cwd, env=driver_env,
                          capture_output=True, text=True, timeout=1800)


# The folder holding the grove_tui this test imports: the driver's code, which the workers must run.
CHECKOUT = str(Path(package_fingerprint()[0]).parent)
# Joins the cluster as `grove batch --ray ADDRESS` does and prints where a task there imports grove_tui
# from, and from where the driver does.
WHERE_WORKERS_IMPORT = """
import json, sys
import ray
from grove_tui.services.cluster import _connect, package_fingerprint
if __name__ == "__main__":
    _connect(ray, sys.argv[1], None)
    on_a_worker = ray.remote(lambda: package_fingerprint())  # the worker imports grove_tui.services.cluster
    print(json.dumps([ray.get(on_a_worker.remote()), package_fingerprint()]))
    ray.shutdown()
"""


@pytest.mark.slow
@pytest.mark.ray
@pytest.mark.timeout(2400)  # two batches of 7 jobs and a resume of 2: 3.2 min at load average 6, ~10 at 12, on 2 cores
def test_ray_cluster_batch_matches_one_process_records_failures_and_resumes(tmp_path):
    # Here, not at module level: the resume test below needs no Ray and runs without the extra.
    pytest.importorskip("ray", reason="the cluster extra is not installed (./install.sh cluster)")
    jobs = tmp_path / "jobs.jsonl"
    jobs.write_text("".join(json.dumps(job) + "\n" for job in JOBS), encoding="utf-8")

    single = _batch(jobs, tmp_path / "single")
    assert single.exit_code == EXIT_RUNTIME_FAILURE, single.output  # one job failed, the batch went on
    assert "6/7 scenarios generated" in single.stderr

    with loopback_cluster(cpus=2) as (address, env):
        # Ray puts the driver's working folder first on its workers' sys.path: from a folder without
        # grove_tui, only the PYTHONPATH the batch gives its workers makes them import the driver's copy.
        on_ray = _grove(env, tmp_path, "batch", str(jobs), "--out", str(tmp_path / "ray"), "--ray", address,
                        "--workers", "2")
        assert on_ray.returncode == EXIT_RUNTIME_FAILURE, on_ray.stdout + on_ray.stderr
        assert "6/7 scenarios generated" in on_ray.stderr

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

        # Resume on the cluster, the worker sending its files back (--ray-return, as workers without the
        # driver's file system do): the bundle removed here and the failed job run again, the five others
        # are not written again, and the returned bundle is the one-process bundle byte for byte. One
        # worker: a second would only load another model copy for the failing job, which fails before
        # the model. visitors-v000 is the first job of its process in both runs, so this compares the
        # transfer alone; whether a job's bundle depends on the jobs its worker ran before is the
        # comparison above.
        gone = "visitors-v000"
        shutil.rmtree(tmp_path / "ray" / gone)
        kept = [name for name in GOOD if name != gone]
        stamps = {name: (tmp_path / "ray" / name / "scenario.yaml").stat().st_mtime_ns for name in kept}
        resumed = _grove(env, tmp_path, "batch", str(jobs), "--out", str(tmp_path / "ray"), "--ray", address,
                         "--workers", "1", "--resume", "--ray-return")
        assert resumed.returncode == EXIT_RUNTIME_FAILURE, resumed.stdout + resumed.stderr
        assert "resume: 5 completed job(s) skipped, 2 to run" in resumed.stderr
        assert {name: (tmp_path / "ray" / name / "scenario.yaml").stat().st_mtime_ns for name in kept} == stamps
        assert _files(tmp_path / "ray" / gone) == _files(tmp_path / "single" / gone)
        assert not list((tmp_path / "ray").glob(".grove-ray-probe-*")), "the driver removes its probe file"
        assert len((tmp_path / "ray" / STATE_FILE).read_text(encoding="utf-8").splitlines()) == 9
        assert {n for n, r in read_records(tmp_path / "ray").items() if r["status"] == "ok"} == set(GOOD)

        # The batch refuses workers whose code is not the driver's (services.cluster.check_same_package);
        # here, directly: a task on the cluster, joined as the batch joins it, imports the driver's
        # grove_tui from the driver's folder, though the cluster started without the driver's PYTHONPATH
        # (this environment's install of GROVE-TUI may be another checkout).
        where = subprocess.run([sys.executable, "-c", WHERE_WORKERS_IMPORT, address], cwd=tmp_path,
                               env={**env, "PYTHONPATH": CHECKOUT}, capture_output=True, text=True, timeout=600)
        assert where.returncode == 0, where.stderr[-3000:]
        worker, driver = json.loads(where.stdout.strip().splitlines()[-1])
        assert worker == driver == list(package_fingerprint())


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
