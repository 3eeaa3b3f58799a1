"""Pilot tests of issue 21's "nothing lost" and seeds: Escape asks, recent runs reopen, `grove open`, new seeds."""

from __future__ import annotations

import pytest
from click.testing import CliRunner
from helpers.app import generate_to_inspect
from helpers.app import CLEAR, open_counts
from helpers.app import (
    fake_llm_session,
    test_settings,
    wait_until,
)
from textual.widgets import Input, OptionList

from grove_tui.cli import main
from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.choice import ChoiceScreen
from grove_tui.tui.screens.export import ExportResultScreen
from grove_tui.tui.screens.generation import counts_by_index
from grove_tui.tui.screens.inspect import InspectScreen
from grove_tui.tui.screens.recent import RecentRunsScreen
from grove_tui.tui.screens.setup import SetupScreen
from grove_tui.tui.widgets.bt_tree import BTTree

pytestmark = pytest.mark.anyio


@pytest.mark.slow
async def test_escape_on_a_new_scenario_asks_and_stay_keeps_it(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        inspect = await generate_to_inspect(pilot, app)
        await pilot.press("escape")
        await wait_until(pilot, lambda: isinstance(app.screen, ChoiceScreen), what="leave question")
        assert "not been exported" in app.screen.text and inspect.generated.bundle_dir.name in app.screen.text
        await pilot.press("n")
        await wait_until(pilot, lambda: app.screen is inspect, what="back on inspect")
        await pilot.press("escape")
        await wait_until(pilot, lambda: isinstance(app.screen, ChoiceScreen), what="leave question again")
        await pilot.press("y")
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")


@pytest.mark.slow
async def test_export_first_then_escape_leaves_without_asking(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        inspect = await generate_to_inspect(pilot, app)
        await pilot.press("escape")
        await wait_until(pilot, lambda: isinstance(app.screen, ChoiceScreen), what="leave question")
        await pilot.press("e")
        await wait_until(pilot, lambda: isinstance(app.screen, ExportResultScreen), timeout=60, what="exported")
        assert not inspect.unsaved
        await pilot.press("escape")
        await wait_until(pilot, lambda: app.screen is inspect, what="inspect")
        await pilot.press("escape")
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup without a question")


@pytest.mark.slow
async def test_recent_runs_reopen_a_saved_bundle_in_inspect(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        first = (await generate_to_inspect(pilot, app)).generated
        await pilot.press("escape", "y")
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
        assert any(b.key == "ctrl+o" and b.show for b in app.screen.active_bindings.values() for b in [b.binding])
        await pilot.press("ctrl+o")
        await wait_until(pilot, lambda: isinstance(app.screen, RecentRunsScreen) and bool(app.screen.runs),
                         what="recent runs listed")
        listing = app.screen
        assert [run.path for run in listing.runs] == [first.bundle_dir]
        run = listing.runs[0]
        assert (run.prompt, run.world, run.preset, run.seed, run.agents) == (first.prompt, "hospital", "queuing", 0, 6)
        assert listing.query_one("#recent-runs", OptionList).highlighted == 0
        await pilot.press("enter")
        await wait_until(pilot, lambda: isinstance(app.screen, InspectScreen), timeout=30, what="reopened")
        reopened = app.screen
        tree = reopened.query_one("#bt-tree", BTTree)
        await wait_until(pilot, lambda: bool(tree.root.children), what="trees shown")
        assert reopened.generated.bundle_dir == first.bundle_dir
        assert [a.id for a in reopened.generated.scenario.agents] == [a.id for a in first.scenario.agents]
        assert reopened.generated.result.trees == first.result.trees
        assert app.generated is reopened.generated
        # nothing new to lose: Escape goes straight back to setup
        await pilot.press("escape")
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")


async def test_recent_runs_list_says_when_there_are_none_and_marks_broken_bundles(tmp_path):
    runs = tmp_path / "runs"
    broken = runs / "20260101-000000-broken-0"
    broken.mkdir(parents=True)
    (broken / "scenario.yaml").write_text("world: [unclosed\n", encoding="utf-8")
    app = GroveApp(fake_llm_session(runs), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
        await pilot.press("ctrl+o")
        await wait_until(pilot, lambda: isinstance(app.screen, RecentRunsScreen) and bool(app.screen.runs),
                         what="listed")
        assert app.screen.runs[0].error, "a broken bundle must say why it cannot open"
        options = app.screen.query_one("#recent-runs", OptionList)
        assert options.get_option_at_index(0).disabled
        await pilot.press("escape")
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="closed")


@pytest.mark.slow
async def test_the_app_opens_a_bundle_given_at_start(tmp_path):
    session = fake_llm_session(tmp_path / "runs")
    app = GroveApp(session, test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        bundle = (await generate_to_inspect(pilot, app)).generated.bundle_dir
    reopened_app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path), open_bundle=bundle)
    async with reopened_app.run_test(size=(80, 24)) as pilot:
        await wait_until(pilot, lambda: isinstance(reopened_app.screen, InspectScreen), timeout=30, what="inspect")
        assert reopened_app.screen.generated.bundle_dir == bundle
        await pilot.press("escape")
        await wait_until(pilot, lambda: isinstance(reopened_app.screen, SetupScreen), what="setup below it")


def test_grove_open_refuses_a_folder_that_is_not_a_bundle(tmp_path):
    result = CliRunner().invoke(main, ["open", str(tmp_path)])
    assert result.exit_code == 2
    assert result.output.startswith("error:") and "scenario.yaml" in result.output


@pytest.mark.slow
async def test_seed_field_sets_the_seed_and_g_regenerates_with_the_next_one(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
        seed = app.screen.query_one("#seed", Input)
        assert seed.value == "0"
        await pilot.press("ctrl+s")
        assert app.focused is seed
        await pilot.press("backspace", *"41", "ctrl+l")
        inspect = await generate_to_inspect(pilot, app)
        assert inspect.generated.seed == 41 and inspect.generated.scenario.seed == 41
        first = inspect.generated
        await pilot.press("g")  # no count edits: no question
        # The regenerated scenario replaces the one shown, in the same inspect screen.
        await wait_until(pilot, lambda: app.screen is inspect and inspect.generated is not first,
                         timeout=60, what="regenerated")
        assert app.screen.generated.seed == 42
        assert app.screen.generated.bundle_dir != first.bundle_dir


@pytest.mark.slow
async def test_g_keeps_count_edits_when_asked_and_drops_them_otherwise(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        inspect = await generate_to_inspect(pilot, app)
        await open_counts(pilot, app)
        await pilot.press(*CLEAR, *"4", "enter")
        await wait_until(pilot, lambda: app.screen is inspect and len(inspect.generated.scenario.agents) == 4,
                         timeout=60, what="re-planned")
        label = inspect.generated.result.report["groups"][0]["label"]
        assert inspect.count_edits == {label: 4}
        await pilot.press("g")
        await wait_until(pilot, lambda: isinstance(app.screen, ChoiceScreen), what="keep counts question")
        assert f"{label} 4" in app.screen.text
        edited = inspect.generated
        await pilot.press("y")
        await wait_until(pilot, lambda: app.screen is inspect and inspect.generated is not edited,
                         timeout=60, what="regenerated with counts")
        kept = app.screen
        assert kept.generated.seed == 1 and len(kept.generated.scenario.agents) == 4
        assert kept.count_edits == {label: 4}
        await pilot.press("g")
        await wait_until(pilot, lambda: isinstance(app.screen, ChoiceScreen), what="question again")
        with_counts = kept.generated
        await pilot.press("n")
        await wait_until(pilot, lambda: app.screen is kept and kept.generated is not with_counts,
                         timeout=60, what="regenerated with the model's counts")
        assert app.screen.generated.seed == 2 and len(app.screen.generated.scenario.agents) == 6
        assert app.screen.count_edits == {}


def test_count_edits_match_groups_by_label():
    groups = [{"label": "patients", "count": 6}, {"label": "nurses", "count": 2}]
    assert counts_by_index(groups, {"patients": 4, "nurses": 2, "visitors": 3}) == ({0: 4}, ["visitors"])
