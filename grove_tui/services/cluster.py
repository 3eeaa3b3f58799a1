"""`grove batch --ray`: the batch's jobs on Ray actors, one long-lived actor per worker.

Ray is an optional extra (`./install.sh cluster`): this is the only module that imports it, inside
the functions that need it, so the core and a plain install never load it.

Each actor holds one `GroveSession`, so a worker loads the models and the retrieval index once and
reuses them for every job it is given. A job runs exactly as `GroveSession.run_job` runs it in one
process. Where its bundle is written depends on what the worker sees:

- a worker that shares the driver's file system (one machine, or a shared --out) writes the bundle
  atomically (`scenario.bundle.write_bundle`) straight into --out; only a small `JobRecord` travels
  back to the driver, which keeps the batch state and the dataset index;
- a worker that does not (the driver's probe file in --out is not there for it), or every worker with
  `--ray-return`, generates into a folder of its own and returns the job's files (bundle and exports,
  at most MAX_RETURNED_BYTES) through Ray's object store; the driver writes them into --out with the
  same atomic swap (`scenario.bundle.write_bundle_files`).
"""

from __future__ import annotations

import hashlib
import os
import secrets
import stat
import tempfile
from collections import defaultdict
from collections.abc import Callable, Sequence
from functools import cache
from pathlib import Path, PurePosixPath
from typing import Any

from grove_tui.errors import EXIT_CANCELLED, EXIT_RUNTIME_FAILURE, Cancelled, GroveError, ModelError, \
    RuntimeFailure, require_extra
from grove_tui.files import absolute_path, write_bytes_atomic, write_files_atomic, write_text_atomic
from grove_tui.scenario.bundle import write_bundle_files
from grove_tui.services.dataset import JobRecord, record_outcome
from grove_tui.services.jobs import BatchJob

# What one job may send back to the driver (bundle and exports together). A bundle without simulation
# is tens to hundreds of kB; long simulated runs with exports reach tens of MB. The bound keeps one
# runaway job from filling the object store and the driver's memory; past it, give the workers a
# shared --out.
MAX_RETURNED_BYTES = 512 * 2**20
# The driver writes this file (with a random token) into --out; a worker that reads the token back
# shares the driver's file system and writes bundles itself.
PROBE_PREFIX = ".grove-ray-probe-"

# A job's files relative to the batch's --out ("NAME/scenario.yaml", "NAME.mcap", ...), and their bytes.
JobFiles = tuple[tuple[str, bytes], ...]

# Ray's own objects, by what they are here. Ray is an optional extra that mypy cannot see (not installed
# where the core is checked), so they have no type but their name.
RayModule = Any  # Any: the `ray` module (optional extra, not visible to mypy)
ActorHandle = Any  # Any: a Ray actor handle of BatchWorker (its methods are called through .remote)
ObjectRef = Any  # Any: a Ray object reference to a job's (record, files)


RAY_INSTALL = "Install the cluster extra: ./install.sh cluster (or pip install 'grove-tui[cluster]')."


def require_ray() -> None:
    """MissingExtraError (exit 2) unless Ray imports here: checked before a batch reads or writes anything."""
    require_extra("`--ray`", "Ray", ["ray"], RAY_INSTALL)


class BatchWorker:
    """The body of one Ray actor: a session kept for the actor's life."""

    def __init__(self, model: str | None, roi_model: str | None, bt_model: str | None) -> None:
        from grove_tui.services.session import GroveSession

        self.session = GroveSession(model=model, roi_model=roi_model, bt_model=bt_model)
        # Loading starts with the actor, not with its first job: the driver is still placing the others.
        self.warming = self.session.start_warm_up()

    def package(self) -> tuple[str, str]:
        """Where this worker imports grove_tui from, and the digest of that code (`package_fingerprint`)."""
        return package_fingerprint()

    def sees(self, probe: str, token: str) -> bool:
        """Whether this worker reads the driver's probe file, that is, shares the driver's --out."""
        try:
            return Path(probe).read_text(encoding="ascii") == token
        except (OSError, UnicodeDecodeError):
            return False

    def run(self, job: BatchJob, out_dir: str, overwrite: bool, inputs: str,
            return_files: bool = False) -> tuple[JobRecord, JobFiles]:
        """Run one job; with `return_files`, in a folder of this worker's own, returning its files."""
        if not return_files:
            return self._run(job, Path(out_dir), overwrite, inputs), ()
        with tempfile.TemporaryDirectory(prefix="grove-ray-job-") as local:
            record = _relocated(self._run(job, Path(local), False, inputs), local, out_dir)
            if not record.ok:
                return record, ()
            try:
                return record, collect_job_files(Path(local))
            except RuntimeFailure as exc:
                return JobRecord(job.name, job.line, inputs, "failed", str(exc), exc.exit_code), ()

    def _run(self, job: BatchJob, out_dir: Path, overwrite: bool, inputs: str) -> JobRecord:
        try:
            outcome = self.session.run_job(job, out_dir, overwrite=overwrite)
        except GroveError as exc:
            # A model error or a cancellation stops the batch in one process; the driver does the same.
            return JobRecord(job.name, job.line, inputs, "fatal", str(exc), exc.exit_code)
        return record_outcome(outcome, inputs)

    def close(self) -> None:
        self.session.close()


