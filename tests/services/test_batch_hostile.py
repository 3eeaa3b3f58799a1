"""Batch under hostile input and crashes (issue 35): a lone surrogate in a prompt, a job named like the batch's
own files, 5,000-digit numbers, a record line torn by kill -9, staging entries a killed run left, and a full
disk. Each is a refused line (with its number), a whole record, or a clean folder: never a traceback, a lost
"ok" or a stale staging folder after the next run.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.errors import EXIT_BAD_INPUT, OutputError, PromptError
from grove_tui.files import _HOST
from grove_tui.services.dataset import INDEX_FILE, STATE_FILE, JobRecord, append_record, read_records, write_index
from grove_tui.services.jobs import read_jobs
from grove_tui.services.session import GroveSession, ScenarioRequest

REPO = Path(__file__).resolve().parents[2]


def job(**extra) -> str:
    return json.dumps({"world": "hospital", "preset": "normal", "prompt": "ten visitors walk to the cafeteria",
                       **extra})


def test_a_lone_surrogate_in_a_prompt_is_a_refused_line_not_an_aborted_batch(tmp_path):
    jobs_file = tmp_path / "jobs.jsonl"
    # JSON's \\ud800 decodes to a lone surrogate, which spaCy, the model and sqlite cannot encode.
    jobs_file.write_text(job(name="good") + "\n" + job(prompt="visitors \ud800 walk", name="bad") + "\n")
    jobs, problems = read_jobs(jobs_file)
    assert [j.name for j in jobs] == ["good"]
    assert [(p.line, p.message) for p in problems] == [
        (2, "prompt is not Unicode text: character 10 is a lone surrogate (\\ud800); JSON \\u escapes must come "
            "in valid pairs")]
    only_bad = tmp_path / "bad.jsonl"
    only_bad.write_text(job(prompt="\udfff", name="bad") + "\n")
    run = CliRunner().invoke(main, ["batch", str(only_bad), "--out", str(tmp_path / "out")])
    assert run.exit_code == EXIT_BAD_INPUT and run.stderr.count("\n") == 1 and "lone surrogate" in run.stderr
    assert not (tmp_path / "out").exists()
    # The same check guards every path into generation (generate, the app, the Gym env).
    with pytest.raises(PromptError, match="lone surrogate"):
        GroveSession().check_request(ScenarioRequest("hospital", "normal", "ten \ud800 visitors", 0))


@pytest.mark.parametrize("name", ["dataset.sqlite", "DATASET.SQLITE", "batch-state.jsonl", "dataset.parquet",
                                  "pharmacy.mcap", "pharmacy.hunav", "x.layout.json"])
def test_a_job_cannot_take_a_name_the_batch_writes_itself(tmp_path, name):
    jobs_file = tmp_path / "jobs.jsonl"
    jobs_file.write_text(job(name=name) + "\n" + job(name="fine") + "\n")
    jobs, problems = read_jobs(jobs_file)
    assert [j.name for j in jobs] == ["fine"] and [p.line for p in problems] == [2 - 1]
    assert name in problems[0].message and "choose another name" in problems[0].message


def test_an_index_blocked_by_a_folder_from_an_earlier_version_is_one_clear_error(tmp_path):
    out = tmp_path / "out"
    (out / INDEX_FILE).mkdir(parents=True)  # what a job named dataset.sqlite left before names were checked
    with pytest.raises(OutputError, match="dataset.sqlite: is a folder.*move it away"):
        write_index(out, [])


def test_huge_numbers_do_not_leak_pythons_own_message(tmp_path):
    jobs_file = tmp_path / "jobs.jsonl"
    jobs_file.write_text('{"world": "hospital", "preset": "normal", "prompt": "x", "variations": '
                         + "9" * 5000 + "}\n" + job() + "\n")
    jobs, problems = read_jobs(jobs_file)
    assert len(jobs) == 1 and problems[0].line == 1
    assert "4,300 digits" in problems[0].message and "sys." not in problems[0].message


def test_a_torn_last_record_does_not_swallow_the_next_one(tmp_path):
    """kill -9 during an append left `{"name": "job-3", "inp`; the next record was glued onto it and the
    job's "ok" was lost (the index said pending for a complete bundle)."""
    out = tmp_path / "out"
    append_record(out, JobRecord("job-1", 1, "h1", "ok", agents=3))
    with open(out / STATE_FILE, "ab") as state:
        state.write(b'{"name": "job-2", "inputs": "h2", "status": "o\xc3')  # torn, even inside a character
    append_record(out, JobRecord("job-3", 3, "h3", "ok", agents=5))
    records = read_records(out)
    assert sorted(records) == ["job-1", "job-3"] and records["job-3"]["status"] == "ok"
    lines = (out / STATE_FILE).read_bytes().splitlines()
    assert len(lines) == 3 and json.loads(lines[-1])["name"] == "job-3"


