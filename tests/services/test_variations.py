"""Variations: N scenarios of one prompt, differing in seed and in what the sentence leaves open,
the same N for the same inputs, each recording its index and parent prompt."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.services.jobs import MAX_VARIATIONS, read_jobs, variation_seed


pytestmark = pytest.mark.usefixtures("shared_index")  # tests/conftest.py


def _write_jobs(path: Path, *jobs: dict) -> Path:
    path.write_text("".join(json.dumps(job) + "\n" for job in jobs), encoding="utf-8")
    return path


def test_a_job_with_variations_expands_into_named_seeded_jobs(tmp_path):
    jobs, problems = read_jobs(_write_jobs(tmp_path / "jobs.jsonl",
                                           {"world": "hospital", "preset": "normal", "prompt": "a few visitors wait",
                                            "seed": 7, "name": "wait", "variations": 3},
                                           {"world": "hospital", "preset": "normal", "prompt": "two nurses walk",
                                            "name": "nurses"}))
    assert problems == []
    assert [job.name for job in jobs] == ["wait-v000", "wait-v001", "wait-v002", "nurses"]
    assert jobs[0].seed == 7, "variation 0 is the plain job"
    assert len({job.seed for job in jobs[:3]}) == 3
    assert [job.variation.index for job in jobs[:3]] == [0, 1, 2]
    assert {job.variation.parent_seed for job in jobs[:3]} == {7} and jobs[3].variation is None
    again, _ = read_jobs(tmp_path / "jobs.jsonl")
    assert again == jobs, "the same file gives the same jobs and seeds"


def test_variation_seeds_are_in_range_and_do_not_overlap_between_neighbouring_seeds():
    first = {variation_seed(1, i) for i in range(1, 200)}
    second = {variation_seed(2, i) for i in range(1, 200)}
    assert not first & second
    assert all(0 <= seed < 2**32 for seed in first | second)


@pytest.mark.parametrize("value, message", [(0, "between 1 and"), (MAX_VARIATIONS + 1, "between 1 and"),
                                            ("3", "whole number"), (True, "whole number")])
def test_bad_variations_are_refused_with_the_line(tmp_path, value, message):
    jobs, problems = read_jobs(_write_jobs(tmp_path / "jobs.jsonl",
                                           {"world": "hospital", "preset": "normal", "prompt": "p", "variations": value},
                                           {"world": "hospital", "preset": "normal", "prompt": "q"}))
    assert len(jobs) == 1 and len(problems) == 1
    assert problems[0].line == 1 and message in problems[0].message


def test_an_expanded_name_clashing_with_another_line_is_refused(tmp_path):
    jobs, problems = read_jobs(_write_jobs(tmp_path / "jobs.jsonl",
                                           {"world": "hospital", "preset": "normal", "prompt": "p", "name": "a-v001"},
                                           {"world": "hospital", "preset": "normal", "prompt": "q", "name": "a",
                                            "variations": 2}))
    assert [job.name for job in jobs] == ["a-v001"]
    assert problems[0].line == 2 and "already used by line 1" in problems[0].message


@pytest.mark.slow
def test_generate_variations_writes_distinct_recorded_reproducible_bundles(tmp_path):
    prompt = "a few visitors walk to the cafeteria"
    base = ["generate", "--no-ui", "--world", "hospital", "--preset", "normal", "--prompt", prompt, "--seed", "5",
            "--no-robot"]
    result = CliRunner().invoke(main, [*base, "--variations", "3", "--out", str(tmp_path / "vars")])
    assert result.exit_code == 0, result.output
    bundles = [tmp_path / "vars" / f"v{i:03d}" for i in range(3)]
    reports = [json.loads((b / "generation.json").read_text(encoding="utf-8")) for b in bundles]
    assert [r["variation"]["index"] for r in reports] == [0, 1, 2]
    assert {r["variation"]["parent_prompt"] for r in reports} == {prompt}
    assert {r["variation"]["count"] for r in reports} == {3}
    assert reports[0]["seed"] == 5 and len({r["seed"] for r in reports}) == 3
    scenarios = [(b / "scenario.yaml").read_bytes() for b in bundles]
    assert len(set(scenarios)) == 3, "each variation is a different scenario"
    # Variation 0 is the plain generation with the parent seed: same inputs, same bundle.
    plain = CliRunner().invoke(main, [*base, "--out", str(tmp_path / "plain")])
    assert plain.exit_code == 0, plain.output
    assert (tmp_path / "plain" / "scenario.yaml").read_bytes() == scenarios[0]
    assert "variation" not in json.loads((tmp_path / "plain" / "generation.json").read_text(encoding="utf-8"))