@cache
def package_fingerprint() -> tuple[str, str]:
    """The folder this process imports grove_tui from, and a SHA-256 of every Python source in it.

    The digest, not the folder, decides whether a worker runs the driver's code: on another node the
    same code sits at another path, and on this machine another checkout may sit at the same one.
    """
    import grove_tui

    root = Path(grove_tui.__file__).resolve().parent
    digest = hashlib.sha256()
    for source in sorted(root.rglob("*.py")):
        digest.update(source.relative_to(root).as_posix().encode() + b"\0")
        digest.update(hashlib.sha256(source.read_bytes()).digest())
    return str(root), digest.hexdigest()


def check_same_package(driver: tuple[str, str], workers: Sequence[tuple[str, str]]) -> None:
    """RuntimeFailure when a worker's grove_tui (`package_fingerprint`) is not the driver's code."""
    for where, digest in workers:
        if digest != driver[1]:
            # Another version would write other bundles under the same inputs hash, and resume would trust them.
            raise RuntimeFailure(
                f"a Ray worker imports grove_tui from {where}, whose code differs from this driver's "
                f"({driver[0]}): its bundles would not be the one-process batch's",
                hint="Install the same GROVE-TUI on every node, or run the driver from the copy the workers import.")


def _relocated(record: JobRecord, local: str, out_dir: str) -> JobRecord:
    """The record as if the job had run in `out_dir`: paths in its message and exports name --out."""
    from dataclasses import replace

    return replace(record, message=record.message.replace(local, out_dir),
                   exports=tuple((kind, path.replace(local, out_dir, 1)) for kind, path in record.exports))


def collect_job_files(root: Path, limit: int = MAX_RETURNED_BYTES) -> JobFiles:
    """Every file under `root` (one job's private folder) with its bytes; RuntimeFailure past `limit`."""
    members: list[tuple[str, Path]] = []
    total = 0
    for folder, dirs, names in os.walk(root):
        dirs.sort()
        for name in sorted(names) + [d for d in dirs if os.path.islink(os.path.join(folder, d))]:
            path = Path(folder, name)
            info = os.lstat(path)
            rel = path.relative_to(root).as_posix()
            if not stat.S_ISREG(info.st_mode):
                raise RuntimeFailure(f"{rel}: the job wrote something other than a regular file; "
                                     "it cannot be sent to the driver")
            total += info.st_size
            if total > limit:
                raise RuntimeFailure(f"the job's files exceed the {limit / 2**20:.3g} MB a Ray worker sends back "
                                     "to the driver", hint="Give the Ray workers a --out on a shared file system.")
            members.append((rel, path))
    return tuple((rel, path.read_bytes()) for rel, path in members)


def write_returned_files(out_dir: Path, name: str, files: JobFiles, overwrite: bool) -> None:
    """Write what a worker sent back for job `name`: its bundle folder first, then its exports."""
    entries: dict[str, dict[str, bytes]] = defaultdict(dict)
    for rel, data in files:
        top, *rest = PurePosixPath(rel).parts or ("",)
        if top != name and not top.startswith(name + "."):
            # A job writes its bundle NAME and its exports NAME.KIND beside it, nothing else.
            raise RuntimeFailure(f"{out_dir}: the worker sent {rel!r}, which is not job {name!r}'s to write")
        entries[top]["/".join(rest)] = data
    if name not in entries:
        raise RuntimeFailure(f"{out_dir / name}: the worker sent no bundle for job {name!r}")
    write_bundle_files(entries.pop(name), out_dir / name, overwrite=overwrite)
    for top, members in sorted(entries.items()):
        # Each export replaces only its own earlier output, as the one-process batch does; the same guard.
        owned, what = export_owner(top[len(name) + 1:])
        if "" in members:  # a single file beside the bundle (a Foxglove .mcap and its layout)
            if len(members) > 1:
                raise RuntimeFailure(f"{out_dir / top}: the worker sent it both as a file and as a folder")
            write_bytes_atomic(out_dir / top, members[""], owned=owned, what=what, overwrite=overwrite)
        else:  # an export folder
            write_files_atomic(out_dir / top, members, owned=owned, what=what, overwrite=overwrite)


