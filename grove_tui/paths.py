"""Where the shipped data lives (worlds, node database, presets) and the user's directories (cache, data,
config; each overridden by its GROVE_*_DIR variable). Light to import: the reader needs the cache dir
without the settings model's pydantic."""

from __future__ import annotations

import os
from pathlib import Path

import platformdirs

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


def _environment_directory(variable: str, default: str) -> Path:
    value = os.environ.get(variable)
    return Path(value).expanduser() if value else Path(default)


def cache_dir() -> Path:
    return _environment_directory("GROVE_CACHE_DIR", platformdirs.user_cache_dir(APP))


def data_dir() -> Path:
    return _environment_directory("GROVE_DATA_DIR", platformdirs.user_data_dir(APP))


def config_dir() -> Path:
    return _environment_directory("GROVE_CONFIG_DIR", platformdirs.user_config_dir(APP))
