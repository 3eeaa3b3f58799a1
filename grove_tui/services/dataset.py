"""A batch's record of its jobs and the dataset index built from its bundles.

Both ways of running a batch (one process, or Ray actors) share this module, so they skip, record
and index jobs the same way:

- `batch-state.jsonl` (in the batch's --out): one line per finished job, appended as it finishes:
  name, inputs hash, status ("ok" or "failed"), and for a failure its message and exit code. A
  resumed batch skips a job whose last line says "ok" with the same inputs hash and whose bundle is
  still there; a changed job (prompt, seed, models...) has another hash and runs again.
- `dataset.sqlite` (or `dataset.parquet` with `--index parquet`, when pyarrow is installed): one row
  per job of the file (world, preset, prompt, variation, seed, models, counts per group, grounding
  verdicts, simulation metrics, status), rebuilt from the bundles after every batch. Trajectories
  stay in the bundles. `grove dataset summary DIR` prints the totals of the newer of the two.
"""

from __future__ import annotations

import hashlib
import json
import sqlite3
from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING, Literal, TypedDict, cast

from grove_tui.errors import DatasetError, OutputError, describe_error, require_extra
from grove_tui.files import append_line, atomic_file, protect_folders
from grove_tui.jsontypes import Parsed

if TYPE_CHECKING:
    from grove_tui.services.jobs import BatchJob
    from grove_tui.llm.registry import ModelChoice
    from grove_tui.services.session import JobOutcome

STATE_FILE = "batch-state.jsonl"
INDEX_FILE = "dataset.sqlite"
PARQUET_FILE = "dataset.parquet"
INDEX_FORMATS = ("sqlite", "parquet")
# What the index writer of earlier versions staged under a fixed name (now a staging name with its pid).
LEGACY_INDEX_STAGE = f".{INDEX_FILE}.tmp"


def is_batch_folder(path: Path) -> bool:
    """The --out of a `grove batch` run (it holds the batch's record of its jobs)."""
    return (path / STATE_FILE).is_file()


# No other output may take the batch's own file names inside its folder (`generate --out OUT/dataset.sqlite`).
protect_folders(is_batch_folder, (STATE_FILE, INDEX_FILE, PARQUET_FILE), "batch folder")


@dataclass(frozen=True)
class JobRecord:
    """How one job ended, small enough to send from a Ray worker to the driver."""

    name: str
    line: int
    inputs: str  # job_inputs_hash
    status: str  # "ok" | "failed"
    message: str = ""
    exit_code: int = 0
    agents: int = 0
    prompt_tokens: int = 0
    seconds: float = 0.0
    exports: tuple[tuple[str, str], ...] = ()

    @property
    def ok(self) -> bool:
        return self.status == "ok"


def job_inputs_hash(job: BatchJob, models: dict[str, str]) -> str:
    """What decides a job's bundle: its request, simulation, exports and the model files of each role."""
    variation = None if job.variation is None else [job.variation.index, job.variation.count, job.variation.parent_seed]
    inputs = {"world": job.world, "preset": job.preset, "prompt": job.prompt, "seed": job.seed, "name": job.name,
              "simulate": job.simulate, "exports": list(job.exports), "variation": variation, "models": models}
    if job.refine:
        inputs["refine"] = list(job.refine)
    return hashlib.sha256(json.dumps(inputs, sort_keys=True).encode()).hexdigest()[:20]


def model_identity(choices: dict[str, ModelChoice]) -> dict[str, str]:
    """Each role's model file by name and size: a swapped GGUF changes the inputs hash."""
    identity = {}
    for role, choice in sorted(choices.items()):
        path = Path(choice.path)
        size = path.stat().st_size if path.is_file() else -1
        identity[role] = f"{path.name}:{size}"
    return identity