def export_owner(suffix: str) -> tuple[Callable[[Path], bool], str]:
    """The ownership test of the export a batch writes as NAME.<suffix> (hunav, rosbag, mcap, layout.json...)."""
    from grove_tui.exports.foxglove import is_grove_layout, is_grove_mcap
    from grove_tui.exports.hunav import is_hunav_export
    from grove_tui.exports.rosbag import is_rosbag_export
    from grove_tui.exports.trajectories import is_trajectories_export

    owners: dict[str, tuple[Callable[[Path], bool], str]] = {
        "hunav": (is_hunav_export, "GROVE HuNavSim export"), "rosbag": (is_rosbag_export, "GROVE ROS 2 bag export"),
        "trajectories": (is_trajectories_export, "GROVE trajectories export"),
        "mcap": (is_grove_mcap, "GROVE Foxglove export"), "layout.json": (is_grove_layout, "GROVE Foxglove layout")}
    if suffix not in owners:
        raise RuntimeFailure(f"a batch export named *.{suffix} is not one GROVE writes")
    return owners[suffix]


def _import_ray() -> RayModule:
    require_ray()
    import ray

    return ray


def _connect(ray: RayModule, address: str, workers: int | None) -> None:
    """`local`: a private Ray on this machine; `auto`, `host:port` (its GCS) or `ray://host:port`: an
    existing cluster."""
    # The workers read the same GROVE_* settings (cache folder, model folder, threads) as the driver,
    # so a job gives the bundle it gives in one process.
    env = {key: value for key, value in os.environ.items() if key.startswith("GROVE_")}
    options: dict[str, object] = {"runtime_env": {"env_vars": env}, "log_to_driver": False,
                               "include_dashboard": False, "logging_level": "warning"}
    # Workers on this machine, of a private Ray or of a cluster started beforehand with `ray start`,
    # import the driver's own grove_tui, not whichever the folder they start in or the environment's
    # install would give (a checkout beside an installed copy). On other nodes the folder is usually
    # absent and Python skips it; `check_same_package` refuses workers whose code still differs.
    package_root = str(Path(__file__).resolve().parents[2])
    env["PYTHONPATH"] = os.pathsep.join(p for p in (package_root, os.environ.get("PYTHONPATH")) if p)
    try:
        if address == "local":
            ray.init(address="local", num_cpus=workers or os.cpu_count() or 1, **options)
        else:
            ray.init(address=address, **options)
    except (ConnectionError, ValueError, RuntimeError) as exc:
        raise RuntimeFailure(f"cannot connect to Ray at {address!r}: {exc}",
                             hint="Start one with `ray start --head`, or use --ray local. A cluster with token "
                                  "authentication (Ray's default) needs its token in RAY_AUTH_TOKEN or "
                                  "~/.ray/auth_token.") from None


def _next_job(queue: Sequence[BatchJob], prompt: tuple[str, str, str] | None) -> int:
    """The index in `queue` of the first job of `prompt` (world, preset, sentence), else 0."""
    if prompt is not None:
        for index, job in enumerate(queue):
            if (job.world, job.preset, job.prompt) == prompt:
                return index
    return 0


