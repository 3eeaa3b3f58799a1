"""The dataset index of a batch: dataset.sqlite by default, dataset.parquet when asked (and pyarrow is
installed); both hold the same rows and `grove dataset summary` reads either, the newer when both."""

from __future__ import annotations

import json
import os
import sqlite3
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.errors import EXIT_BAD_INPUT, DatasetError, MissingExtraError
from grove_tui.services.dataset import (
    COLUMNS,
    INDEX_FILE,
    PARQUET_FILE,
    JobRecord,
    append_record,
    check_index_format,
    summarize,
    write_index,
)
from grove_tui.services.jobs import read_jobs


@pytest.fixture
def batch_out(tmp_path) -> tuple[Path, list]:
    """A batch folder as `grove batch` leaves it: two bundles' reports, one failed job, one pending."""
    jobs_file = tmp_path / "jobs.jsonl"
    jobs_file.write_text(
        json.dumps({"world": "hospital", "preset": "normal", "prompt": "a few visitors walk to the cafeteria",
                    "name": "visitors", "variations": 2, "seed": 5}) + "\n"
        + json.dumps({"world": "office", "preset": "queuing", "prompt": "Ten people swim", "name": "pool"}) + "\n"
        + json.dumps({"world": "office", "preset": "normal", "prompt": "Two people walk", "name": "later"}) + "\n",
        encoding="utf-8")
    jobs, problems = read_jobs(jobs_file)
    assert not problems
    out = tmp_path / "out"
    for index, agents in ((0, 3), (1, 4)):
        bundle = out / f"visitors-v00{index}"
        bundle.mkdir(parents=True)
        (bundle / "scenario.yaml").write_text("world: hospital\n", encoding="utf-8")
        report = {"groups": [{"label": "visitors", "count": agents}], "total_seconds": 10.0 + index,
                  "prompt_tokens": 1700, "completion_tokens": 90, "models": {"roi": "none", "bt": "smollm2"},
                  "grounding": {"groups": [{"ok": index == 0}], "unhonoured": []}}
        (bundle / "generation.json").write_text(json.dumps(report), encoding="utf-8")
        # the report checked on the run: every claim held for the first, not for the second
        (bundle / "grounding.json").write_text(json.dumps({"status": "holds" if index == 0 else "fails",
                                                           "groups": []}), encoding="utf-8")
        append_record(out, JobRecord(bundle.name, 1, f"hash{index}", "ok", agents=agents))
    (out / "visitors-v001" / "metrics.json").write_text(json.dumps({"crowd": {"goal_reach_rate": 1.0}}),
                                                        encoding="utf-8")
    append_record(out, JobRecord("pool", 2, "hash2", "failed", "no place 'swimming pool' in office", 2))
    return out, jobs


def _sqlite_rows(path: Path) -> list[dict]:
    with sqlite3.connect(path) as db:
        cursor = db.execute("SELECT * FROM scenarios ORDER BY name")
        names = [column[0] for column in cursor.description]
        return [dict(zip(names, values)) for values in cursor]


def test_sqlite_index_rows_and_summary(batch_out):
    out, jobs = batch_out
    assert write_index(out, jobs) == out / INDEX_FILE
    rows = {row["name"]: row for row in _sqlite_rows(out / INDEX_FILE)}
    assert [row["status"] for _, row in sorted(rows.items())] == ["pending", "failed", "ok", "ok"]
    assert rows["visitors-v001"]["variation"] == 1 and rows["visitors-v001"]["parent_seed"] == 5
    assert rows["visitors-v001"]["agents"] == 4 and rows["visitors-v001"]["simulated"] == 1
    assert rows["pool"]["exit_code"] == 2 and rows["later"]["exit_code"] is None
    totals = summarize(out)
    assert (totals.scenarios, totals.ok, totals.failed, totals.pending) == (4, 2, 1, 1)
    assert (totals.agents, totals.grounded, totals.simulated, totals.prompts) == (7, 1, 1, 3)
    assert totals.worlds == {"hospital": 2, "office": 2}
    assert totals.failures == [("pool", 2, "no place 'swimming pool' in office")]


def test_parquet_index_holds_the_sqlite_rows(batch_out):
    pq = pytest.importorskip("pyarrow.parquet", reason="pyarrow is not installed (the parquet index is optional)")
    out, jobs = batch_out
    write_index(out, jobs)
    from_sqlite = summarize(out)
    assert write_index(out, jobs, "parquet") == out / PARQUET_FILE
    table = pq.read_table(out / PARQUET_FILE)
    assert table.column_names == [name for name, _ in COLUMNS]
    assert sorted(table.to_pylist(), key=lambda row: row["name"]) == _sqlite_rows(out / INDEX_FILE)
    # Both present: the summary reads the newer (here the parquet) and gives the same totals.
    os.utime(out / INDEX_FILE, ns=(1, 1))
    assert summarize(out) == from_sqlite
    (out / INDEX_FILE).unlink()
    assert summarize(out) == from_sqlite
    result = CliRunner().invoke(main, ["dataset", "summary", str(out)])
    assert result.exit_code == 0, result.output
    assert "scenarios: 4 (ok 2, failed 1, pending 1)" in result.stdout


def test_a_broken_parquet_index_is_named(batch_out):
    pytest.importorskip("pyarrow.parquet", reason="pyarrow is not installed (the parquet index is optional)")
    out, _jobs = batch_out
    (out / PARQUET_FILE).write_bytes(b"PAR1 not really")
    with pytest.raises(DatasetError, match=f"{PARQUET_FILE}: not a readable dataset index"):
        summarize(out)


def test_parquet_without_pyarrow_is_refused_before_any_job(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "pyarrow", None)  # what `import pyarrow` meets in an install without it
    monkeypatch.setitem(sys.modules, "pyarrow.parquet", None)
    with pytest.raises(MissingExtraError, match="needs pyarrow") as caught:
        check_index_format("parquet")
    assert "--index sqlite" in caught.value.hint and "grove-tui[parquet]" in caught.value.hint
    jobs = tmp_path / "jobs.jsonl"
    jobs.write_text(json.dumps({"world": "hospital", "preset": "normal", "prompt": "Two nurses walk"}) + "\n",
                    encoding="utf-8")
    result = CliRunner().invoke(main, ["batch", str(jobs), "--out", str(tmp_path / "out"), "--index", "parquet"])
    assert result.exit_code == EXIT_BAD_INPUT
    assert "needs pyarrow" in result.output
    assert not (tmp_path / "out").exists(), "nothing is written"


def test_summary_of_a_folder_without_an_index(tmp_path):
    result = CliRunner().invoke(main, ["dataset", "summary", str(tmp_path)])
    assert result.exit_code == EXIT_BAD_INPUT
    assert f"{tmp_path}: no {INDEX_FILE} or {PARQUET_FILE}" in result.output
    (tmp_path / INDEX_FILE).write_bytes(b"not sqlite at all, just some bytes " * 40)
    with pytest.raises(DatasetError, match="not a readable dataset index"):
        summarize(tmp_path)
