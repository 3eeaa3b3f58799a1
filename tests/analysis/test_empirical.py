"""Issue 32: the crowd against measured crowds (`grove validate empirical`), on cheap subsets."""

from __future__ import annotations

import numpy as np
import pytest
from click.testing import CliRunner

from grove_tui.analysis import empirical
from grove_tui.cli.validate import validate
from grove_tui.crowd.sfm import SFMParams


def test_weidmann_curve_from_the_committed_constants():
    speeds = [empirical.weidmann_speed(rho) for rho in (0.5, 1, 2, 3, 4, 5.4)]
    assert speeds == pytest.approx([1.298, 1.058, 0.606, 0.331, 0.156, 0.0], abs=1e-3)
    sources = empirical.published()
    assert "Weidmann" in sources["weidmann_1993"]["source"]
    assert sources["bottleneck"]["band"] == [1.3, 1.9] and len(sources["bottleneck"]["sources"]) >= 3


def test_the_default_model_walks_weidmanns_curve_where_lightsfm_does_not():
    sparse, dense = empirical.fundamental_diagram(SFMParams.named("grove"), densities=(1.0, 3.0)).rows
    for density, speed, expected, _off in (sparse, dense):
        assert abs(float(speed) / float(expected) - 1.0) <= empirical.FD_TOLERANCE, (density, speed, expected)
    lightsfm = empirical.fundamental_diagram(SFMParams.named("lightsfm"), densities=(3.0,))
    assert not lightsfm.passed  # its crowd walks at free speed whatever the density


def test_a_one_metre_twenty_bottleneck_passes_a_laboratory_flow():
    flow, unfinished = empirical.bottleneck_flow(1.2, SFMParams.named("grove"))
    low, high = empirical.published()["bottleneck"]["band"]
    assert not unfinished and low <= flow / 1.2 <= high, flow


def test_a_zero_point_eight_metre_bottleneck_is_not_narrower_than_its_width():
    """The narrowest width asked: people reaching its mouth abreast used to block each other at the
    jambs (1.30 per m s, under the band); laboratory crowds pass it at least as fast per metre as
    wider ones (Kretz et al. 2006)."""
    flow, unfinished = empirical.bottleneck_flow(0.8, SFMParams.named("grove"))
    low, high = empirical.published()["bottleneck"]["band"]
    assert not unfinished and low + 0.1 <= flow / 0.8 <= high, flow


def test_linearity_is_a_straight_line_fit():
    slope, intercept, r2 = empirical.linear_fit([0.8, 1.6, 2.4], [1.6, 3.2, 4.8])
    assert (slope, intercept, r2) == pytest.approx((2.0, 0.0, 1.0), abs=1e-9)
    _s, _i, bent = empirical.linear_fit([0.8, 1.6, 2.4], [1.6, 3.2, 1.0])
    assert bent < 0.95


def test_counterflow_sorts_itself_into_lanes():
    result = empirical.lane_formation(SFMParams.named("grove"))
    assert result.passed, result
    # the order parameter itself: clean lanes score 1, a lane of mixed directions little
    pos = np.array([[x, 1.0] for x in range(5)] + [[x, 2.0] for x in range(5)], dtype=float)
    assert empirical.lane_order(pos, np.array([1] * 5 + [-1] * 5), 30.0) == 1.0
    mixed = np.array([[0.0, 1.0], [0.5, 1.0], [1.0, 1.0], [1.5, 1.0]])
    assert empirical.lane_order(mixed, np.array([1, -1, 1, -1]), 30.0) == pytest.approx(1 / 9)


@pytest.mark.slow
def test_the_command_reports_both_models_and_fails_only_for_the_default():
    runner = CliRunner()
    both = runner.invoke(validate, ["empirical", "--check", "lanes"])
    assert both.exit_code == 0, both.output
    assert "model grove" in both.output and "model lightsfm" in both.output
    reported = runner.invoke(validate, ["empirical", "--model", "lightsfm", "--check", "fd"])
    assert reported.exit_code == 0 and "FAIL" in reported.output  # lightsfm reports; only grove must pass
    assert runner.invoke(validate, ["empirical", "--check", "walls"]).exit_code != 0