def run_on_ray(jobs: Sequence[BatchJob], out_dir: Path, hashes: dict[str, str], *, address: str,
               workers: int | None, overwrite: bool, models: tuple[str | None, str | None, str | None],
               on_record: Callable[[JobRecord], None], return_files: bool | None = None) -> list[JobRecord]:
    """Run `jobs` on `workers` actors (default: one per CPU of the cluster); a record per job, as each ends.

    `return_files`: True, every worker sends its jobs' files back for the driver to write; None, only
    the workers that cannot see the driver's --out do.
    """
    ray = _import_ray()
    # Absolute: a worker's working folder is not the driver's.
    out_dir = absolute_path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    probe = out_dir / f"{PROBE_PREFIX}{secrets.token_hex(8)}"
    token = secrets.token_hex(16)
    write_text_atomic(probe, token)
    started_here = not ray.is_initialized()
    actors: list[ActorHandle] = []
    try:
        if started_here:
            _connect(ray, address, workers)
        count = workers or max(1, int(ray.cluster_resources().get("CPU", 1)))
        count = max(1, min(count, len(jobs)))
        worker_class = ray.remote(num_cpus=1)(BatchWorker)
        actors = [worker_class.remote(*models) for _ in range(count)]
        sends_back: dict[ActorHandle, bool] = {}

        def check_workers(new: list[ActorHandle]) -> None:
            """New actors must run the driver's code; then: does each see --out, or send files back?"""
            try:
                packages = ray.get([actor.package.remote() for actor in new])
            except ray.exceptions.RayError as exc:
                # An actor that did not start (its session could not be built), or a worker whose grove_tui
                # is older than the driver's and has no BatchWorker.package: Ray's last line says which.
                cause = (str(exc).strip().splitlines() or [type(exc).__name__])[-1]
                raise RuntimeFailure(f"a Ray worker could not say which grove_tui it runs: {cause}",
                                     hint="Install the same GROVE-TUI (and model files) on every node.") from None
            check_same_package(package_fingerprint(), packages)
            if return_files:
                sends_back.update((actor, True) for actor in new)
                return
            seen = ray.get([actor.sees.remote(str(probe), token) for actor in new])
            sends_back.update((actor, not sees) for actor, sees in zip(new, seen))

        check_workers(actors)
        idle = list(actors)
        queue = list(jobs)
        running: dict[ObjectRef, tuple[ActorHandle, BatchJob]] = {}
        records: list[JobRecord] = []
        last_prompt: dict[ActorHandle, tuple[str, str, str]] = {}
        while queue or running:
            # Hand each idle actor a job as soon as it is free (a slow job never holds up the others),
            # preferably another variation of the prompt it ran last: its model then reuses the prompt's
            # evaluated prefix, which made a variation about ten times cheaper than a new prompt here.
            while idle and queue:
                actor = idle.pop()
                job = queue.pop(_next_job(queue, last_prompt.get(actor)))
                last_prompt[actor] = (job.world, job.preset, job.prompt)
                ref = actor.run.remote(job, str(out_dir), overwrite, hashes[job.name], sends_back[actor])
                running[ref] = (actor, job)
            finished, _ = ray.wait(list(running), num_returns=1)
            for ref in finished:
                actor, job = running.pop(ref)
                try:
                    record, files = ray.get(ref)
                except ray.exceptions.RayError as exc:
                    # The actor process died (killed, out of memory): the job failed, a fresh actor takes its place.
                    record, files = JobRecord(job.name, job.line, hashes[job.name], "failed",
                                              f"the Ray worker running it died: {type(exc).__name__}",
                                              EXIT_RUNTIME_FAILURE), ()
                    actors.remove(actor)
                    actor = worker_class.remote(*models)
                    actors.append(actor)
                    check_workers([actor])
                if record.status == "fatal":
                    raise (Cancelled if record.exit_code == EXIT_CANCELLED else ModelError)(record.message)
                if record.ok and files:  # a worker without --out sent the job's files back
                    record = _write_sent(out_dir, job, record, files, overwrite)
                records.append(record)
                on_record(record)
                idle.append(actor)
        return records
    finally:
        probe.unlink(missing_ok=True)
        # Each actor's models run in a child process of its own: close them before the actor goes.
        try:
            ray.get([actor.close.remote() for actor in actors], timeout=60)
        except Exception:  # noqa: BLE001 - a dead or hung actor must not keep the others (or the driver) alive
            pass
        for actor in actors:
            ray.kill(actor)
        if started_here:
            ray.shutdown()


def _write_sent(out_dir: Path, job: BatchJob, record: JobRecord, files: JobFiles, overwrite: bool) -> JobRecord:
    """Write a job's returned files into --out; a refused write fails that job, not the batch."""
    try:
        write_returned_files(out_dir, job.name, files, overwrite)
    except GroveError as exc:
        return JobRecord(job.name, job.line, record.inputs, "failed", str(exc), exc.exit_code)
    return record
