"""Nothing GROVE did not write is deleted or replaced; every output folder is complete or absent.

One test per data-loss case of the reliability issue: a user's folder given as `--out`, device nodes
and other special files, duplicate batch names, base names that climb out of `--out`, `--out .`, and
an interrupt between two simulation outputs.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.files import OutputError, atomic_directory, check_output_dir, write_bytes_atomic
from grove_tui.scenario.bundle import RUN_FILES, is_bundle, replace_run_outputs, write_bundle
from grove_tui.generation.draft import DraftGroup
from grove_tui.services.jobs import read_jobs

EXIT_BAD_INPUT = 2


def invoke(args: list[str]):
    return CliRunner().invoke(main, args, catch_exceptions=False)


def tree_listing(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


@pytest.fixture(scope="module")
def result(clinic):
    from helpers.clinic import QUEUE, make_result

    return make_result(clinic, "queuing", "Six patients in the lobby queue at the pharmacy counter",
                       [DraftGroup("patients", 6, "lobby", QUEUE)])


@pytest.fixture
def users_folder(tmp_path) -> Path:
    folder = tmp_path / "thesis"
    (folder / "chapters").mkdir(parents=True)
    (folder / "chapters" / "one.tex").write_text("\\chapter{One}")
    (folder / "notes.txt").write_text("do not lose me")
    return folder


# --out naming a user's folder ----------------------------------------------------------------------
def test_generate_refuses_a_users_folder_before_loading_any_model(users_folder, tmp_path):
    before = tree_listing(users_folder)
    run = invoke(["generate", "--no-ui", "--world", "hospital", "--preset", "queuing", "--prompt",
                  "Six patients queue at the pharmacy", "--out", str(users_folder),
                  "--bt-model", str(tmp_path / "no-such-model.gguf")])
    assert run.exit_code == EXIT_BAD_INPUT
    assert "is not a scenario bundle" in run.stderr and "--overwrite" in run.stderr
    assert tree_listing(users_folder) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["thesis"]  # no staging folder left behind


def test_write_bundle_replaces_a_bundle_but_not_a_users_folder(result, users_folder, tmp_path):
    before = tree_listing(users_folder)
    with pytest.raises(OutputError, match="--overwrite"):
        write_bundle(result, users_folder)
    assert tree_listing(users_folder) == before
    first = write_bundle(result, tmp_path / "bundle")
    (first / "trees" / "agent_1.xml").write_text("stale")
    again = write_bundle(result, tmp_path / "bundle")  # a bundle is replaced as a whole
    assert (again / "trees" / "agent_1.xml").read_text() != "stale"
    assert is_bundle(again)
    forced = write_bundle(result, users_folder, overwrite=True)
    assert is_bundle(forced) and not (forced / "notes.txt").exists()


def test_an_empty_folder_is_used_as_is(result, tmp_path):
    empty = tmp_path / "empty"
    empty.mkdir()
    assert is_bundle(write_bundle(result, empty))


# device nodes and other special files ----------------------------------------------------------------
def test_device_nodes_pipes_files_and_links_are_refused_untouched(tmp_path, result):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    plain = tmp_path / "plain.txt"
    plain.write_text("keep")
    link = tmp_path / "link"
    link.symlink_to(tmp_path)
    for special, kind in ((Path("/dev/null"), "a device node"), (fifo, "a named pipe"), (plain, "a file"),
                          (link, "a symbolic link")):
        with pytest.raises(OutputError, match=kind):
            check_output_dir(special, owned=is_bundle)
        with pytest.raises(OutputError, match=kind):
            write_bundle(result, special)
    assert Path("/dev/null").is_char_device()
    assert fifo.is_fifo() and plain.read_text() == "keep" and link.is_symlink()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link", "pipe", "plain.txt"]


def test_generate_refuses_a_device_node_as_out(tmp_path):
    run = invoke(["generate", "--no-ui", "--world", "hospital", "--preset", "queuing", "--prompt", "Six patients",
                  "--out", "/dev/null", "--bt-model", str(tmp_path / "none.gguf")])
    assert run.exit_code == EXIT_BAD_INPUT and "device node" in run.stderr
    assert Path("/dev/null").is_char_device()


def test_single_file_writes_refuse_devices_and_folders(tmp_path):
    with pytest.raises(OutputError, match="device node"):
        write_bytes_atomic("/dev/null", b"x")
    with pytest.raises(OutputError, match="folder"):
        write_bytes_atomic(tmp_path, b"x")
    assert list(tmp_path.iterdir()) == []


# duplicate batch names --------------------------------------------------------------------------------
def test_duplicate_batch_names_are_refused_with_line_numbers(tmp_path):
    jobs = tmp_path / "jobs.jsonl"
    jobs.write_text("\n".join(json.dumps(j) for j in [
        {"world": "hospital", "preset": "queuing", "prompt": "Six patients queue", "name": "same"},
        {"world": "office", "preset": "normal", "prompt": "Four people walk", "name": "same"},
        {"world": "office", "preset": "normal", "prompt": "Four people walk", "name": "SAME"},
        {"world": "office", "preset": "normal", "prompt": "Four people walk"},
    ]) + "\n")
    good, problems = read_jobs(jobs)
    assert [j.line for j in good] == [1, 4]
    assert [(p.line, "already used by line 1" in p.message) for p in problems] == [(2, True), (3, True)]


# base names climbing out of --out ---------------------------------------------------------------------
@pytest.mark.parametrize("base", ["../../x", "/tmp/x", "..", ".", "a/b", ""])
def test_export_base_name_cannot_escape_out(tmp_path, result, base):
    bundle = write_bundle(result, tmp_path / "bundle")
    out = tmp_path / "deep" / "er" / "out"
    run = invoke(["export", "hunav", str(bundle), "--out", str(out), "--base-name", base])
    assert run.exit_code == EXIT_BAD_INPUT, run.output
    assert "--base-name" in run.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bundle"]


def test_export_refuses_a_users_folder_and_replaces_its_own(tmp_path, result, users_folder):
    bundle = write_bundle(result, tmp_path / "bundle")
    before = tree_listing(users_folder)
    run = invoke(["export", "hunav", str(bundle), "--out", str(users_folder)])
    assert run.exit_code == EXIT_BAD_INPUT and "--overwrite" in run.stderr
    assert tree_listing(users_folder) == before
    out = tmp_path / "hunav"
    assert invoke(["export", "hunav", str(bundle), "--out", str(out)]).exit_code == 0
    assert invoke(["export", "hunav", str(bundle), "--out", str(out)]).exit_code == 0


# --out . ---------------------------------------------------------------------------------------------
def test_out_dot_writes_the_current_folder_and_leaves_no_staging(tmp_path, result, monkeypatch):
    here = tmp_path / "here"
    here.mkdir()
    monkeypatch.chdir(here)
    written = write_bundle(result, ".")
    assert written == here and is_bundle(here)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["here"]


def test_out_dot_in_a_users_folder_is_refused_and_leaves_no_staging(tmp_path, result, users_folder, monkeypatch):
    monkeypatch.chdir(users_folder)
    with pytest.raises(OutputError):
        write_bundle(result, ".")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["thesis"]
    assert sorted(p.name for p in users_folder.iterdir()) == ["chapters", "notes.txt"]


# an interrupt between two simulation outputs -----------------------------------------------------------
def test_an_interrupted_run_keeps_the_old_outputs_together(tmp_path, result):
    bundle = write_bundle(result, tmp_path / "bundle")

    def old_run(stage: Path) -> None:
        for name in RUN_FILES:
            (stage / name).write_text(f"old {name}")

    replace_run_outputs(bundle, old_run)
    before = tree_listing(bundle)

    def interrupted(stage: Path) -> None:
        (stage / "trajectories.csv").write_text("new trajectories")
        raise KeyboardInterrupt  # Ctrl-C right after trajectories.csv landed

    with pytest.raises(KeyboardInterrupt):
        replace_run_outputs(bundle, interrupted)
    assert tree_listing(bundle) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bundle"]

    def new_run(stage: Path) -> None:
        for name in RUN_FILES:
            (stage / name).write_text(f"new {name}")

    replace_run_outputs(bundle, new_run)
    after = tree_listing(bundle)
    assert {name: after[name] for name in RUN_FILES} == {name: f"new {name}".encode() for name in RUN_FILES}
    assert {k: v for k, v in after.items() if k not in RUN_FILES} == \
        {k: v for k, v in before.items() if k not in RUN_FILES}


def test_a_folder_that_changed_under_the_staging_is_not_replaced(tmp_path):
    target = tmp_path / "out"
    with pytest.raises(OutputError):
        with atomic_directory(target, owned=is_bundle) as stage:
            (stage / "scenario.yaml").write_text("x")
            target.mkdir()
            (target / "precious.txt").write_text("appeared meanwhile")
    assert (target / "precious.txt").read_text() == "appeared meanwhile"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


def test_outputs_get_the_usual_permissions_not_private_temp_ones(tmp_path, result):
    previous = os.umask(0o022)
    try:
        bundle = write_bundle(result, tmp_path / "bundle")
        write_bytes_atomic(tmp_path / "file.bin", b"x")
    finally:
        os.umask(previous)
    assert (bundle.stat().st_mode & 0o777) == 0o755
    assert ((tmp_path / "file.bin").stat().st_mode & 0o777) == 0o644
