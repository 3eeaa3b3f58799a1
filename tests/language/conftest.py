"""Fixtures of the reader's tests."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="session")
def worlds():
    """Every shipped world by name: the reader is checked against all of them, not a chosen few."""
    from grove_tui.world import list_worlds, load_world

    return {name: load_world(name) for name in list_worlds()}


@pytest.fixture(scope="session")
def read(worlds):
    """`read(world, prompt)`: the reading of a prompt in a shipped world or an understanding set's world
    (eval/understanding/worlds: "library", "sports_centre"), seed 0."""
    from pathlib import Path

    from grove_tui.language.reading import read_prompt
    from grove_tui.world import load_world

    extra = Path(__file__).resolve().parents[2] / "eval" / "understanding" / "worlds"
    loaded = dict(worlds)

    def reading(world, prompt):
        if world not in loaded:
            loaded[world] = load_world(extra / f"{world}.yaml")
        return read_prompt(prompt, loaded[world], seed=0)

    return reading