def record_outcome(outcome: JobOutcome, inputs: str) -> JobRecord:
    job = outcome.job
    if outcome.error is not None:
        return JobRecord(job.name, job.line, inputs, "failed", describe_error(outcome.error).message,
                         outcome.error.exit_code)
    assert outcome.generated is not None  # a JobOutcome without an error has its scenario
    report = outcome.generated.result.report
    return JobRecord(job.name, job.line, inputs, "ok", agents=len(outcome.generated.scenario.agents),
                     prompt_tokens=int(report.get("prompt_tokens", 0)),
                     seconds=float(report.get("total_seconds", 0.0)),
                     exports=tuple((kind, str(path)) for kind, path in outcome.exports.items()))


def append_record(out_dir: Path, record: JobRecord) -> None:
    """One line per finished job, appended whole (files.append_line): a line torn by a crash stays a
    line of its own, so the next record is never glued onto it and lost."""
    line = json.dumps({k: v for k, v in asdict(record).items() if k != "exports"}, ensure_ascii=True)
    append_line(out_dir / STATE_FILE, line)


def read_records(out_dir: Path) -> dict[str, Parsed]:
    """The last record of each job name; a torn line (a killed batch, even mid-character) is ignored."""
    records: dict[str, Parsed] = {}
    path = out_dir / STATE_FILE
    if not path.is_file():
        return records
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise DatasetError(f"{path}: cannot read it: {exc.strerror}") from None
    for raw in data.splitlines():
        try:
            entry = json.loads(raw.decode("utf-8"))
        except (UnicodeDecodeError, ValueError, RecursionError):
            continue
        if isinstance(entry, dict) and isinstance(entry.get("name"), str):
            records[entry["name"]] = entry
    return records


def completed_jobs(jobs: Sequence[BatchJob], out_dir: Path, hashes: dict[str, str]) -> set[str]:
    """Names of the jobs a resumed batch skips: recorded ok with the same inputs, bundle still there."""
    from grove_tui.scenario.bundle import is_bundle

    records = read_records(out_dir)
    done = set()
    for job in jobs:
        entry = records.get(job.name)
        if entry and entry.get("status") == "ok" and entry.get("inputs") == hashes[job.name] \
                and is_bundle(out_dir / job.name):
            done.add(job.name)
    return done


# -- the dataset index ---------------------------------------------------------------------------------

COLUMNS = (
    ("name", "TEXT PRIMARY KEY"), ("status", "TEXT"), ("exit_code", "INTEGER"), ("message", "TEXT"),
    ("world", "TEXT"), ("preset", "TEXT"), ("prompt", "TEXT"), ("variation", "INTEGER"), ("variations", "INTEGER"),
    ("parent_seed", "INTEGER"), ("seed", "INTEGER"), ("model_roi", "TEXT"), ("model_bt", "TEXT"),
    ("agents", "INTEGER"), ("group_counts", "TEXT"), ("grounding_ok", "INTEGER"), ("grounding", "TEXT"),
    ("generation_seconds", "REAL"), ("prompt_tokens", "INTEGER"), ("completion_tokens", "INTEGER"),
    ("simulated", "INTEGER"), ("metrics", "TEXT"), ("inputs", "TEXT"),
)


class IndexRow(TypedDict):
    """One scenario of the dataset index, as COLUMNS stores it (JSON columns are text)."""

    name: str
    status: str  # "ok", "failed" or "pending"
    exit_code: int | None
    message: str
    world: str
    preset: str
    prompt: str
    variation: int | None
    variations: int | None
    parent_seed: int
    seed: int
    model_roi: str | None
    model_bt: str | None
    agents: int | None
    group_counts: str | None
    grounding_ok: int | None
    grounding: str | None
    generation_seconds: float | None
    prompt_tokens: int | None
    completion_tokens: int | None
    simulated: int | None
    metrics: str | None
    inputs: str | None


def _read_json(path: Path) -> Parsed:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


