"""The pedestrian model is a user's choice (issue 19): `grove simulate --model`, else the settings'
simulation.pedestrian_model; "grove" by default, "lightsfm" for HuNavSim's forces exactly."""

from __future__ import annotations

import csv

from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.crowd.sfm import SFM_MODELS, SFMParams
from grove_tui.services.session import pedestrian_params
from grove_tui.settings import PEDESTRIAN_MODELS
from helpers.handmade import build_hospital_bundle


def _positions(bundle) -> list[tuple[str, ...]]:
    with open(bundle / "trajectories.csv", newline="") as handle:
        return [tuple(row) for row in csv.reader(handle)]


def test_the_settings_and_the_option_pick_the_model(tmp_path, monkeypatch):
    assert PEDESTRIAN_MODELS == SFM_MODELS
    config = tmp_path / "grove.yaml"
    monkeypatch.setenv("GROVE_CONFIG_FILE", str(config))
    assert pedestrian_params() == SFMParams.named("grove")
    config.write_text("simulation:\n  pedestrian_model: lightsfm\n", encoding="utf-8")
    assert pedestrian_params() == SFMParams.named("lightsfm")
    assert pedestrian_params("grove") == SFMParams.named("grove")  # the option wins over the file

    bundle = build_hospital_bundle(tmp_path / "bundle")
    runner = CliRunner()
    runs = {}
    for model in ("grove", "lightsfm"):
        result = runner.invoke(main, ["simulate", str(bundle), "--seconds", "20", "--model", model])
        assert result.exit_code == 0, result.output
        runs[model] = _positions(bundle)
    assert runs["grove"] != runs["lightsfm"]  # the two models move people differently
    # without the option, the settings' model (lightsfm) runs
    assert runner.invoke(main, ["simulate", str(bundle), "--seconds", "20"]).exit_code == 0
    assert _positions(bundle) == runs["lightsfm"]
    bad = runner.invoke(main, ["simulate", str(bundle), "--model", "helbing"])
    assert bad.exit_code == 2 and "helbing" in bad.output
