"""The one settings model: defaults < the config file < GROVE_* environment variables.

Every GROVE_* variable is read in this module and nowhere else:

    GROVE_CONFIG_FILE      the config file (default: GROVE_CONFIG_DIR/config.yaml)
    GROVE_CONFIG_DIR       user config directory (user presets in presets/); default platformdirs'
    GROVE_DATA_DIR         user data directory (models/, runs/, exports/, prompt history, last choices)
    GROVE_CACHE_DIR        user cache directory (retrieval index, compiled kernels)
    GROVE_MODEL            GGUF for both roles; GROVE_ROI_MODEL / GROVE_BT_MODEL for one role
    GROVE_LLM_THREADS      llama.cpp threads (default: the cores idle at each request)
    GROVE_<SECTION>__<KEY> any key of the file, e.g. GROVE_SIMULATION__FPS=30

The file is YAML with the sections below (`ui`, `generation`, `simulation`, `export`, `keymap`,
`models`, `llm_threads`); `models: {roi: PATH, bt: PATH}` picks the model of each role (paths
relative to the file). The `keymap` section maps binding ids (shown by F1) to keys, e.g.
`keymap: {sim.play: p}`. A file that is not UTF-8, not YAML, uses tags (`!!python/...`), has an
unknown key or a bad value, or a bad GROVE_* value, is a SettingsError (exit 2) naming the key.
The directory variables are read without the file, because the file's default path depends on them.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Literal, TypedDict

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError
from pydantic_settings import BaseSettings, InitSettingsSource, PydanticBaseSettingsSource, SettingsConfigDict

from grove_tui.errors import SettingsError
from grove_tui.limits import InputLimitError, compose_yaml
from grove_tui.paths import APP, cache_dir, config_dir, data_dir  # noqa: F401  (the user's directories, re-exported)

MAX_CONFIG_BYTES = 1024 * 1024
# The pedestrian models a user can pick (crowd.sfm.SFMParams.named); here so that front ends list
# them without compiling the crowd's kernels.
PEDESTRIAN_MODELS = ("grove", "lightsfm")
# Set only in the environment: the file names models in its `models:` section, with paths relative to it.
ENVIRONMENT_ONLY = ("model", "roi_model", "bt_model")




def models_dir() -> Path:
    """Where `grove models pull` writes and the registry looks for GGUF files."""
    return data_dir() / "models"


def config_file() -> Path:
    override = os.environ.get("GROVE_CONFIG_FILE")
    return Path(override).expanduser() if override else config_dir() / "config.yaml"


class _Section(BaseModel):
    # A misspelt key inside a section is an error too, not a default silently kept.
    model_config = ConfigDict(extra="forbid")


class UISettings(_Section):
    theme: str = "textual-dark"
    """Textual theme name (any built-in theme)."""
    animation: Literal["none", "basic", "full"] = "none"
    """Animation level; 'none' keeps SSH sessions responsive."""
    preload_models: bool = True
    """Load the GGUF models in the background as soon as the app opens."""
    ask_when_unsure: bool = True
    """Before generating, ask about what the reader is unsure of in the sentence (two places that fit
    alike, a guessed count, an implied group); false generates the reader's best guess straight away
    (the grounding report still lists the questions)."""


class GenerationSettings(_Section):
    world: str | None = None
    """World selected at the app's first start (a shipped name or a path); None picks the first shipped
    world. Later starts open the world, preset and seed of the last generation (data dir)."""
    preset: str = "normal"
    """Preset selected at the app's first start."""
    seed: int = 0
    """Seed for generation and simulation, so a prompt reproduces the same scenario."""
    history_size: int = Field(default=200, ge=0)
    """How many prompts the history keeps (Up/Down in the prompt box)."""


