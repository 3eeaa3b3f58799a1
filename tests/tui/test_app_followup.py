"""Pilot tests of the inspect screen's follow-up box at 80x24: the diff before anything runs, applying,
asking which group, undo and redo, and the keys in F1. The model is the UI tests' fake one."""

from __future__ import annotations

import pytest
from helpers.app import FakeLLM, fake_llm_session, generate_to_inspect, test_settings, wait_until
from textual.widgets import Static

from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.help import HelpScreen, key_rows
from grove_tui.tui.screens.inspect import InspectScreen
from grove_tui.tui.screens.refine import RefineScreen
from grove_tui.tui.widgets.bt_tree import BTTree
from grove_tui.tui.widgets.followup import FollowupInput
from grove_tui.tui.widgets.grounding import grounding_text, read_grounding

pytestmark = pytest.mark.anyio
GUARDS = "2 guards from main_entrance: GoTo(main_entrance)"


class FollowUpLLM(FakeLLM):
    """The fake model: the queue's draft first, then the drafts scripted for the follow-ups."""

    def __init__(self, *later: str) -> None:
        super().__init__()
        self.later = list(later)

    def generate(self, messages, grammar=None, **kwargs):
        self.asked = messages
        if self.requests >= 1 and self.later and "\nGroups:" in messages[-1]["content"]:
            self.text = self.later.pop(0)
        return super().generate(messages, grammar, **kwargs)


async def follow_up(pilot, app, sentence: str) -> RefineScreen:
    if not isinstance(app.focused, FollowupInput):  # after an edit the box keeps the keys
        await pilot.press("f")
    await wait_until(pilot, lambda: isinstance(app.focused, FollowupInput), what="follow-up box focused")
    await pilot.press("end", "ctrl+u", *sentence, "enter")  # a cancelled sentence stays in the box to edit
    await wait_until(pilot, lambda: isinstance(app.screen, RefineScreen), what="follow-up dialog")
    dialog = app.screen
    await wait_until(pilot, lambda: dialog.state in ("ready", "asking", "failed"), timeout=60, what="diff read")
    return dialog


def diff_text(dialog: RefineScreen) -> str:
    return str(dialog.query_one("#refine-diff", Static).render())


