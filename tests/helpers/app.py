"""Helpers of the app tests: settings, a scripted session, a fake LLM, waits, and the walks to a screen.

Fixtures live in tests/tui/conftest.py."""

from __future__ import annotations

import asyncio
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from grove_tui.services.session import MODEL_NICENESS, GroveSession, ModelStatus
from grove_tui.settings import ExportSettings, GenerationSettings, GroveSettings, SimulationSettings, UISettings


def test_settings(tmp_path: Path, **overrides: Any) -> GroveSettings:
    return GroveSettings(
        # Asking about unsure readings has its own tests (test_app_unsure.py); the flows here type
        # sentences with guessed counts and generate them as read.
        ui=UISettings(preload_models=False, ask_when_unsure=overrides.pop("ask_when_unsure", False)),
        generation=GenerationSettings(world="hospital", preset=overrides.pop("preset", "queuing"), seed=0),
        simulation=SimulationSettings(fps=overrides.pop("fps", 20), speed=overrides.pop("speed", 1.0)),
        export=ExportSettings(directory=tmp_path / "exports"),
        **overrides,
    )


test_settings.__test__ = False  # type: ignore[attr-defined]  # a helper, not a test


# The engine's own pipeline events: the fake session emits exactly what the real pipeline emits.
from grove_tui.generation.pipeline import StageFinished, StageStarted, TokenStreamed  # noqa: E402,F401


class ScriptedFailure(Exception):
    pass




FIXED_SCRIPT: list[Any] = [
    StageStarted("rois"),
    TokenStreamed("rois", '{"rois": ["pharmacy", '),
    TokenStreamed("rois", '"pharmacy_counter"]}'),
    StageFinished("rois", 0.42, 310, 12, "2 places"),
    StageStarted("retrieval"),
    StageFinished("retrieval", 0.08, 0, 0, "6 nodes"),
    StageStarted("synthesis"),
    TokenStreamed("synthesis", '{"groups": [{"label": "patients", "count": 10, '),
]


class ScriptedSession(GroveSession):
    """Real worlds and presets; generation replays a fixed event script, then blocks, fails or returns."""

    def __init__(self, script: list[Any], outcome: Any = "block", block_seconds: float = 30.0, **kwargs: Any) -> None:
        kwargs.setdefault("model_niceness", MODEL_NICENESS)  # as the app's session (GroveSession.for_app)
        kwargs.setdefault("remember_step_seconds", True)
        super().__init__(**kwargs)
        self.block_seconds = block_seconds
        self.script = script
        self.outcome = outcome
        self.blocking = threading.Event()
        self.cancel_seen = threading.Event()

    def model_status(self) -> list[ModelStatus]:
        return [ModelStatus("roi", "scripted.gguf", True), ModelStatus("bt", "scripted.gguf", True)]

    def load_models(self) -> Any:
        return None

    def generate(self, request: Any, out_dir: Any = None, *, on_event: Callable[[Any], None] | None = None,
                 cancel: threading.Event | None = None, **_: Any) -> Any:
        assert on_event is not None and cancel is not None
        for event in self.script:
            on_event(event)
        if self.outcome == "block":
            self.blocking.set()
            if cancel.wait(self.block_seconds):
                self.cancel_seen.set()
                raise ScriptedFailure("cancelled by the user")
            raise AssertionError("generation was never cancelled")
        if isinstance(self.outcome, BaseException):
            raise self.outcome
        return self.outcome


async def wait_until(pilot: Any, condition: Callable[[], bool], timeout: float = 30.0, what: str = "") -> None:
    """Let the app run until `condition()` holds (workers post their messages meanwhile).

    A screen just pushed is the app's screen before it has composed (much later on a cold first
    run), so the wait also covers the current screen being mounted: callers query its widgets
    next. A widget the condition itself queries may not exist yet: NoMatches means "not yet".
    """
    from textual.css.query import NoMatches

    def holds() -> bool:
        try:
            return bool(condition()) and bool(getattr(pilot.app.screen, "is_mounted", True))
        except NoMatches:
            return False

    loop = asyncio.get_running_loop()
    deadline = loop.time() + timeout
    while not holds():
        if loop.time() > deadline:
            raise AssertionError(f"timed out waiting for {what or condition}")
        await pilot.pause(0.05)


async def map_laid_out(pilot: Any, world_map: Any) -> None:
    """Wait until a MapView has drawn its raster for the size it finally got from the layout."""
    await wait_until(
        pilot,
        lambda: world_map.raster is not None and world_map._fit_for == (world_map.size.width, world_map.size.height),
        what="map laid out",
    )


# --- a fake LLM and a lexical retriever for UI-only tests of the real pipeline ----------------------

QUEUE_DRAFT = "6 patients from pharmacy: Sequence(GoTo(pharmacy_counter), Queue(pharmacy_counter))"


class FakeLLM:
    """Answers every request with a fixed draft, streamed a few characters at a time."""

    def __init__(self, text: str = QUEUE_DRAFT, path: str = "fake-model.gguf") -> None:
        self.text = text
        self.path = Path(path)
        self.running = True
        self.requests = 0

    def generate(self, messages: Any, grammar: str | None = None, *, max_tokens: int = 512, seed: int = 0,
                 on_token: Callable[[str], None] | None = None, cancel: threading.Event | None = None,
                 **_: Any) -> Any:
        from grove_tui.llm.local import Generation

        self.requests += 1
        chunks = [self.text[i:i + 6] for i in range(0, len(self.text), 6)]
        for chunk in chunks:
            if cancel is not None and cancel.is_set():
                from grove_tui.errors import GroveError

                raise GroveError("cancelled")
            if on_token is not None:
                on_token(chunk)
        return Generation(self.text, "stop", 120, len(chunks), 0.01, 0.001)

    def close(self) -> None:
        self.running = False