def _row(job: BatchJob, out_dir: Path, record: Parsed | None) -> IndexRow:
    bundle = out_dir / job.name
    report = _read_json(bundle / "generation.json") if record and record.get("status") == "ok" else {}
    metrics = _read_json(bundle / "metrics.json") if report else {}
    # The report checked on the bundle's run (grounding.json) when it was simulated: a scenario is
    # grounded when every claim held there; a planned report (no run yet) grounds nothing.
    checked = _read_json(bundle / "grounding.json") if report else {}
    grounding = checked or report.get("grounding") or {}
    models = report.get("models", {})
    return {
        "name": job.name, "status": record.get("status", "pending") if record else "pending",
        "exit_code": int(record.get("exit_code", 0)) if record else None,
        "message": record.get("message", "") if record else "",
        "world": job.world, "preset": job.preset, "prompt": job.prompt,
        "variation": job.variation.index if job.variation else None,
        "variations": job.variation.count if job.variation else None,
        "parent_seed": job.variation.parent_seed if job.variation else job.seed, "seed": job.seed,
        "model_roi": models.get("roi"), "model_bt": models.get("bt"),
        "agents": sum(int(g.get("count", 0)) for g in report.get("groups", [])) if report else None,
        "group_counts": json.dumps({g.get("label", str(i)): g.get("count") for i, g in
                                    enumerate(report.get("groups", []))}) if report else None,
        "grounding_ok": (int(checked.get("status") == "holds") if checked else None),
        "grounding": json.dumps(grounding) if grounding else None,
        "generation_seconds": report.get("total_seconds"), "prompt_tokens": report.get("prompt_tokens"),
        "completion_tokens": report.get("completion_tokens"),
        "simulated": int(bool(metrics)) if report else None, "metrics": json.dumps(metrics) if metrics else None,
        "inputs": record.get("inputs") if record else None,
    }


def check_index_format(index_format: str) -> None:
    """`index_format` is one this install can write; else a DatasetError saying what to install."""
    if index_format not in INDEX_FORMATS:
        raise DatasetError(f"index format {index_format!r}: choose one of {', '.join(INDEX_FORMATS)}",
                           title="Unknown index format", hint="Use --index sqlite (the default) or --index parquet.")
    if index_format == "parquet":
        _pyarrow()


PYARROW_INSTALL = "pip install 'grove-tui[parquet]', or keep the default --index sqlite."


def _pyarrow() -> tuple[ModuleType, ModuleType]:
    require_extra("dataset.parquet", "pyarrow", ["pyarrow", "pyarrow.parquet"], PYARROW_INSTALL)
    import pyarrow
    import pyarrow.parquet

    return pyarrow, pyarrow.parquet


def index_path(out_dir: Path, index_format: str = "sqlite") -> Path:
    """Where `write_index` puts the dataset index of `out_dir` in `index_format`."""
    return out_dir / (PARQUET_FILE if index_format == "parquet" else INDEX_FILE)


def write_index(out_dir: Path, jobs: Iterable[BatchJob], index_format: str = "sqlite") -> Path:
    """Rebuild the dataset index from the bundles and batch-state.jsonl; replaced in one rename."""
    records = read_records(out_dir)
    rows = [_row(job, out_dir, records.get(job.name)) for job in jobs]
    if index_format == "parquet":
        return _write_parquet(out_dir / PARQUET_FILE, rows)
    target = out_dir / INDEX_FILE
    (out_dir / LEGACY_INDEX_STAGE).unlink(missing_ok=True)
    try:
        with atomic_file(target) as stage:
            db = sqlite3.connect(stage)
            try:
                with db:
                    db.execute(f"CREATE TABLE scenarios ({', '.join(f'{name} {kind}' for name, kind in COLUMNS)})")
                    names = [name for name, _ in COLUMNS]
                    db.executemany(f"INSERT INTO scenarios ({', '.join(names)}) VALUES "
                                   f"({', '.join('?' * len(names))})",
                                   [tuple(row.get(name) for name in names) for row in rows])
            finally:
                db.close()
    except sqlite3.Error as exc:  # a full disk, mostly ("database or disk is full")
        raise OutputError(f"{target}: cannot write the dataset index: {exc}") from None
    except OutputError as exc:
        raise OutputError(f"{exc} (the dataset index; a job named {INDEX_FILE} in an earlier version made a "
                          "folder there: move it away)" if target.is_dir() else str(exc)) from None
    return target


