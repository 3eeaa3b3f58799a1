"""Fixtures of the reader's tests."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="session")
def worlds():
    """Every shipped world by name: the reader is checked against all of them, not a chosen few."""
    from grove_tui.world import list_worlds, load_world

    return {name: load_world(name) for name in list_worlds()}


@pytest.fixture(scope="session")
def read():
    """read(world, prompt): the reading of a prompt in a shipped world, or in an understanding world
    ("library", "sports_centre") by its name."""
    from pathlib import Path

    from grove_tui.language.reading import read_prompt
    from grove_tui.world import list_worlds, load_world

    extra = Path(__file__).resolve().parents[2] / "eval" / "understanding" / "worlds"
    return lambda world, prompt: read_prompt(
        prompt, load_world(world if world in list_worlds() else extra / f"{world}.yaml"))
