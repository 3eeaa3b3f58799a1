"""Where things live: the user's cache/data/config directories and the shipped data directories."""

from __future__ import annotations

import os
from pathlib import Path

import platformdirs

APP = "grove-tui"
PACKAGE_ROOT = Path(__file__).resolve().parent
PROJECT_ROOT = PACKAGE_ROOT.parent


def _env_dir(var: str, default: str) -> Path:
    value = os.environ.get(var)
    path = Path(value) if value else Path(default)
    return path


def cache_dir() -> Path:
    return _env_dir("GROVE_CACHE_DIR", platformdirs.user_cache_dir(APP))


def data_dir() -> Path:
    return _env_dir("GROVE_DATA_DIR", platformdirs.user_data_dir(APP))


def config_dir() -> Path:
    return _env_dir("GROVE_CONFIG_DIR", platformdirs.user_config_dir(APP))


def models_dir() -> Path:
    return data_dir() / "models"


def _shipped(name: str) -> Path:
    # Editable installs and source checkouts keep the data folders beside the package.
    return PROJECT_ROOT / name


def worlds_dir() -> Path:
    return _shipped("worlds")


def node_db_dir() -> Path:
    return _shipped("node_db")


def presets_dir() -> Path:
    return _shipped("presets")