def _write_parquet(target: Path, rows: list[IndexRow]) -> Path:
    pa, pq = _pyarrow()
    # The sqlite table's columns and types, so both indexes read the same.
    types = {"TEXT": pa.string(), "INTEGER": pa.int64(), "REAL": pa.float64()}
    schema = pa.schema([(name, types[kind.split()[0]]) for name, kind in COLUMNS])
    table = pa.Table.from_pylist(rows, schema=schema)
    with atomic_file(target) as stage:
        pq.write_table(table, stage)
    return target


def _read_index(out_dir: Path) -> list[IndexRow]:
    """The rows of DIR's dataset index: the newer of dataset.sqlite and dataset.parquet."""
    present = [path for path in (out_dir / INDEX_FILE, out_dir / PARQUET_FILE) if path.is_file()]
    if not present:
        raise DatasetError(f"{out_dir}: no {INDEX_FILE} or {PARQUET_FILE} "
                           "(not the --out folder of a `grove batch` run)")
    path = max(present, key=lambda candidate: candidate.stat().st_mtime_ns)
    if path.name == PARQUET_FILE:
        _pa, pq = _pyarrow()
        try:
            table = pq.read_table(path)
        except (OSError, ValueError) as exc:  # pyarrow's ArrowInvalid is a ValueError
            raise DatasetError(f"{path}: not a readable dataset index: {exc}") from None
        missing = [name for name, _ in COLUMNS if name not in table.column_names]
        if missing:
            raise DatasetError(f"{path}: not a GROVE dataset index (no column {', '.join(missing)})")
        rows = cast(list[IndexRow], table.to_pylist())  # COLUMNS, checked above
        return sorted(rows, key=lambda row: str(row["name"]))
    try:
        db = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
        try:
            cursor = db.execute("SELECT * FROM scenarios ORDER BY name")
            names = [column[0] for column in cursor.description]
            return [cast(IndexRow, dict(zip(names, values))) for values in cursor]  # the table write_index made
        finally:
            db.close()
    except sqlite3.Error as exc:
        raise DatasetError(f"{path}: not a readable dataset index: {exc}") from None


@dataclass(frozen=True)
class DatasetSummary:
    scenarios: int
    ok: int
    failed: int
    pending: int
    agents: int
    grounded: int  # scenarios whose grounding report, checked on their run, holds for every group and the robot
    simulated: int
    worlds: dict[str, int]
    presets: dict[str, int]
    prompts: int
    generation_seconds: float
    failures: list[tuple[str, int, str]]  # name, exit code, message


def summarize(out_dir: str | Path) -> DatasetSummary:
    rows = _read_index(Path(out_dir))

    def count_by(key: Literal["world", "preset"]) -> dict[str, int]:
        counts: dict[str, int] = {}
        for row in rows:
            counts[row[key]] = counts.get(row[key], 0) + 1
        return dict(sorted(counts.items()))

    ok = [row for row in rows if row["status"] == "ok"]
    return DatasetSummary(
        scenarios=len(rows), ok=len(ok), failed=sum(row["status"] == "failed" for row in rows),
        pending=sum(row["status"] == "pending" for row in rows), agents=sum(row["agents"] or 0 for row in ok),
        grounded=sum(1 for row in ok if row["grounding_ok"]), simulated=sum(1 for row in ok if row["simulated"]),
        worlds=count_by("world"), presets=count_by("preset"), prompts=len({row["prompt"] for row in rows}),
        generation_seconds=round(sum(row["generation_seconds"] or 0.0 for row in ok), 2),
        failures=[(row["name"], int(row["exit_code"] or 0), row["message"]) for row in rows
                  if row["status"] == "failed"])

