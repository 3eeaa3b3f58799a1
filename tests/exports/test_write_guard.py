"""Nothing lost on the new surfaces (issue 35's data-loss cases): every writer goes through the one guard of
grove_tui/files.py, so it never writes through a link, never replaces a file it did not write (or one not
in its own format) without --overwrite, and never takes a name that is one of a bundle's own files.

Each case runs the real command on a really simulated bundle and checks the user's files byte for byte.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
import yaml
from click.testing import CliRunner
from helpers.handmade import build_hospital_bundle

from grove_tui.cli import main
from grove_tui.errors import BundleError, OutputError
from grove_tui.scenario.bundle import write_bundle
from grove_tui.services.session import GroveSession

EXIT_BAD_INPUT = 2


def invoke(args: list[str]):
    return CliRunner().invoke(main, [str(a) for a in args], catch_exceptions=False)


def listing(root: Path) -> dict[str, bytes | str]:
    out: dict[str, bytes | str] = {}
    for path in sorted(root.rglob("*")):
        rel = str(path.relative_to(root))
        out[rel] = ("-> " + os.readlink(path)) if path.is_symlink() else path.read_bytes() if path.is_file() else "dir"
    return out


# 1. `grove metrics` and a metrics.json link -------------------------------------------------------------------
def test_metrics_never_writes_through_a_metrics_json_link(simulated_copy, tmp_path):
    precious = tmp_path / "thesis.tex"
    precious.write_text("\\chapter{Results}")
    (simulated_copy / "metrics.json").unlink()
    (simulated_copy / "metrics.json").symlink_to(precious)
    run = invoke(["metrics", simulated_copy])
    assert run.exit_code == EXIT_BAD_INPUT, run.output
    assert "metrics.json: is a symbolic link" in run.stderr and run.stderr.count("\n") == 1
    assert precious.read_text() == "\\chapter{Results}"
    assert (simulated_copy / "metrics.json").is_symlink()
    # Simulating again gives the bundle its own metrics.json back (run files never keep a link).
    GroveSession().simulate(simulated_copy, 1.0)
    assert not (simulated_copy / "metrics.json").is_symlink() and invoke(["metrics", simulated_copy]).exit_code == 0
    assert precious.read_text() == "\\chapter{Results}"


# 2. `grove export trajectories` into a folder that is not its own ----------------------------------------------
def test_export_trajectories_keeps_a_users_folder(simulated_copy, tmp_path):
    mine = tmp_path / "analysis"
    mine.mkdir()
    (mine / "trajectories.csv").write_text("my own measurements\n")
    (mine / "notes.md").write_text("keep")
    before = listing(mine)
    run = invoke(["export", "trajectories", simulated_copy, "--out", mine])
    assert run.exit_code == EXIT_BAD_INPUT, run.output
    assert "is not a GROVE trajectories export" in run.stderr and "--overwrite" in run.stderr
    assert listing(mine) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["analysis", "bundle"]  # nothing staged left behind
    # Its own earlier export is replaced; --overwrite replaces the user's folder when asked.
    out = tmp_path / "export"
    assert invoke(["export", "trajectories", simulated_copy, "--out", out]).exit_code == 0
    assert invoke(["export", "trajectories", simulated_copy, "--out", out]).exit_code == 0
    assert sorted(p.name for p in out.iterdir()) == [".grove-trajectories-export", "trajectories.csv",
                                                     "trajectories.sqlite", "trajectories.txt"]
    assert invoke(["export", "trajectories", simulated_copy, "--out", mine, "--overwrite"]).exit_code == 0
    assert not (mine / "notes.md").exists()


@pytest.mark.parametrize("kind", ["trajectories", "hunav", "rosbag"])
def test_an_export_never_replaces_the_bundle_it_reads(simulated_copy, kind):
    if kind == "rosbag":
        pytest.importorskip("rosbags")
    before = listing(simulated_copy)
    for out in (simulated_copy, simulated_copy.parent):
        run = invoke(["export", kind, simulated_copy, "--out", out, "--overwrite"])
        assert run.exit_code == EXIT_BAD_INPUT and "the bundle being exported" in run.stderr, run.output
    assert listing(simulated_copy) == before


# 3. `grove export foxglove` over a file that is not its own ------------------------------------------------------
def test_export_foxglove_keeps_a_file_that_is_not_its_mcap_and_a_users_layout(simulated_copy, tmp_path):
    pytest.importorskip("foxglove")
    mine = tmp_path / "mine.mcap"
    mine.write_text("a recording from the real robot")
    run = invoke(["export", "foxglove", simulated_copy, "--out", mine])
    assert run.exit_code == EXIT_BAD_INPUT and "is not a GROVE Foxglove export" in run.stderr
    assert mine.read_text() == "a recording from the real robot"
    assert not (tmp_path / "mine.layout.json").exists()

    # A layout the user saved from Foxglove: refused before the .mcap is written, both kept.
    other = tmp_path / "other.mcap"
    layout = tmp_path / "other.layout.json"
    layout.write_text('{"my": "layout"}')
    run = invoke(["export", "foxglove", simulated_copy, "--out", other])
    assert run.exit_code == EXIT_BAD_INPUT and "is not a GROVE Foxglove layout" in run.stderr
    assert layout.read_text() == '{"my": "layout"}' and not other.exists()

    # Its own export (and its unchanged layout) are replaced; --overwrite replaces the user's files.
    own = tmp_path / "own.mcap"
    assert invoke(["export", "foxglove", simulated_copy, "--out", own]).exit_code == 0
    assert invoke(["export", "foxglove", simulated_copy, "--out", own]).exit_code == 0
    assert invoke(["export", "foxglove", simulated_copy, "--out", mine, "--overwrite"]).exit_code == 0
    assert mine.read_bytes().startswith(b"\x89MCAP0\r\n")
    assert sorted(p.name for p in tmp_path.iterdir() if p.name.startswith(".")) == []


def test_export_foxglove_never_writes_through_a_link(simulated_copy, tmp_path):
    pytest.importorskip("foxglove")
    precious = tmp_path / "precious.bin"
    precious.write_bytes(b"\x89MCAP0\r\n grove-tui but a link")
    (tmp_path / "x.mcap").symlink_to(precious)
    run = invoke(["export", "foxglove", simulated_copy, "--out", tmp_path / "x.mcap", "--overwrite"])
    assert run.exit_code == EXIT_BAD_INPUT and "symbolic link" in run.stderr
    assert precious.read_bytes() == b"\x89MCAP0\r\n grove-tui but a link"


# 4. `grove import hunav` with `map: scenario` --------------------------------------------------------------------
def test_import_hunav_map_named_scenario_keeps_the_bundles_scenario_yaml(simulated, tmp_path, monkeypatch):
    exported = GroveSession().export("hunav", simulated, tmp_path / "hunav")
    document = yaml.safe_load(exported.agents_yaml.read_text())
    document["hunav_loader"]["ros__parameters"]["map"] = "scenario"
    exported.agents_yaml.write_text(yaml.safe_dump(document))
    run = invoke(["import", "hunav", exported.agents_yaml, "--out", tmp_path / "imported"])
    assert run.exit_code == 0, run.output
    imported = tmp_path / "imported"
    scenario_text = (imported / "scenario.yaml").read_text()
    assert "agents:" in scenario_text and "zones:" not in scenario_text
    assert (imported / "world" / "scenario.yaml").is_file()
    # The bundle plays from anywhere, with its own world (not a same-named file in the current folder).
    elsewhere = tmp_path / "elsewhere"
    (elsewhere / "world").mkdir(parents=True)
    (elsewhere / "world" / "scenario.yaml").write_text("name: decoy\nzones: []\n")
    monkeypatch.chdir(elsewhere)
    assert invoke(["simulate", imported, "--seconds", "1"]).exit_code == 0
    assert invoke(["metrics", imported]).exit_code == 0


def test_a_bundle_file_named_like_the_bundles_own_is_refused(tmp_path):
    from grove_tui.generation.pipeline import GenerationResult
    from grove_tui.scenario.bundle import load_bundle

    bundle = build_hospital_bundle(tmp_path / "b")
    scenario, trees, fields, grid = load_bundle(bundle)
    for name in ("scenario.yaml", "grid.npz", "metrics.json", "../outside.yaml"):
        with pytest.raises(BundleError):
            write_bundle(GenerationResult(scenario, trees, fields, grid, {}, files={name: "zones: []\n"}),
                         tmp_path / "o")
        with pytest.raises(BundleError):  # a tree under such a name too
            write_bundle(GenerationResult(scenario, {**trees, name: trees[scenario.agents[0].tree]}, fields, grid, {}),
                         tmp_path / "o")
    assert not (tmp_path / "o").exists() and not (tmp_path / "outside.yaml").exists()
    # No export may take a bundle's own name inside it either.
    before = listing(bundle)
    with pytest.raises(OutputError, match="trees is the scenario bundle .* own"):
        GroveSession().export("hunav", bundle, bundle / "trees", overwrite=True)
    assert listing(bundle) == before


@pytest.mark.slow
def test_picture_keeps_a_users_image_and_replaces_its_own(simulated_copy, tmp_path):
    pytest.importorskip("matplotlib")
    photo = tmp_path / "figure.png"
    photo.write_bytes(b"\x89PNG\r\n\x1a\n a photo of the lab")
    run = invoke(["picture", simulated_copy, "--out", photo])
    assert run.exit_code == EXIT_BAD_INPUT and "is not a picture GROVE drew" in run.stderr
    assert photo.read_bytes() == b"\x89PNG\r\n\x1a\n a photo of the lab"
    own = tmp_path / "own.svg"
    assert invoke(["picture", simulated_copy, "--out", own]).exit_code == 0
    assert invoke(["picture", simulated_copy, "--out", own]).exit_code == 0
    assert invoke(["picture", simulated_copy, "--out", photo, "--overwrite"]).exit_code == 0
