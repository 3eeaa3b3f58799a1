"""Fixtures of the reader's tests."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="session")
def worlds():
    """Every shipped world by name: the reader is checked against all of them, not a chosen few."""
    from grove_tui.world import list_worlds, load_world

    return {name: load_world(name) for name in list_worlds()}