@pytest.mark.slow
async def test_follow_ups_on_the_inspect_screen(tmp_path):
    """One app session (a generation costs seconds): count, cancel, add, refusal, ambiguity, undo, redo, keys."""
    llm = FollowUpLLM(GUARDS, "4 patients from pharmacy: Sequence(GoTo(pharmacy_counter), Queue(pharmacy_counter))")
    app = GroveApp(fake_llm_session(tmp_path / "runs", llm), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        inspect = await generate_to_inspect(pilot, app)
        first = inspect.generated
        requests = llm.requests

        # a count: the diff first, then applied without the model; the box is ready for the next one
        dialog = await follow_up(pilot, app, "make the queue twice as long")
        assert diff_text(dialog).splitlines()[0] == "~ patient: ×6 → ×12"
        assert inspect.generated is first  # nothing applied yet
        await pilot.press("enter")
        await wait_until(pilot, lambda: app.screen is inspect and inspect.generated is not first, timeout=60,
                         what="applied")
        second = inspect.generated
        assert len(second.scenario.agents) == 12 and llm.requests == requests
        assert second.result.report["history"][0]["sentence"] == "make the queue twice as long"
        await wait_until(pilot, lambda: isinstance(app.focused, FollowupInput), what="the box ready again")
        assert app.focused.value == ""
        tree = inspect.query_one("#bt-tree", BTTree)
        await wait_until(pilot, lambda: "12 agents" in str(tree.border_title), what="trees rebuilt")

        # undo and redo, with the box focused (ctrl+z is not a key of the box)
        await pilot.press("ctrl+z")
        await wait_until(pilot, lambda: inspect.generated is first, what="undone")
        assert "6 agents" in str(tree.border_title)
        await pilot.press("ctrl+y")
        await wait_until(pilot, lambda: inspect.generated is second, what="redone")

        # an addition: Escape cancels before anything runs, Enter asks the model for the new group alone
        dialog = await follow_up(pilot, app, "add two guards standing at the main entrance")
        assert diff_text(dialog).startswith("+ guard ×2: wait at main_entrance")
        await pilot.press("escape")
        await wait_until(pilot, lambda: app.screen is inspect, what="dialog closed")
        assert inspect.generated is second
        await follow_up(pilot, app, "add two guards standing at the main entrance")
        await pilot.press("enter")
        await wait_until(pilot, lambda: app.screen is inspect and inspect.generated is not second, timeout=60,
                         what="guards added")
        lines = llm.asked[-1]["content"].splitlines()
        groups_line = " ".join(lines[lines.index("Groups:") + 1:])  # the lean draft's numbered groups
        assert "guard x2" in groups_line and "patient" not in groups_line
        third = inspect.generated
        assert [g["label"] for g in third.result.report["groups"]] == ["patient", "guard"]
        kept = [a for a in third.scenario.agents if a.label == "patient"]
        assert kept == [a for a in second.scenario.agents]  # the queue as it was
        # the grounding report names every sentence and which one asked for each group
        report = grounding_text(read_grounding(third.result.report), width=200)
        assert "3. add two guards standing at the main entrance" in report
        assert "sentence 1, changed by 2" in report and "sentence 3" in report

        # a sentence that changes nothing says why and applies nothing
        dialog = await follow_up(pilot, app, "remove the janitor")
        assert dialog.state == "failed" and "names no group" in diff_text(dialog)
        await pilot.press("escape")
        await wait_until(pilot, lambda: app.screen is inspect, what="closed")
        assert inspect.generated is third

        # a name two groups share is asked about, by number
        await follow_up(pilot, app, "plus four more patients")
        await pilot.press("enter")
        await wait_until(pilot, lambda: app.screen is inspect and len(inspect.generated.result.report["groups"]) == 3,
                         timeout=60, what="second patient group")
        dialog = await follow_up(pilot, app, "the patient walks slowly")
        assert dialog.state == "asking"
        text = diff_text(dialog)
        assert "Which group is 'the patient'?" in text and "1  patient ×12" in text and "2  patient ×4" in text
        await pilot.press("2")
        await wait_until(pilot, lambda: dialog.state == "ready", what="diff after the answer")
        assert diff_text(dialog).splitlines()[0] == "~ patient: normal → slow pace"
        await pilot.press("enter")
        await wait_until(pilot, lambda: app.screen is inspect and len(inspect.undo_stack) == 4, timeout=60,
                         what="applied")
        groups = inspect.generated.result.report["groups"]
        assert [g.get("changed_by", []) for g in groups] == [[1], [], [4]]

        # Escape in the box gives the keys back to the trees without leaving; F1 lists the keys
        await pilot.press("escape")
        await wait_until(pilot, lambda: isinstance(app.focused, BTTree), what="trees focused")
        assert app.screen is inspect
        ids = {ident for _, _, ident in key_rows(inspect)}
        assert {"inspect.followup", "inspect.undo", "inspect.redo"} <= ids
        await pilot.press("f1")
        await wait_until(pilot, lambda: isinstance(app.screen, HelpScreen), what="help")


def test_the_follow_up_keys_have_ids_and_reach_the_app_over_ssh():
    for owner in (FollowupInput, RefineScreen, InspectScreen):
        for binding in owner.BINDINGS:
            assert binding.id and binding.description, f"{owner.__name__}: {binding.key}"
            assert all(len(k) == 1 or k in ("escape", "enter", "up", "down", "f1") or
                       (k.startswith("ctrl+") and len(k) == 6) for k in binding.key.split(","))
