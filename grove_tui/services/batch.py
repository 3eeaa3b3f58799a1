"""One batch, in one process or on Ray: resume, per-job records, the dataset index.

`run_batch` is what `grove batch` calls. Both ways run each job through `GroveSession.run_job`, skip
the same completed jobs, append the same records to batch-state.jsonl and rebuild the same
dataset index (services.dataset), so `--ray` changes where jobs run and nothing they produce.

A batch killed at any point leaves whole bundles, whole record lines and a whole index: every write
goes through grove_tui.files, and the next run into the same folder first removes the staging entries
a killed process left (`sweep_stale`). A batch that stops on an error (a full disk, a broken model)
still rewrites the index when it can, keeps its own error when it cannot, and removes the --out folder
it made if nothing was written into it.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from grove_tui.errors import GroveError
from grove_tui.files import sweep_stale

from grove_tui.services.dataset import (
    JobRecord,
    append_record,
    check_index_format,
    completed_jobs,
    index_path,
    job_inputs_hash,
    model_identity,
    record_outcome,
    write_index,
)
from grove_tui.services.jobs import BatchJob
from grove_tui.services.session import EventSink, GroveSession, JobOutcome


@dataclass(frozen=True)
class BatchResult:
    records: list[JobRecord]  # the jobs that ran, in the order they ended
    skipped: list[BatchJob]  # completed by an earlier run with the same inputs (resume)
    index: Path  # dataset.sqlite or dataset.parquet

    @property
    def failures(self) -> int:
        return sum(1 for record in self.records if not record.ok)


def run_batch(session: GroveSession, jobs: Sequence[BatchJob], out_dir: Path, *, overwrite: bool = False,
              resume: bool = False, ray_address: str | None = None, workers: int | None = None,
              ray_return: bool = False, index_format: str = "sqlite",
              on_start: Callable[[list[BatchJob], list[BatchJob]], None] | None = None,
              events_for: Callable[[int, BatchJob], EventSink | None] | None = None,
              on_record: Callable[[JobRecord], None] | None = None) -> BatchResult:
    """Run the checked jobs; `on_start(to_run, skipped)` before the first, `on_record` as each ends.

    `ray_return`: every Ray worker sends its jobs' files back and the driver writes them (else only
    the workers that cannot see `out_dir` do). `index_format`: "sqlite" or "parquet" (needs pyarrow).
    """
    check_index_format(index_format)  # before any job runs: a missing pyarrow must not cost a batch
    if ray_address is not None:
        from grove_tui.services.cluster import require_ray

        require_ray()  # likewise a missing Ray: one error line, nothing read or written
    made_out_dir = not os.path.lexists(out_dir)
    sweep_stale(out_dir)  # staging folders and files a killed earlier run left behind
    warming = None
    if jobs and ray_address is None:
        # Models, embedder and reader load while the inputs are hashed and checked for resume (the
        # model files are read whole for the hash); the first job waits only for what is left.
        warming = session.start_warm_up(jobs[0].world, jobs[0].preset)
    interrupted = False
    try:
        identity = model_identity(session.model_choices())
        hashes = {job.name: job_inputs_hash(job, identity) for job in jobs}
        done = completed_jobs(jobs, out_dir, hashes) if resume else set()
        skipped = [job for job in jobs if job.name in done]
        to_run = [job for job in jobs if job.name not in done]
        if on_start is not None:
            on_start(to_run, skipped)
        records: list[JobRecord] = []

        def finished(record: JobRecord) -> None:
            append_record(out_dir, record)
            records.append(record)
            if on_record is not None:
                on_record(record)

        try:
            if not to_run:
                pass
            elif ray_address is not None:
                from grove_tui.services.cluster import run_on_ray

                run_on_ray(to_run, out_dir, hashes, address=ray_address, workers=workers, overwrite=overwrite,
                           models=session.model_options, on_record=finished, return_files=True if ray_return else None)
            else:
                def outcome_done(_index: int, outcome: JobOutcome) -> None:
                    finished(record_outcome(outcome, hashes[outcome.job.name]))

                session.batch(to_run, out_dir, overwrite=overwrite, events_for=events_for, on_outcome=outcome_done)
        except BaseException:
            # Also after a model error or Ctrl+C the index shows what is done, failed and still pending; if it
            # cannot be written either (the disk that stopped the batch is full), the batch's own error is the
            # one reported, and a --out this run made and never wrote into is removed. A batch stopped before
            # its folder existed has nothing to index (and sqlite's "unable to open" would hide why it stopped).
            if out_dir.is_dir():
                with contextlib.suppress(GroveError):
                    write_index(out_dir, jobs, index_format)
            if made_out_dir:
                _remove_if_empty(out_dir)
            raise
        try:
            if out_dir.is_dir():
                write_index(out_dir, jobs, index_format)
        except BaseException:
            if made_out_dir:
                _remove_if_empty(out_dir)
            raise
        return BatchResult(records, skipped, index_path(out_dir, index_format))
    except KeyboardInterrupt:
        interrupted = True
        raise
    finally:
        if warming is not None:  # a batch that ends early leaves nothing loading behind it; Ctrl+C waits for none
            session.stop_warm_up(warming, wait=not interrupted)


def _remove_if_empty(folder: Path) -> None:
    sweep_stale(folder)
    with contextlib.suppress(OSError):
        folder.rmdir()
