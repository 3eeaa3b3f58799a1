"""Shared helpers for the TUI tests (imported by test_app_*.py and test_tui_*.py; holds no tests)."""

from __future__ import annotations

import asyncio
import threading
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from grove_tui.services.backend import EngineBackend, ModelStatus
from grove_tui.settings import ExportSettings, GenerationSettings, GroveSettings, SimulationSettings, UISettings


@pytest.fixture
def anyio_backend() -> str:
    return "asyncio"


@pytest.fixture(autouse=True)
def isolated_user_dirs(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Config, data and cache go to the test's tmp dir, never the developer's real ones."""
    for name in ("CONFIG", "DATA", "CACHE"):
        folder = tmp_path / name.lower()
        folder.mkdir()
        monkeypatch.setenv(f"GROVE_{name}_DIR", str(folder))
    monkeypatch.delenv("GROVE_CONFIG_FILE", raising=False)
    return tmp_path


def test_settings(tmp_path: Path, **overrides: Any) -> GroveSettings:
    return GroveSettings(
        ui=UISettings(preload_models=False),
        generation=GenerationSettings(world="hospital", preset=overrides.pop("preset", "queuing"), seed=0),
        simulation=SimulationSettings(fps=overrides.pop("fps", 20), speed=overrides.pop("speed", 1.0)),
        export=ExportSettings(directory=tmp_path / "exports"),
        **overrides,
    )


test_settings.__test__ = False  # type: ignore[attr-defined]  # a helper, not a test


# The engine's own pipeline events: the fake backend emits exactly what the real pipeline emits.
from grove_tui.generation.pipeline import StageFinished, StageStarted, TokenStreamed  # noqa: E402,F401


class ScriptedFailure(Exception):
    pass


from grove_tui.errors import ModelError  # noqa: E402  the engine's own error, so the screen shows its hint


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


class ScriptedBackend(EngineBackend):
    """Real worlds and presets; generation replays a fixed event script, then blocks, fails or returns."""

    def __init__(self, script: list[Any], outcome: Any = "block", block_seconds: float = 30.0, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.block_seconds = block_seconds
        self.script = script
        self.outcome = outcome
        self.blocking = threading.Event()
        self.cancel_seen = threading.Event()

    def model_status(self) -> list[ModelStatus]:
        return [ModelStatus("roi", "scripted.gguf", True), ModelStatus("bt", "scripted.gguf", True)]

    def load_models(self) -> dict[str, Any]:
        return {}

    def generate(self, world_name: str, preset_name: str, prompt: str, seed: int,
                 on_event: Callable[[Any], None] | None = None, cancel: threading.Event | None = None) -> Any:
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

QUEUE_DRAFT = (
    '{"groups": [{"label": "patients", "count": 6, "spawn": "pharmacy", "tree": {"node": "Sequence", '
    '"children": [{"node": "GoTo", "target": "pharmacy_counter"}, '
    '{"node": "Queue", "service_point": "pharmacy_counter"}]}}]}'
)


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


def fake_llm_backend(runs_dir: Path, llm: FakeLLM | None = None) -> EngineBackend:
    model = llm or FakeLLM()
    return EngineBackend(llm_factory=lambda role, info: model, retriever_factory=lexical_retriever, runs_dir=runs_dir)
