"""Issue 21 items 3 and 9: the running stage shows elapsed time, tokens/s and an ETA; the models and the
embedder are warmed at start-up with a status saying when they are ready; a broken model is shown in
full and Enter refuses to generate with the reason."""

from __future__ import annotations

import pytest
from helpers.app import (
    FIXED_SCRIPT,
    ScriptedSession,
    StageStarted,
    fake_llm_session,
    test_settings,
    wait_until,
)
from textual.widgets import DataTable, Static

from grove_tui.services.session import ModelStatus
from grove_tui.settings import UISettings
from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.generation import GenerationScreen, StageProgress
from grove_tui.tui.screens.setup import SetupScreen

pytestmark = pytest.mark.anyio
PROMPT = "six patients queue at the pharmacy counter"


async def start_generation(pilot, app: GroveApp) -> GenerationScreen:
    await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
    await wait_until(pilot, lambda: app.screen.selected_world is not None and app.screen.selected_preset is not None,
                     what="catalogue")
    await pilot.press(*PROMPT, "enter")
    await wait_until(pilot, lambda: isinstance(app.screen, GenerationScreen), what="generation")
    return app.screen


@pytest.mark.slow
async def test_the_running_stage_shows_elapsed_time_tokens_rate_and_eta(tmp_path):
    session = ScriptedSession(FIXED_SCRIPT, outcome="block", block_seconds=20)
    app = GroveApp(session, test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await start_generation(pilot, app)
        table = screen.query_one("#stages", DataTable)
        await wait_until(pilot, lambda: "tok/s" in str(table.get_cell("synthesis", "detail")), what="rate shown")
        detail = str(table.get_cell("synthesis", "detail"))
        assert "ETA ≤" in detail, "no run of synthesis yet: the ETA is the token cap's bound"
        assert str(table.get_cell("synthesis", "tokens")) == "1 tok"
        first = float(str(table.get_cell("synthesis", "time")).removesuffix("s"))
        await wait_until(pilot, lambda: float(str(table.get_cell("synthesis", "time")).removesuffix("s")) >= first + 0.5,
                         what="elapsed time advances")
        # RoIs finished before: its numbers are the stage's own, not the running display
        assert str(table.get_cell("rois", "tokens")) == "310+12"
        assert app.stage_tokens["rois"] == 12
        await pilot.press("escape")
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="cancelled")


@pytest.mark.slow
async def test_before_the_first_token_the_stage_says_the_model_reads_the_prompt(tmp_path):
    session = ScriptedSession([StageStarted("rois")], outcome="block", block_seconds=20)
    app = GroveApp(session, test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await start_generation(pilot, app)
        table = screen.query_one("#stages", DataTable)
        await wait_until(pilot, lambda: "reading the prompt" in str(table.get_cell("rois", "detail")),
                         what="prefill shown")
        assert str(table.get_cell("rois", "time")).endswith("s")
        await pilot.press("escape")


def test_eta_comes_from_the_last_run_of_the_stage_when_known():
    progress = StageProgress("synthesis", started=100.0, tokens=50, first_token=102.0)
    time_cell, tokens, detail = progress.describe(112.0, expected_tokens=150, bound=False)
    assert (time_cell, tokens) == ("12.0s", "50 tok")
    assert detail == "5.0 tok/s · ETA ~20s"
    assert StageProgress("retrieval", started=0.0).describe(3.0, None, True) == ("3.0s", "", "")


async def test_models_and_embedder_are_warmed_at_start_and_the_panel_says_ready(tmp_path):
    settings = test_settings(tmp_path).model_copy(update={"ui": UISettings(preload_models=True)})
    session = fake_llm_session(tmp_path / "runs")
    app = GroveApp(session, settings)
    async with app.run_test(size=(80, 24)) as pilot:
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
        models = app.screen.query_one("#models", Static)
        await wait_until(pilot, lambda: "ready to generate" in str(models.render()), timeout=60, what="ready")
        text = str(models.render())
        assert "roi loaded" in text and "bt  loaded" in text and "emb ready" in text
        assert session.embedder_ready()


class BrokenModelSession(ScriptedSession):
    PROBLEM = "ModelError: /models/roi.gguf: not a GGUF file (bad magic bytes), re-download it"

    def model_status(self) -> list[ModelStatus]:
        return [ModelStatus("roi", "roi.gguf", False, self.PROBLEM), ModelStatus("bt", "bt.gguf", True)]


@pytest.mark.slow
async def test_a_broken_model_is_shown_in_full_and_enter_refuses_with_the_reason(tmp_path):
    session = BrokenModelSession(FIXED_SCRIPT)
    app = GroveApp(session, test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
        setup = app.screen
        models = setup.query_one("#models", Static)
        await wait_until(pilot, lambda: "error" in str(models.render()), what="model status")
        problems = setup.query_one("#model-problems", Static)
        assert problems.display and "re-download it" in str(problems.render()).replace("\n", " "), "message cut off"
        assert models.has_class("-broken")
        await wait_until(pilot, lambda: setup.selected_world is not None and setup.selected_preset is not None,
                         what="catalogue")
        await pilot.press(*PROMPT, "enter")
        await pilot.pause(0.3)
        assert app.screen is setup, "generation started with a model known to be broken"
        assert not session.blocking.is_set()
        assert any("re-download it" in str(n.message) and n.severity == "error" for n in app._notifications)
