"""Shared helpers for the TUI tests (imported by test_app_*.py and test_tui_*.py; holds no tests)."""

from __future__ import annotations

import asyncio
import threading
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from grove_tui.backend import EngineBackend, ModelStatus
from grove_tui.config import ExportSettings, GenerationSettings, GroveSettings, SimulationSettings, UISettings


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


# Pipeline events with the engine's class names (the generation screen dispatches on the name).
@dataclass(frozen=True)
class StageStarted:
    stage: str


@dataclass(frozen=True)
class StageFinished:
    stage: str
    seconds: float
    prompt_tokens: int
    completion_tokens: int
    detail: str


@dataclass(frozen=True)
class TokenStreamed:
    stage: str
    text: str


class ScriptedFailure(Exception):
    pass


class ModelError(Exception):
    """Same class name as the engine's, so the screen shows the model hint."""


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

    def __init__(self, script: list[Any], outcome: Any = "block", **kwargs: Any) -> None:
        super().__init__(**kwargs)
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
            if cancel.wait(30):
                self.cancel_seen.set()
                raise ScriptedFailure("cancelled by the user")
            raise AssertionError("generation was never cancelled")
        if isinstance(self.outcome, BaseException):
            raise self.outcome
        return self.outcome


async def wait_until(pilot: Any, condition: Callable[[], bool], timeout: float = 30.0, what: str = "") -> None:
    """Let the app run until `condition()` holds (workers post their messages meanwhile)."""
    loop = asyncio.get_running_loop()
    deadline = loop.time() + timeout
    while not condition():
        if loop.time() > deadline:
            raise AssertionError(f"timed out waiting for {what or condition}")
        await pilot.pause(0.05)
