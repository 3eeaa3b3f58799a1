"""Batch job lines with "refine": [...] follow-ups: checked with the other keys, part of the inputs hash."""

from __future__ import annotations

import json
from dataclasses import replace

import pytest

from grove_tui.services.dataset import job_inputs_hash
from grove_tui.services.jobs import read_jobs

LINE = {"world": "hospital", "preset": "queuing", "prompt": "ten patients queue at the pharmacy"}


def jobs_of(tmp_path, *lines):
    path = tmp_path / "jobs.jsonl"
    path.write_text("\n".join(json.dumps(line) for line in lines) + "\n", encoding="utf-8")
    return read_jobs(path)


def test_follow_ups_are_read_and_change_the_inputs_hash(tmp_path):
    (plain, refined), problems = jobs_of(tmp_path, dict(LINE, name="a"),
                                         dict(LINE, name="a2", refine=["make the queue twice as long", "no robot"]))
    assert not problems
    assert plain.refine == () and refined.refine == ("make the queue twice as long", "no robot")
    assert job_inputs_hash(refined, {}) != job_inputs_hash(replace(refined, refine=()), {})


@pytest.mark.parametrize("value, message", [
    ("make it longer", "refine must be a list"),
    ([""], "refine[0] is empty"),
    (["x" * 3000], "refine[0] is 3000 characters"),
    (["a"] * 21, "at most 20"),
])
def test_bad_follow_up_lists_are_refused_with_the_line(tmp_path, value, message):
    jobs, problems = jobs_of(tmp_path, dict(LINE, name="ok"), dict(LINE, name="bad", refine=value))
    assert [j.name for j in jobs] == ["ok"]
    assert problems[0].line == 2 and message in problems[0].message
