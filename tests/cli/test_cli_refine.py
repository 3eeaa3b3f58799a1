"""`grove refine BUNDLE --prompt ... (--out NEW | --in-place)`: the diff first, atomic writes through the
bundle writer, exit 2 with the choices for a name two groups share, nothing written on bad input.
Count, pace and robot edits call no model, so these run on a bundle made with a scripted draft."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.errors import EXIT_BAD_INPUT, EXIT_OK
from grove_tui.scenario.bundle import load_report
from grove_tui.world import load_world
from helpers.refining import build_base_bundle

TWO_NURSES = "two nurses walk to the cafeteria while a nurse waits in the pharmacy"
TWO_NURSES_DRAFT = "2 nurses from pharmacy: GoTo(cafeteria)\n1 nurse from pharmacy: GoTo(pharmacy)"


@pytest.fixture(scope="module")
def bundles(tmp_path_factory):
    world = load_world("hospital")
    root = tmp_path_factory.mktemp("bundles")
    return {"base": build_base_bundle(root / "base", world),
            "nurses": build_base_bundle(root / "nurses", world, "normal", TWO_NURSES, TWO_NURSES_DRAFT)}


def invoke(*args: str):
    return CliRunner().invoke(main, ["refine", *args], catch_exceptions=False)


@pytest.mark.slow
def test_refine_into_a_new_bundle_prints_the_diff_first(bundles, tmp_path):
    out = tmp_path / "refined"
    result = invoke(str(bundles["base"]), "--prompt", "make the queue twice as long", "--out", str(out))
    assert result.exit_code == EXIT_OK, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0] == "follow-up 1: make the queue twice as long"
    assert lines[1].strip() == "~ patient: ×10 → ×20"
    assert f"bundle: {out}" in result.stdout and "changed by 2" in result.stdout
    assert load_report(out)["history"][0]["sentence"] == "make the queue twice as long"
    assert "history" not in load_report(bundles["base"])  # the source is left as it was


def test_in_place_and_dry_run(bundles, tmp_path):
    import shutil

    bundle = tmp_path / "copy"
    shutil.copytree(bundles["base"], bundle)
    before = (bundle / "scenario.yaml").read_bytes()
    dry = invoke(str(bundle), "--prompt", "no robot", "--dry-run")
    assert dry.exit_code == EXIT_OK and "- robot:" in dry.stdout
    assert (bundle / "scenario.yaml").read_bytes() == before
    result = invoke(str(bundle), "--prompt", "no robot", "--in-place", "--json")
    assert result.exit_code == EXIT_OK, result.stderr
    payload = json.loads(result.stdout)
    assert payload["applied"] and payload["diff"]["robot"]["kind"] == "removed"
    assert "robot: null" in (bundle / "scenario.yaml").read_text()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["copy"]  # no staging folder left behind


@pytest.mark.parametrize("args, message", [
    (["--prompt", "make the queue longer"], "--out NEW or --in-place"),
    (["--prompt", "the lights are off", "--out", "x"], "changes nothing"),
    (["--prompt", "   ", "--out", "x"], "the follow-up is empty"),
])
def test_bad_follow_ups_exit_2_and_write_nothing(bundles, tmp_path, args, message):
    out_args = [str(tmp_path / a) if a == "x" else a for a in args]
    result = invoke(str(bundles["base"]), *out_args)
    assert result.exit_code == EXIT_BAD_INPUT and message in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_a_name_two_groups_share_exits_2_with_the_choices_and_group_picks(bundles, tmp_path):
    ambiguous = invoke(str(bundles["nurses"]), "--prompt", "the nurse walks slowly", "--out", str(tmp_path / "a"))
    assert ambiguous.exit_code == EXIT_BAD_INPUT
    assert "'the nurse' could be group 1 (nurse ×2: walk to cafeteria" in ambiguous.stderr
    assert "group 2 (nurse ×1" in ambiguous.stderr and "--group" in ambiguous.stderr
    assert not (tmp_path / "a").exists()
    picked = invoke(str(bundles["nurses"]), "--prompt", "the nurse walks slowly", "--group", "2",
                    "--out", str(tmp_path / "b"))
    assert picked.exit_code == EXIT_OK, picked.stderr
    groups = load_report(tmp_path / "b")["groups"]
    assert [g.get("changed_by", []) for g in groups] == [[], [1]]


def test_a_bundle_whose_group_records_are_broken_is_refused_in_one_line(bundles, tmp_path):
    import shutil

    bundle = tmp_path / "broken"
    shutil.copytree(bundles["base"], bundle)
    report = json.loads((bundle / "generation.json").read_text())
    report["groups"][0]["reading"] = {"who": 1}
    (bundle / "generation.json").write_text(json.dumps(report))
    result = invoke(str(bundle), "--prompt", "no robot", "--out", str(tmp_path / "out"))
    assert result.exit_code == EXIT_BAD_INPUT and "cannot be read as the scenario's groups" in result.stderr
    assert not (tmp_path / "out").exists()
