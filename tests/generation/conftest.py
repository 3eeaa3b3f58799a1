"""Fixtures of the generation tests (the worlds and models they share are in tests/conftest.py)."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="module")
def grid(clinic):
    """The clinic's planning grid at the default resolution and inflation."""
    from grove_tui.navigation.grid import build_grid

    return build_grid(clinic)
