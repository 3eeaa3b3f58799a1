"""RiMEA verification (issue 19): a fast subset of `grove validate rimea` on the product's crowd."""

from __future__ import annotations

import pytest

from click.testing import CliRunner

from grove_tui.analysis.rimea import run_rimea, test_11_exit_choice as rimea_11, test_9_exits as rimea_9
from grove_tui.cli.validate import validate
from grove_tui.crowd.sfm import SFMParams


def test_corridor_premovement_and_fundamental_diagram_pass_with_the_default_model():
    results = {r.test: r for r, _ in run_rimea("grove", (1, 4, 5))}
    assert all(r.passed for r in results.values()), [r for r in results.values() if not r.passed]
    assert results[1].measured.endswith(" s") and 26.0 <= float(results[1].measured.split()[0]) <= 34.0


def test_lightsfm_fails_where_issue_19_said_it_does():
    """The same checks can fail: HuNavSim's forces barely slow with density and let waiting people drift."""
    results = {r.test: r for r, _ in run_rimea("lightsfm", (4, 5))}
    assert not results[4].passed and not results[5].passed


def test_the_command_prints_the_table_and_exits_1_on_a_failure():
    runner = CliRunner()
    ok = runner.invoke(validate, ["rimea", "--test", "1", "--no-jupedsim"])
    assert ok.exit_code == 0, ok.output
    assert "corridor 40 m at 1.33 m/s" in ok.output and ok.output.rstrip().endswith("pass")
    assert "no JuPedSim column (--no-jupedsim)" in ok.output  # asked off, not "not installed"
    failing = runner.invoke(validate, ["rimea", "--model", "lightsfm", "--test", "5", "--no-jupedsim"])
    assert failing.exit_code == 1 and "FAIL" in failing.output
    unknown = runner.invoke(validate, ["rimea", "--test", "2"])
    assert unknown.exit_code != 0


def test_assigned_routes_and_the_bottleneck_pass_at_product_defaults():
    """RiMEA 10 and 12 in full: every person through the assigned exit; 150 through a 1 m corridor."""
    results = {r.test: r for r, _ in run_rimea("grove", (10, 12))}
    assert results[10].passed, results[10]
    assert results[12].passed, results[12]


@pytest.mark.slow
def test_four_exits_drain_a_room_about_twice_as_fast_as_two():
    """RiMEA 9 scaled down from 1000 to 240 people (the command runs 1000): doors, not walking, set the time."""
    result = rimea_9(SFMParams.named("grove"), people=240)
    assert result.passed, result


def test_least_congested_choice_sends_some_people_to_the_farther_exit():
    """RiMEA 11 scaled down from 1000 to 160 people: exit 1 is nearer for all, yet exit 2 is used too."""
    result = rimea_11(SFMParams.named("grove"), people=160)
    assert result.passed, result
    assert "nearest 160/0" in result.measured  # what the nearest-exit choice alone would do
