"""Issue 28: the app asks before generating a sentence the reader is unsure of."""

from __future__ import annotations

import pytest
from helpers.app import fake_llm_session, setup_ready, test_settings, wait_until
from textual.widgets import Static

from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.choice import ChoiceScreen
from grove_tui.tui.screens.generation import GenerationScreen
from grove_tui.tui.screens.inspect import InspectScreen
from grove_tui.tui.screens.setup import SetupScreen
from grove_tui.tui.widgets.prompt_input import PromptInput

pytestmark = pytest.mark.anyio


@pytest.mark.slow
async def test_an_unsure_reading_is_asked_about_before_generating(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path, ask_when_unsure=True))
    async with app.run_test(size=(80, 24)) as pilot:
        await setup_ready(pilot)
        setup = app.screen
        # "the counter": the hospital has two (the pharmacy's and the cafeteria's food counter)
        await pilot.press(*"ten people queue at the counter", "enter")
        await wait_until(pilot, lambda: isinstance(app.screen, ChoiceScreen), timeout=60, what="the question")
        question = str(app.screen.query_one("#choice-text", Static).render())
        assert "pharmacy" in question and "food_counter" in question
        await pilot.press("e")  # edit the sentence: back on setup, nothing generated
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup again")
        assert isinstance(app.focused, PromptInput) and setup.query_one("#prompt", PromptInput).value
        await pilot.press("enter")
        await wait_until(pilot, lambda: isinstance(app.screen, ChoiceScreen), what="the question again")
        await pilot.press("enter")  # generate as read
        await wait_until(pilot, lambda: isinstance(app.screen, GenerationScreen), timeout=60, what="generation")


@pytest.mark.slow
async def test_a_plain_sentence_generates_without_a_question(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path, ask_when_unsure=True))
    async with app.run_test(size=(80, 24)) as pilot:
        await setup_ready(pilot)
        await pilot.press(*"six patients queue at the pharmacy counter", "enter")
        # the scripted model is quick: the generation screen may already have given way to the inspect screen
        await wait_until(pilot, lambda: isinstance(app.screen, (GenerationScreen, InspectScreen, ChoiceScreen)),
                         timeout=60, what="generation")
        assert isinstance(app.screen, (GenerationScreen, InspectScreen))
