"""`grove eval` end to end with the embedded model on one case: bundles, scores, tables."""

from __future__ import annotations

import csv

import pytest
from click.testing import CliRunner

from grove_tui.cli import main

pytestmark = pytest.mark.slow  # every test here runs a real model


def test_eval_runs_grove_and_baselines_on_a_case(tmp_path):
    suite = tmp_path / "suite.yaml"
    suite.write_text(
        "cases:\n"
        "  - id: home-tv\n"
        "    world: residential\n"
        "    preset: normal\n"
        "    prompt: two people walk from the kitchen to the sofa in the living room\n"
        "    seed: 4\n"
        "    expect: {targets: [living_room, sofa], spawns: [kitchen], count: 2}\n"
    )
    out = tmp_path / "out"
    result = CliRunner().invoke(main, ["eval", str(suite), "--out", str(out), "--seconds", "10",
                                       "--methods", "grove,no-planner,decoupled"])
    assert result.exit_code == 0, result.output
    rows = {r["method"]: r for r in csv.DictReader((out / "results.csv").open())}
    assert set(rows) == {"grove", "no-planner", "decoupled"}
    for method, row in rows.items():
        assert row["error"] == "", (method, row["error"])
        assert float(row["wall_penetrations"]) == 0.0
        assert float(row["hallucinated_node_types"]) == 0.0
        assert (out / "bundles" / "home-tv" / method / "trajectories.csv").exists()
    assert float(rows["grove"]["count_accuracy"]) == 1.0
    assert float(rows["grove"]["spawn_grounding"]) == 1.0  # the prompt puts them in the kitchen
    assert float(rows["grove"]["prompt_tokens"]) > 0
    markdown = (out / "RESULTS.md").read_text()
    assert "| normal | grove |" in markdown and "grove eval" in markdown
