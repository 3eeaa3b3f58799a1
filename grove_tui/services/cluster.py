"""`grove batch --ray`: the batch's jobs on Ray actors, one long-lived actor per worker.

Ray is an optional extra (`./install.sh cluster`): this is the only module that imports it, inside
the functions that need it, so the core and a plain install never load it.

Each actor holds one `GroveSession`, so a worker loads the models and the retrieval index once and
reuses them for every job it is given. A job runs exactly as `GroveSession.run_job` runs it in one
process, and writes its bundle atomically (`scenario.bundle.write_bundle`) into the batch's --out,
which the workers must share with the driver (one machine, or a shared file system). Only a small
`JobRecord` travels back to the driver, which keeps the batch state and the dataset index.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from grove_tui.errors import EXIT_CANCELLED, Cancelled, GroveError, ModelError, RuntimeFailure
from grove_tui.services.dataset import JobRecord, record_outcome
from grove_tui.services.jobs import BatchJob


class RayUnavailable(RuntimeFailure):
    title = "Ray is not installed"
    hint = "Install the cluster extra: ./install.sh cluster (or pip install 'grove-tui[cluster]')."


class BatchWorker:
    """The body of one Ray actor: a session kept for the actor's life."""

    def __init__(self, model: str | None, roi_model: str | None, bt_model: str | None) -> None:
        from grove_tui.services.session import GroveSession

        self.session = GroveSession(model=model, roi_model=roi_model, bt_model=bt_model)
        # Loading starts with the actor, not with its first job: the driver is still placing the others.
        self.session.start_warm_up()

    def run(self, job: BatchJob, out_dir: str, overwrite: bool, inputs: str) -> JobRecord:
        try:
            outcome = self.session.run_job(job, Path(out_dir), overwrite=overwrite)
        except GroveError as exc:
            # A model error or a cancellation stops the batch in one process; the driver does the same.
            return JobRecord(job.name, job.line, inputs, "fatal", str(exc), exc.exit_code)
        return record_outcome(outcome, inputs)

    def close(self) -> None:
        self.session.close()


def _import_ray() -> Any:
    try:
        import ray
    except ImportError:
        raise RayUnavailable("`--ray` needs Ray, which this install does not have") from None
    return ray


def _connect(ray: Any, address: str, workers: int | None) -> None:
    """`local`: a private Ray on this machine; `auto` or `ray://host:port`: an existing cluster."""
    # The workers read the same GROVE_* settings (cache folder, model folder, threads) as the driver,
    # so a job gives the bundle it gives in one process.
    env = {key: value for key, value in os.environ.items() if key.startswith("GROVE_")}
    options: dict[str, Any] = {"runtime_env": {"env_vars": env}, "log_to_driver": False,
                               "include_dashboard": False, "logging_level": "warning"}
    try:
        if address == "local":
            ray.init(address="local", num_cpus=workers or os.cpu_count() or 1, **options)
        else:
            ray.init(address=address, **options)
    except (ConnectionError, ValueError, RuntimeError) as exc:
        raise RuntimeFailure(f"cannot connect to Ray at {address!r}: {exc}",
                             hint="Start one with `ray start --head`, or use --ray local.") from None


def _next_job(queue: Sequence[BatchJob], prompt: tuple[str, str, str] | None) -> int:
    """The index in `queue` of the first job of `prompt` (world, preset, sentence), else 0."""
    if prompt is not None:
        for index, job in enumerate(queue):
            if (job.world, job.preset, job.prompt) == prompt:
                return index
    return 0


def run_on_ray(jobs: Sequence[BatchJob], out_dir: Path, hashes: dict[str, str], *, address: str,
               workers: int | None, overwrite: bool, models: tuple[str | None, str | None, str | None],
               on_record: Callable[[JobRecord], None]) -> list[JobRecord]:
    """Run `jobs` on `workers` actors (default: one per CPU of the cluster); a record per job, as each ends."""
    ray = _import_ray()
    started_here = not ray.is_initialized()
    if started_here:
        _connect(ray, address, workers)
    actors: list[Any] = []
    try:
        count = workers or max(1, int(ray.cluster_resources().get("CPU", 1)))
        count = max(1, min(count, len(jobs)))
        worker_class = ray.remote(num_cpus=1)(BatchWorker)
        actors = [worker_class.remote(*models) for _ in range(count)]
        idle = list(actors)
        queue = list(jobs)
        running: dict[Any, tuple[Any, BatchJob]] = {}
        records: list[JobRecord] = []
        last_prompt: dict[Any, tuple[str, str, str]] = {}
        while queue or running:
            # Hand each idle actor a job as soon as it is free (a slow job never holds up the others),
            # preferably another variation of the prompt it ran last: its model then reuses the prompt's
            # evaluated prefix, which made a variation about ten times cheaper than a new prompt here.
            while idle and queue:
                actor = idle.pop()
                job = queue.pop(_next_job(queue, last_prompt.get(actor)))
                last_prompt[actor] = (job.world, job.preset, job.prompt)
                running[actor.run.remote(job, str(out_dir), overwrite, hashes[job.name])] = (actor, job)
            finished, _ = ray.wait(list(running), num_returns=1)
            for ref in finished:
                actor, job = running.pop(ref)
                try:
                    record = ray.get(ref)
                except ray.exceptions.RayError as exc:
                    # The actor process died (killed, out of memory): the job failed, a fresh actor takes its place.
                    record = JobRecord(job.name, job.line, hashes[job.name], "failed",
                                       f"the Ray worker running it died: {type(exc).__name__}", 3)
                    actors.remove(actor)
                    actor = worker_class.remote(*models)
                    actors.append(actor)
                if record.status == "fatal":
                    raise (Cancelled if record.exit_code == EXIT_CANCELLED else ModelError)(record.message)
                records.append(record)
                on_record(record)
                idle.append(actor)
        return records
    finally:
        # Each actor's models run in a child process of its own: close them before the actor goes.
        try:
            ray.get([actor.close.remote() for actor in actors], timeout=60)
        except Exception:  # noqa: BLE001 - a dead or hung actor must not keep the others (or the driver) alive
            pass
        for actor in actors:
            ray.kill(actor)
        if started_here:
            ray.shutdown()