def lexical_retriever() -> Any:
    """The real node database, ranked by shared words instead of embeddings (no torch, no index build)."""
    from grove_tui.generation.retrieval import NodeRetriever, RetrievedNode, content_tokens

    class LexicalRetriever(NodeRetriever):
        def retrieve(self, prompt: str, preset: Any = None, k: int = 8) -> list[Any]:
            words = set(content_tokens(prompt))
            scored = []
            for name in self.document_names(preset):
                doc = self._documents[name]
                overlap = len(words & set(content_tokens(doc.text)))
                scored.append((-overlap, name))
            scored.sort()
            return [RetrievedNode(name=n, kind=self._documents[n].kind, score=float(-s), document=self._documents[n].text,
                                  nodes=self._documents[n].nodes) for s, n in scored[:k]]

    return LexicalRetriever()


def fake_llm_session(runs_dir: Path, llm: FakeLLM | None = None) -> GroveSession:
    model = llm or FakeLLM()
    return GroveSession.for_app(llm_factory=lambda role, info: model, retriever_factory=lexical_retriever,
                                runs_dir=runs_dir)


# ---- walks to a screen (shared by the flow, map, counters, export, runs, replan and snapshot tests)
from textual.widgets import Input, Static, TextArea  # noqa: E402

from grove_tui.tui.app import GroveApp  # noqa: E402
from grove_tui.tui.screens.generation import GenerationScreen  # noqa: E402
from grove_tui.tui.screens.inspect import InspectScreen  # noqa: E402
from grove_tui.tui.screens.setup import SetupScreen  # noqa: E402
from grove_tui.tui.screens.simulation import SimulationScreen  # noqa: E402
from grove_tui.tui.widgets.bt_tree import BTTree  # noqa: E402
from grove_tui.tui.widgets.map_view import MapView  # noqa: E402

PROMPT = "six patients queue at the pharmacy counter"


async def generate_to_inspect(pilot, app: GroveApp, prompt: str = PROMPT, timeout: float = 60) -> InspectScreen:
    await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
    setup = app.screen
    await wait_until(pilot, lambda: setup.query_one("#preview", MapView).raster is not None, what="preview")
    await pilot.press(*prompt, "enter")
    await wait_until(pilot, lambda: isinstance(app.screen, (GenerationScreen, InspectScreen)), what="generation")
    await wait_until(pilot, lambda: isinstance(app.screen, InspectScreen)
                     or (isinstance(app.screen, GenerationScreen) and app.screen.query_one("#gen-error").display),
                     timeout=timeout, what="inspect screen")
    if isinstance(app.screen, GenerationScreen):
        pytest.fail("generation failed: " + str(app.screen.query_one("#gen-error", Static).render()))
    inspect = app.screen
    await wait_until(pilot, lambda: bool(inspect.query_one("#bt-tree", BTTree).root.children), what="trees shown")
    return inspect



async def first_frame(pilot, sim: SimulationScreen, timeout: float = 60) -> None:
    status = sim.query_one("#sim-status", Static)
    await wait_until(pilot, lambda: (sim.controller is not None and sim.controller.latest is not None)
                     or "cannot simulate" in str(status.render()), timeout=timeout, what="first frame")
    assert sim.controller is not None, str(status.render())



async def generate_to_simulation(pilot, app: GroveApp) -> SimulationScreen:
    """Generate the default prompt, open the simulation (`p`) and wait for its first frame."""
    await generate_to_inspect(pilot, app)
    await pilot.press("p")
    await wait_until(pilot, lambda: isinstance(app.screen, SimulationScreen), what="simulation screen")
    sim = app.screen
    await first_frame(pilot, sim)
    return sim


def no_blink(app: GroveApp) -> None:
    for widget in [*app.screen.query(Input), *app.screen.query(TextArea)]:
        widget.cursor_blink = False



async def setup_ready(pilot) -> None:
    app = pilot.app
    await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
    screen = app.screen
    await wait_until(pilot, lambda: screen.query_one("#preview", MapView).raster is not None, what="preview")
    await wait_until(pilot, lambda: "loaded" in str(screen.query_one("#models", Static).render())
                     or "demand" in str(screen.query_one("#models", Static).render()), what="model status")
    await wait_until(pilot, lambda: screen.query_one("#preset-description").text.strip() != "",
                     what="preset description")
    no_blink(app)




from grove_tui.tui.screens.counts import CountsScreen  # noqa: E402

CLEAR = ("end", "backspace", "backspace", "backspace")  # counts have at most three digits


async def open_counts(pilot, app: GroveApp) -> CountsScreen:
    await pilot.press("c")
    await wait_until(pilot, lambda: isinstance(app.screen, CountsScreen), what="counts dialog")
    dialog = app.screen
    await wait_until(pilot, lambda: isinstance(app.focused, Input), what="count input focused")
    return dialog


