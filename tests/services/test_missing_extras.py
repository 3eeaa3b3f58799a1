"""A missing optional part (Ray, rosbags, foxglove-sdk; pyarrow in test_dataset_index.py) is one error line with the line that
installs it, exit 2, and nothing written: no output folder, no empty dataset index, no half bag.

Each part is hidden from the import system (a None entry in sys.modules makes `import` fail as if
the package were absent), so the check holds whether or not this machine has the extra installed.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.errors import EXIT_BAD_INPUT
from grove_tui.exports.foxglove import FOXGLOVE_MODULES
from grove_tui.exports.rosbag import ROSBAGS_MODULES

JOB = {"world": "hospital", "preset": "normal", "prompt": "two visitors walk to ward a", "seed": 0}


def _hide(monkeypatch, modules) -> None:
    for name in modules:
        monkeypatch.setitem(sys.modules, name, None)


def _jobs(tmp_path: Path) -> Path:
    path = tmp_path / "jobs.jsonl"
    path.write_text(json.dumps(JOB) + "\n")
    return path


def _one_error_line(result) -> str:
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert result.exit_code == EXIT_BAD_INPUT, result.output
    assert len(lines) == 1 and lines[0].startswith("error: "), result.output
    assert "Traceback" not in result.output
    return lines[0]


@pytest.mark.parametrize("existing", [False, True], ids=["new-out", "existing-out"])
def test_batch_on_ray_without_ray_says_so_and_writes_nothing(monkeypatch, tmp_path, existing):
    _hide(monkeypatch, ["ray"])
    out = tmp_path / "out"
    if existing:
        out.mkdir()
    result = CliRunner().invoke(main, ["batch", str(_jobs(tmp_path)), "--out", str(out), "--ray"])
    line = _one_error_line(result)
    assert "needs Ray" in line and "install.sh cluster" in line and "grove-tui[cluster]" in line
    assert out.is_dir() == existing
    assert not existing or list(out.iterdir()) == []  # no empty dataset.sqlite, no probe file


def test_rosbag_export_without_rosbags_says_so_and_writes_nothing(monkeypatch, bundle, tmp_path):
    _hide(monkeypatch, ROSBAGS_MODULES)
    out = tmp_path / "bag"
    result = CliRunner().invoke(main, ["export", "rosbag", str(bundle), "--out", str(out)])
    line = _one_error_line(result)
    assert "needs rosbags" in line and "grove-tui[ros]" in line
    assert not out.exists()


def test_foxglove_export_without_foxglove_sdk_says_so_and_writes_nothing(monkeypatch, bundle, tmp_path):
    _hide(monkeypatch, FOXGLOVE_MODULES)
    out = tmp_path / "scene.mcap"
    result = CliRunner().invoke(main, ["export", "foxglove", str(bundle), "--out", str(out)])
    line = _one_error_line(result)
    assert "needs foxglove-sdk" in line and "grove-tui[ros]" in line
    assert list(tmp_path.iterdir()) == []
