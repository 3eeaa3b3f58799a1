"""Issue 31 item 1: every text field of the app keeps readline's editing keys (ctrl+w and alt+backspace
delete the word before the cursor, ctrl+u to the start, ctrl+k to the end, ctrl+a / ctrl+e to the
ends), and no screen takes those keys from it. The terminal test (test_tui_e2e_app.py) types them into
the prompt over tmux; this one visits every field: the prompt and the seed on setup, the follow-up box
on inspect, a head count in the counts dialog."""

from __future__ import annotations

import pytest
from helpers.app import fake_llm_session, generate_to_inspect, open_counts, test_settings, wait_until
from textual.widgets import Input, TextArea

from grove_tui.tui.app import GroveApp

pytestmark = pytest.mark.anyio


def text_of(field: Input | TextArea) -> str:
    return field.text if isinstance(field, TextArea) else field.value


async def edit_like_a_shell_user(pilot, field: Input | TextArea, words: tuple[str, str, str]) -> None:
    """Type three words and edit them with readline's keys, checking the field after each."""
    first, second, third = words
    name = field.id
    await pilot.press("ctrl+u", *f"{first} {second} {third}")
    assert text_of(field) == f"{first} {second} {third}", name
    await pilot.press("ctrl+w")
    assert text_of(field) == f"{first} {second} ", name
    await pilot.press("alt+backspace")
    assert text_of(field) == f"{first} ", name
    await pilot.press("ctrl+a", *second, "ctrl+e", *third)
    assert text_of(field) == f"{second}{first} {third}", name
    await pilot.press("ctrl+a", "ctrl+k")
    assert text_of(field) == "", name
    await pilot.press(*f"{first} {second}", "ctrl+u")
    assert text_of(field) == "", name
    assert pilot.app.focused is field, f"{name}: a readline key moved the focus"
    await help_lists_the_keys(pilot, field)


async def help_lists_the_keys(pilot, field: Input | TextArea) -> None:
    """F1 on the field lists its editing keys."""
    from grove_tui.tui.screens.help import HelpPage, HelpScreen

    await pilot.press("f1")
    await wait_until(pilot, lambda: isinstance(pilot.app.screen, HelpScreen), what="help")
    page = pilot.app.screen.query_one(HelpPage).plain_text()
    print(page)
    for key in ("ctrl+w", "alt+backspace", "ctrl+u", "ctrl+k", "ctrl+a", "ctrl+e"):
        assert key in page, f"{field.id}: help does not list {key}"
    await pilot.press("escape")
    await wait_until(pilot, lambda: pilot.app.focused is field, what="back to the field")


async def edit_digits_like_a_shell_user(pilot, field: Input) -> None:
    """The same keys in a field that takes digits only (one word)."""
    name = field.id
    await pilot.press("ctrl+u", *"123", "ctrl+w")
    assert field.value == "", name
    await pilot.press(*"45", "alt+backspace")
    assert field.value == "", name
    await pilot.press("6", "ctrl+a", "8", "ctrl+e", "9")  # head counts take three digits
    assert field.value == "869", name
    await pilot.press("left", "left", "ctrl+k")
    assert field.value == "8", name
    await pilot.press("ctrl+u")
    assert field.value == "", name
    assert pilot.app.focused is field, f"{name}: a readline key moved the focus"
    await help_lists_the_keys(pilot, field)


@pytest.mark.slow
async def test_every_text_field_keeps_readline_keys(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        inspect = await generate_to_inspect(pilot, app)
        await pilot.press("f")
        followup = inspect.query_one("#followup-input", Input)
        await wait_until(pilot, lambda: app.focused is followup, what="the follow-up box")
        await edit_like_a_shell_user(pilot, followup, ("add", "two", "guards"))
        await pilot.press("escape")

        dialog = await open_counts(pilot, app)
        count = dialog.query(Input).first()
        await edit_digits_like_a_shell_user(pilot, count)
        await pilot.press("escape")
        await wait_until(pilot, lambda: app.screen is inspect, what="back on inspect")

        await pilot.press("escape")  # to setup (it may ask: leave the scenario?)
        await wait_until(pilot, lambda: app.screen is not inspect, what="leaving inspect")
        if not app.screen.query("#prompt"):
            await pilot.press("y")
        await wait_until(pilot, lambda: bool(app.screen.query("#prompt")), what="setup")
        setup = app.screen
        prompt = setup.query_one("#prompt", TextArea)
        prompt.focus()
        await wait_until(pilot, lambda: app.focused is prompt, what="the prompt")
        await edit_like_a_shell_user(pilot, prompt, ("six", "nurses", "walk"))
        await pilot.press("ctrl+s")
        seed = setup.query_one("#seed", Input)
        await wait_until(pilot, lambda: app.focused is seed, what="the seed")
        await edit_digits_like_a_shell_user(pilot, seed)
