"""Where the shipped data lives (worlds, node database, presets); the user's directories are in settings."""

from __future__ import annotations

from pathlib import Path

APP = "grove-tui"
PACKAGE_ROOT = Path(__file__).resolve().parent
PROJECT_ROOT = PACKAGE_ROOT.parent


def _shipped(name: str) -> Path:
    # Editable installs and source checkouts keep the data folders beside the package.
    return PROJECT_ROOT / name


def worlds_dir() -> Path:
    return _shipped("worlds")


def node_db_dir() -> Path:
    return _shipped("node_db")


def presets_dir() -> Path:
    return _shipped("presets")
