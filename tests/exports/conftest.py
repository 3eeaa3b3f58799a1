"""Fixtures of the export tests (the hand-built bundles they read are in tests/conftest.py)."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="module")
def hospital_export(bundle, tmp_path_factory):
    """The HuNavSim export of the module's hand-built hospital `bundle`."""
    from grove_tui.exports.hunav import export_hunav

    return export_hunav(bundle, tmp_path_factory.mktemp("out") / "hunav")
