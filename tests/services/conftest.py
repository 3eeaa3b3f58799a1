"""Fixtures of the services tests."""

from __future__ import annotations

import os

import pytest


@pytest.fixture()
def shared_index(monkeypatch):
    """The retrieval index is built once per machine: reuse the suite's (GROVE_TEST_CACHE_DIR) when it has one."""
    if os.environ.get("GROVE_TEST_CACHE_DIR"):
        monkeypatch.setenv("GROVE_CACHE_DIR", os.environ["GROVE_TEST_CACHE_DIR"])
