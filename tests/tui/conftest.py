"""Fixtures of the app tests (helpers are in tests/helpers/app.py)."""

from __future__ import annotations

from pathlib import Path

import pytest


@pytest.fixture
def anyio_backend() -> str:
    return "asyncio"



@pytest.fixture(scope="session")
def door_graphs(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """One folder of door graphs (navigation/door_graph.py) for every app test of the session."""
    return tmp_path_factory.mktemp("door_graphs")


@pytest.fixture(scope="session")
def place_vectors(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """One folder of the worlds' place-name vectors (language/meaning.py) for every app test of the session."""
    return tmp_path_factory.mktemp("place_vectors")


@pytest.fixture(autouse=True)
def isolated_user_dirs(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, door_graphs: Path,
                       place_vectors: Path) -> Path:
    """Config, data and cache go to the test's tmp dir, never the developer's real ones.

    The data dir's door graphs are the session's: a door graph is a cache keyed by a hash of the world
    and grid (a stale one is never read), built by the first test that plans in a world (2-4 s for the
    hospital) and read back by the next ones, as on a user's machine after the first run. No app test
    checks the door graph itself (tests/navigation does, on their own folders). The cache dir's place-name
    vectors are shared the same way (keyed by a hash of the names and the model; 0.7 s of encoding per
    test otherwise; tests/language checks them on their own folders).
    """
    from grove_tui.language.meaning import PLACE_VECTORS_FOLDER
    from grove_tui.navigation.door_graph import CACHE_FOLDER

    for name in ("CONFIG", "DATA", "CACHE"):
        folder = tmp_path / name.lower()
        folder.mkdir()
        monkeypatch.setenv(f"GROVE_{name}_DIR", str(folder))
    (tmp_path / "data" / CACHE_FOLDER).symlink_to(door_graphs, target_is_directory=True)
    (tmp_path / "cache" / PLACE_VECTORS_FOLDER).symlink_to(place_vectors, target_is_directory=True)
    monkeypatch.delenv("GROVE_CONFIG_FILE", raising=False)
    return tmp_path




@pytest.fixture(autouse=True)
def unfrozen_heap():
    """A test that warms the app up freezes the heap (tui/heap.py); the next test starts unfrozen."""
    import gc

    yield
    gc.unfreeze()
