"""The app's settings: defaults < YAML file in the user config dir < GROVE_* environment variables.

The YAML file is `config_dir()/config.yaml` (override the file with GROVE_CONFIG_FILE). Nested
environment variables use `__`, e.g. `GROVE_SIMULATION__FPS=30`. The `keymap` section maps
binding ids (shown by F1) to keys, e.g. `keymap: {sim.play: p}`.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Literal

from pydantic import BaseModel, Field
from pydantic_settings import BaseSettings, PydanticBaseSettingsSource, SettingsConfigDict, YamlConfigSettingsSource

from grove_tui.paths import config_dir, data_dir


def config_file() -> Path:
    override = os.environ.get("GROVE_CONFIG_FILE")
    return Path(override) if override else config_dir() / "config.yaml"


class UISettings(BaseModel):
    theme: str = "textual-dark"
    """Textual theme name (any built-in theme)."""
    animation: Literal["none", "basic", "full"] = "none"
    """Animation level; 'none' keeps SSH sessions responsive."""
    preload_models: bool = True
    """Load the GGUF models in the background as soon as the app opens."""


class GenerationSettings(BaseModel):
    world: str | None = None
    """World selected at start (a shipped name or a path); None picks the first shipped world."""
    preset: str = "normal"
    """Preset selected at start."""
    seed: int = 0
    """Seed for generation and simulation, so a prompt reproduces the same scenario."""
    history_size: int = Field(default=200, ge=0)
    """How many prompts the history keeps (Up/Down in the prompt box)."""


class SimulationSettings(BaseModel):
    fps: int = Field(default=20, ge=5, le=60)
    """Frames per second of the simulation view."""
    speed: float = Field(default=1.0, gt=0)
    """Initial playback speed (simulated seconds per real second)."""
    colour_by: Literal["group", "behavior"] = "group"
    """What agent colours show: their group or their HuNavSim behavior."""
    robot_speed: float = Field(default=0.8, gt=0)
    """Speed (m/s) of the robot when driven with the arrow keys."""


class ExportSettings(BaseModel):
    directory: Path = Field(default_factory=lambda: data_dir() / "exports")
    """Where exports are written; each export gets its own sub-directory."""


class GroveSettings(BaseSettings):
    model_config = SettingsConfigDict(env_prefix="GROVE_", env_nested_delimiter="__", extra="ignore")

    ui: UISettings = Field(default_factory=UISettings)
    generation: GenerationSettings = Field(default_factory=GenerationSettings)
    simulation: SimulationSettings = Field(default_factory=SimulationSettings)
    export: ExportSettings = Field(default_factory=ExportSettings)
    keymap: dict[str, str] = Field(default_factory=dict)
    """Binding id -> comma-separated keys, applied with App.set_keymap."""

    @classmethod
    def settings_customise_sources(
        cls,
        settings_cls: type[BaseSettings],
        init_settings: PydanticBaseSettingsSource,
        env_settings: PydanticBaseSettingsSource,
        dotenv_settings: PydanticBaseSettingsSource,
        file_secret_settings: PydanticBaseSettingsSource,
    ) -> tuple[PydanticBaseSettingsSource, ...]:
        yaml_source = YamlConfigSettingsSource(settings_cls, yaml_file=config_file(), yaml_file_encoding="utf-8")
        return (init_settings, env_settings, yaml_source)


def load_settings() -> GroveSettings:
    """Read the settings; a broken config file raises pydantic's ValidationError naming the key."""
    return GroveSettings()


def history_file() -> Path:
    return data_dir() / "prompt_history.txt"


def load_history(limit: int) -> list[str]:
    path = history_file()
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except FileNotFoundError:
        return []
    return [line for line in lines if line.strip()][-limit:] if limit else []


def save_history(history: list[str], limit: int) -> None:
    from grove_tui.files import write_text_atomic

    if limit <= 0:
        return
    path = history_file()
    path.parent.mkdir(parents=True, exist_ok=True)
    write_text_atomic(path, "\n".join(history[-limit:]) + "\n")
