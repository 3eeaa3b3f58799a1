"""Issue 21 item 12: when the model is asked again, the output panel says "attempt 2 (reason)" and starts a
fresh section, and the attempt count the app shows is the real one.

The pipeline is the real one (post-processing, planning, bundle); only the model is scripted, because
these tests are about what the screen shows of a retry. The engine's own retry (a real llama.cpp answer
cut off at its budget) is tested in tests/generation/test_synthesis_attempts.py.
"""

from __future__ import annotations

import threading
from typing import Any

import pytest
from helpers.app import PROMPT, QUEUE_DRAFT, FakeLLM, fake_llm_session, test_settings, wait_until
from textual.widgets import DataTable, Static

from grove_tui.errors import ModelError
from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.generation import GenerationScreen
from grove_tui.tui.screens.inspect import InspectScreen
from grove_tui.tui.screens.setup import SetupScreen

pytestmark = pytest.mark.anyio

FIRST_ANSWER_TAIL = "from pharmacy: Sequence(GoTo(pharm"  # where attempt 1 stops


class RetryingLLM(FakeLLM):
    """Attempt 1 goes wrong (`first`: "invalid" streams a draft cut short, "cut off" fills its budget and
    fails as LocalLLM does); attempt 2 streams its first characters, waits for `release`, then the draft."""

    def __init__(self, first: str) -> None:
        super().__init__(QUEUE_DRAFT)
        self.first = first
        self.release = threading.Event()
        self.budgets: list[int] = []

    def generate(self, messages: Any, grammar: str | None = None, *, max_tokens: int = 512, seed: int = 0,
                 on_token: Any = None, cancel: threading.Event | None = None, **kwargs: Any) -> Any:
        from grove_tui.llm.local import Generation

        self.requests += 1
        self.budgets.append(max_tokens)
        assert kwargs.get("length_retries") == 0, "synthesis asks for every attempt itself"
        if self.requests == 1:
            partial = QUEUE_DRAFT[: QUEUE_DRAFT.index(FIRST_ANSWER_TAIL) + len(FIRST_ANSWER_TAIL)]
            for i in range(0, len(partial), 6):
                on_token(partial[i:i + 6])
            if self.first == "cut off":
                raise ModelError(f"the bt model did not finish its answer within {max_tokens} tokens (1 attempts); "
                                 "the output was cut off, so it was not used")
            return Generation(partial, "stop", 120, len(partial) // 6, 0.01, 0.001)
        on_token(QUEUE_DRAFT[:6])
        assert self.release.wait(30), "the test never released attempt 2"
        for i in range(6, len(QUEUE_DRAFT), 6):
            on_token(QUEUE_DRAFT[i:i + 6])
        return Generation(QUEUE_DRAFT, "stop", 120, len(QUEUE_DRAFT) // 6, 0.01, 0.001)


@pytest.mark.slow
@pytest.mark.parametrize(("first", "reason"), [("invalid", "invalid draft"), ("cut off", "cut off at 512 tokens")])
async def test_a_retry_starts_a_fresh_section_and_the_attempt_count_is_real(tmp_path, first, reason):
    llm = RetryingLLM(first)
    session = fake_llm_session(tmp_path / "runs", llm)
    events: list[Any] = []
    generate = session.generate

    def recording_generate(*args: Any, on_event: Any = None, **kwargs: Any) -> Any:
        def record(event: Any) -> None:
            events.append(event)
            on_event(event)
        return generate(*args, on_event=record, **kwargs)

    session.generate = recording_generate  # type: ignore[method-assign]
    app = GroveApp(session, test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen)
                         and app.screen.selected_world is not None and app.screen.selected_preset is not None,
                         what="setup ready")
        await pilot.press(*PROMPT, "enter")
        await wait_until(pilot, lambda: isinstance(app.screen, GenerationScreen), what="generation")
        screen = app.screen
        stream = screen.query_one("#stream", Static)
        await wait_until(pilot, lambda: "attempt 2" in str(stream.render()) and QUEUE_DRAFT[:6] in str(stream.render()),
                         what="attempt 2 streaming")
        shown = str(stream.render())
        assert shown.startswith(f"── attempt 2 ({reason}"), shown
        assert FIRST_ANSWER_TAIL not in shown, "attempt 1's text must not run on into attempt 2's"
        assert shown.count(QUEUE_DRAFT[:6]) == 1, "one answer in the panel, not two spliced together"
        assert str(stream.border_title).endswith("attempt 2")
        table = screen.query_one("#stages", DataTable)
        await wait_until(pilot, lambda: "attempt 2" in str(table.get_cell("synthesis", "detail")),
                         what="the running stage counts the attempt")
        assert str(table.get_cell("synthesis", "tokens")) in ("", "1 tok"), "tokens are attempt 2's own"

        llm.release.set()
        await wait_until(pilot, lambda: isinstance(app.screen, InspectScreen), what="inspect", timeout=60)
        report = app.screen.generated.result.report
        assert report["attempts"] == 2
    finished = [e for e in events if type(e).__name__ == "StageFinished" and e.stage == "synthesis"]
    assert finished and finished[0].detail.endswith("2 attempt(s)"), "the table's count is the real one"
    retries = [e for e in events if type(e).__name__ == "AttemptStarted"]
    assert [(e.stage, e.attempt) for e in retries] == [("synthesis", 2)]
    if first == "cut off":
        assert llm.budgets == [512, 1024], "a cut-off answer is asked again with twice the budget"
    else:
        assert llm.budgets == [512, 512]