def _dead_pid() -> int:
    child = subprocess.Popen([sys.executable, "-c", "pass"])
    child.wait()
    return child.pid


def test_the_next_run_removes_what_a_killed_run_left(tmp_path):
    from grove_tui.services.batch import run_batch

    out = tmp_path / "out"
    out.mkdir()
    pid = _dead_pid()
    left = [out / f".visitors.{_HOST}-{pid}.abcd1234.staging", out / f".dataset.sqlite.{_HOST}-{pid}.efgh5678.tmp"]
    left[0].mkdir()
    (left[0] / "scenario.yaml").write_text("half")
    left[1].write_bytes(b"SQLite format 3\x00 half")
    legacy = out / ".dataset.sqlite.tmp"  # what earlier versions left after a crashed index write
    legacy.write_bytes(b"half")
    live = out / f".other.{_HOST}-{os.getpid()}.ijkl9012.staging"  # a live writer's entry is kept
    live.mkdir()
    run_batch(GroveSession(), [], out)
    assert sorted(p.name for p in out.iterdir()) == [live.name, INDEX_FILE]


def test_a_full_disk_leaves_no_empty_output_folder(tmp_path):
    """The batch folder is made by the first record's append; on a full disk that append fails, and the
    batch's error is what the user sees, with no empty folder (or empty batch-state.jsonl) left behind."""
    out = tmp_path / "new" / "out"
    code = ("import resource, signal\n"
            "from pathlib import Path\n"
            "from grove_tui.services.dataset import JobRecord, append_record\n"
            "signal.signal(signal.SIGXFSZ, signal.SIG_IGN)\n"
            "resource.setrlimit(resource.RLIMIT_FSIZE, (1, 1))\n"
            "try:\n"
            f"    append_record(Path({str(out)!r}), JobRecord('job', 1, 'h', 'failed', 'no room', 2))\n"
            "except Exception as exc:\n"
            "    print(type(exc).__name__, exc)\n")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(REPO), os.environ.get("PYTHONPATH", "")]))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300, env=env, cwd=REPO)
    assert done.stdout.startswith("OutputError") and "batch-state.jsonl: cannot write it" in done.stdout, \
        done.stdout + done.stderr[-2000:]
    assert not (tmp_path / "new").exists()
    # A batch with nothing to run into a folder that does not exist makes none.
    from grove_tui.services.batch import run_batch

    run_batch(GroveSession(), [], out)
    assert not (tmp_path / "new").exists()


def test_a_world_generation_cannot_use_is_a_refused_job_not_a_crashed_batch(tmp_path):
    """A 200,000-point boundary passed the checks, then segfaulted in shapely and took the whole batch down
    (exit 139). The job naming it is now a refused line; the others run. bench/hostile.py runs 200,000."""
    from grove_tui.world.loader import MAX_POLYGON_POINTS

    count = MAX_POLYGON_POINTS + 1
    edge = ", ".join(f"[{20 * i / count:.5f}, {0.01 * (i % 2)}]" for i in range(count))
    world = tmp_path / "zigzag.yaml"
    world.write_text("name: zigzag\nzones:\n  - {name: z, type: room, boundary: [" + edge + ", [20, 10], [0, 10]], "
                     "doors: [{name: d, position: [0, 5], width: 1, leads_to: outside}]}\n")
    jobs_file = tmp_path / "jobs.jsonl"
    jobs_file.write_text(job(world=str(world), name="zigzag") + "\n" + job(name="fine") + "\n")
    jobs, problems = read_jobs(jobs_file)
    assert not problems
    good, refused = GroveSession().check_jobs(jobs, tmp_path / "out", overwrite=False)  # the batch's check
    assert [j.name for j in good] == ["fine"] and [p.line for p in refused] == [1]
    assert f"{count + 2:,} points; at most {MAX_POLYGON_POINTS:,} per polygon" in refused[0].message
    assert not (tmp_path / "out").exists()
