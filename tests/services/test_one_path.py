"""One application layer: the app's backend, `grove generate`, `grove batch` and `grove eval` write the
same bundle, byte for byte, for the same world, preset, prompt, seed and (embedded) model."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import yaml
from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.services.backend import EngineBackend

WORLD, PRESET, SEED = "hospital", "emergency", 3
PROMPT = "fire alarm: six people in the cafeteria and two in the pharmacy evacuate through the nearest exit"


pytestmark = pytest.mark.usefixtures("shared_index")  # tests/conftest.py


def _files(bundle: Path) -> dict[str, bytes]:
    """The bundle's contract files: scenario.yaml, every tree, every velocity field (and the grid)."""
    names = ["scenario.yaml", "grid.npz"] + [str(p.relative_to(bundle)) for folder in ("trees", "fields")
                                             for p in sorted((bundle / folder).glob("*")) if p.is_file()]
    return {name: (bundle / name).read_bytes() for name in names}


def _invoke(args: list[str]) -> None:
    result = CliRunner().invoke(main, args)
    assert result.exit_code == 0, (args[0], result.stderr, result.stdout)


@pytest.mark.slow
def test_app_generate_batch_and_eval_write_byte_identical_bundles(tmp_path):
    backend = EngineBackend(runs_dir=tmp_path / "runs")
    try:
        app_bundle = backend.generate(WORLD, PRESET, PROMPT, SEED).bundle_dir
    finally:
        backend.close()

    cli_bundle = tmp_path / "generate"
    _invoke(["generate", "--no-ui", "--world", WORLD, "--preset", PRESET, "--prompt", PROMPT, "--seed", str(SEED),
             "--out", str(cli_bundle)])

    jobs = tmp_path / "jobs.jsonl"
    # The job also simulates and exports: neither touches the bundle's contract files.
    jobs.write_text(json.dumps({"world": WORLD, "preset": PRESET, "prompt": PROMPT, "seed": SEED, "name": "one",
                                "simulate": 2, "export": ["hunav", "trajectories"]}) + "\n", encoding="utf-8")
    _invoke(["batch", str(jobs), "--out", str(tmp_path / "batch")])
    assert (tmp_path / "batch" / "one" / "trajectories.csv").is_file()
    assert any((tmp_path / "batch" / "one.hunav").glob("*.yaml"))
    assert (tmp_path / "batch" / "one.trajectories" / "trajectories.csv").is_file()

    suite = tmp_path / "suite.yaml"
    suite.write_text(yaml.safe_dump({"cases": [{"id": "fire", "world": WORLD, "preset": PRESET, "prompt": PROMPT,
                                                "seed": SEED, "expect": {"targets": ["main_entrance"]}}]}),
                     encoding="utf-8")
    _invoke(["eval", str(suite), "--out", str(tmp_path / "eval"), "--methods", "grove", "--seconds", "1"])

    reference = _files(app_bundle)
    assert any(name.startswith("fields/") for name in reference), "the emergency preset writes velocity fields"
    assert any(name.startswith("trees/") for name in reference)
    models = yaml.safe_load(reference["scenario.yaml"])["models"]
    assert set(models) == {"roi", "bt"}, "every path uses and records the RoI model the same way"
    for path in (cli_bundle, tmp_path / "batch" / "one", tmp_path / "eval" / "bundles" / "fire" / "grove"):
        assert _files(path) == reference, path