class SimulationSettings(_Section):
    fps: int = Field(default=20, ge=5, le=60)
    """Frames per second of the simulation view."""
    speed: float = Field(default=1.0, gt=0)
    """Initial playback speed (simulated seconds per real second)."""
    colour_by: Literal["group", "behavior"] = "group"
    """What agent colours show: their group or their HuNavSim behavior."""
    robot_speed: float = Field(default=0.8, gt=0)
    """Speed (m/s) of the robot when driven with the arrow keys."""
    pedestrian_model: Literal["grove", "lightsfm"] = "grove"
    """Pedestrian forces: "grove" (contacts, density slowing, waiting in place; passes RiMEA) or
    "lightsfm" (HuNavSim's forces exactly, as Gazebo runs them): PEDESTRIAN_MODELS."""


class ExportSettings(_Section):
    directory: Path = Field(default_factory=lambda: data_dir() / "exports")
    """Where exports are written; each export gets its own sub-directory."""


class ModelFiles(_Section):
    """The config file's `models:` section: a GGUF per role, relative to the config file."""

    roi: str | None = None
    """GGUF that selects the regions of interest."""
    bt: str | None = None
    """GGUF that writes the behavior trees."""


class GroveSettings(BaseSettings):
    # extra="forbid": a misspelt key in the file is an error, not a setting silently ignored.
    model_config = SettingsConfigDict(env_prefix="GROVE_", env_nested_delimiter="__", extra="forbid")

    ui: UISettings = Field(default_factory=UISettings)
    generation: GenerationSettings = Field(default_factory=GenerationSettings)
    simulation: SimulationSettings = Field(default_factory=SimulationSettings)
    export: ExportSettings = Field(default_factory=ExportSettings)
    keymap: dict[str, str] = Field(default_factory=dict)
    """Binding id -> comma-separated keys, applied with App.set_keymap."""
    models: ModelFiles = Field(default_factory=ModelFiles)
    llm_threads: int | None = Field(default=None, ge=1)
    """llama.cpp threads (GROVE_LLM_THREADS); None uses the cores idle at each request (cpu.py)."""
    model: str | None = None
    """GROVE_MODEL: GGUF for both roles."""
    roi_model: str | None = None
    """GROVE_ROI_MODEL."""
    bt_model: str | None = None
    """GROVE_BT_MODEL."""

    @classmethod
    def settings_customise_sources(
        cls,
        settings_cls: type[BaseSettings],
        init_settings: PydanticBaseSettingsSource,
        env_settings: PydanticBaseSettingsSource,
        dotenv_settings: PydanticBaseSettingsSource,
        file_secret_settings: PydanticBaseSettingsSource,
    ) -> tuple[PydanticBaseSettingsSource, ...]:
        file_source = InitSettingsSource(settings_cls, read_config_file(config_file()))
        return (init_settings, env_settings, file_source)

    def model_file(self, role: str) -> Path | None:
        """The config file's model for `role`, resolved against the file's folder; None when unset."""
        value = getattr(self.models, role)
        if not value:
            return None
        path = Path(value).expanduser()
        return path if path.is_absolute() else config_file().parent / path


def read_config_file(path: Path) -> dict[str, Any]:  # Any: YAML values before pydantic validates them
    """The file's mapping ({} when there is no file); SettingsError when it is not a safe YAML mapping."""
    try:
        if not path.exists():
            return {}
        if not path.is_file():
            raise SettingsError(f"{path}: not a file")
        if path.stat().st_size > MAX_CONFIG_BYTES:
            raise SettingsError(f"{path}: larger than {MAX_CONFIG_BYTES // 1024} KB; a config file is a few lines")
        text = path.read_bytes().decode("utf-8")
    except UnicodeDecodeError as exc:
        raise SettingsError(f"{path}: not UTF-8 text (byte {exc.start})") from None
    except OSError as exc:
        raise SettingsError(f"{path}: cannot read it: {exc.strerror}") from None
    try:
        # Safe semantics refuse !!python/... tags: a config file must never run code. The node graph is
        # measured first, so a 500-byte alias bomb is refused instead of hanging validation.
        data = compose_yaml(text)[0]
    except InputLimitError as exc:
        line = f" (line {exc.line})" if exc.line else ""
        raise SettingsError(f"{path}{line}: {exc}") from None
    except yaml.YAMLError as exc:
        where = getattr(exc, "problem_mark", None)
        line = f" (line {where.line + 1})" if where is not None else ""
        problem = getattr(exc, "problem", None) or str(exc).splitlines()[0]
        raise SettingsError(f"{path}: not valid YAML{line}: {problem}") from None
    if data is None:
        return {}
    if not isinstance(data, dict):
        raise SettingsError(f"{path}: expected a mapping of sections (ui:, generation:, ...), got {type(data).__name__}")
    odd_key = _non_text_key(data)
    if odd_key is not _NO_KEY:
        # A key such as `!!binary AAAA` or `1:` is not a setting name (and pydantic fails on it).
        raise SettingsError(f"{path}: key {odd_key!r} is not a setting name; keys are words like theme or seed")
    misplaced = [key for key in ENVIRONMENT_ONLY if key in data]
    if misplaced:
        raise SettingsError(f"{path}: {', '.join(misplaced)} is set by GROVE_{misplaced[0].upper()}; "
                            "in the file, name models under models: {roi: PATH, bt: PATH}")
    return data


