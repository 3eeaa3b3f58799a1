"""Fixtures of the app tests (helpers are in tests/helpers/app.py)."""

from __future__ import annotations

from pathlib import Path

import pytest


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




@pytest.fixture(autouse=True)
def unfrozen_heap():
    """A test that warms the app up freezes the heap (tui/heap.py); the next test starts unfrozen."""
    import gc

    yield
    gc.unfreeze()