_NO_KEY = object()  # a key can be None (`: value` in YAML), so "no such key" needs its own marker


def _non_text_key(value: object) -> object:
    """The first mapping key anywhere in `value` that is not a string, else _NO_KEY (found by fuzzing)."""
    stack: list[object] = [value]
    while stack:
        current = stack.pop()
        if isinstance(current, dict):
            for key, item in current.items():
                if not isinstance(key, str):
                    return key
                stack.append(item)
        elif isinstance(current, list):
            stack.extend(current)
    return _NO_KEY


def _validation_message(error: ValidationError) -> str:
    problems = error.errors()
    first = problems[0]
    key = ".".join(str(part) for part in first["loc"]) or "(top level)"
    value = f" (got {first['input']!r})" if "input" in first and not isinstance(first["input"], dict) else ""
    more = f"; and {len(problems) - 1} more" if len(problems) > 1 else ""
    return f"{key}: {first['msg']}{value}{more}"


def _source_of(error: ValidationError) -> str:
    """The GROVE_* variable that set the first bad value, or the config file."""
    location = [str(part) for part in error.errors()[0]["loc"]]
    for depth in range(len(location), 0, -1):
        variable = "GROVE_" + "__".join(location[:depth]).upper()
        if variable in os.environ:
            return f"{variable}={os.environ[variable]!r}"
    return str(config_file())


def load_settings() -> GroveSettings:
    """Read the file and the environment; SettingsError (one line, naming the key) when either is bad."""
    try:
        return GroveSettings()
    except ValidationError as error:
        raise SettingsError(f"{_source_of(error)}: {_validation_message(error)}") from None


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


class LastChoices(TypedDict, total=False):
    """last_choices.json as load_last_choices reads it: each key only when the file holds a good value."""

    world: str
    preset: str
    seed: int


def last_choices_file() -> Path:
    return data_dir() / "last_choices.json"


def load_last_choices() -> LastChoices:
    """The world, preset and seed of the app's last generation ({} the first time, or from a file that
    is not ours: the app then starts on the config file's choices)."""
    import json

    try:
        data = json.loads(last_choices_file().read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    if not isinstance(data, dict):
        return {}
    choices = LastChoices()
    if isinstance(data.get("world"), str):
        choices["world"] = data["world"]
    if isinstance(data.get("preset"), str):
        choices["preset"] = data["preset"]
    if isinstance(data.get("seed"), int) and not isinstance(data.get("seed"), bool) and data["seed"] >= 0:
        choices["seed"] = data["seed"]
    return choices


def save_last_choices(world: str, preset: str, seed: int) -> None:
    """Remember the choices of a generation; the next start of the app opens on them."""
    import json

    from grove_tui.files import write_text_atomic

    path = last_choices_file()
    path.parent.mkdir(parents=True, exist_ok=True)
    write_text_atomic(path, json.dumps({"world": world, "preset": preset, "seed": int(seed)}, indent=2) + "\n")
