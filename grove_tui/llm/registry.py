"""Which GGUF serves which role.

Two roles, as in the paper's multi-model strategy: `roi` (a light model picks the regions of
interest) and `bt` (a stronger model writes the behavior trees). Each role is resolved, first match wins:

1. the command line: --roi-model / --bt-model, or --model for both;
2. the environment: GROVE_ROI_MODEL / GROVE_BT_MODEL, or GROVE_MODEL for both;
3. the config file config_dir()/config.yaml:  models: {roi: PATH, bt: PATH}  (relative to that file);
4. the models directory (models_dir(), where `grove models pull` writes): the smallest GGUF for
   roi, the largest for bt;
5. the embedded model (models/embedded.py).

An explicitly named file that is missing or not a GGUF is an error, never a silent fallback.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from grove_tui.paths import config_dir, models_dir
from grove_tui.llm.embedded import EMBEDDED_MODEL, embedded_model_path
from grove_tui.llm.errors import ModelError
from grove_tui.llm.gguf_info import GGUFInfo, check_gguf_file, read_gguf_info

ROLES = ("roi", "bt")
ROLE_ENV = {"roi": "GROVE_ROI_MODEL", "bt": "GROVE_BT_MODEL"}
SHARED_ENV = "GROVE_MODEL"
DEFAULT_N_CTX = 4096


@dataclass(frozen=True)
class ModelChoice:
    role: str
    path: Path
    source: str  # where the choice came from, shown to the user ("--bt-model", "GROVE_MODEL", "embedded"...)
    n_ctx: int = DEFAULT_N_CTX


@dataclass(frozen=True)
class FoundModel:
    path: Path
    origin: str  # "models dir", "embedded", or the source of an explicit choice
    roles: tuple[str, ...]
    info: GGUFInfo | None
    problem: str = ""


def config_file() -> Path:
    return config_dir() / "config.yaml"


def _config_models() -> dict[str, Path]:
    path = config_file()
    if not path.is_file():
        return {}
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8")) or {}
    except yaml.YAMLError as error:
        raise ModelError(f"{path}: not valid YAML ({error})") from None
    models = data.get("models") if isinstance(data, dict) else None
    if models is None:
        return {}
    if not isinstance(models, dict):
        raise ModelError(f"{path}: 'models' must be a mapping like {{roi: PATH, bt: PATH}}")
    unknown = set(models) - set(ROLES)
    if unknown:
        raise ModelError(f"{path}: unknown model role(s) {', '.join(sorted(map(str, unknown)))}; roles are roi and bt")
    result = {}
    for role, value in models.items():
        if value in (None, ""):
            continue
        candidate = Path(str(value)).expanduser()
        result[role] = candidate if candidate.is_absolute() else path.parent / candidate
    return result


def models_in_directory(directory: Path | None = None) -> list[Path]:
    """GGUF files in the models directory, smallest first (partial downloads are hidden dot-files)."""
    folder = models_dir() if directory is None else directory
    if not folder.is_dir():
        return []
    files = [path for path in folder.glob("*.gguf") if path.is_file() and not path.name.startswith(".")]
    return sorted(files, key=lambda path: (path.stat().st_size, path.name))


def _checked(path: Path, source: str) -> Path:
    try:
        return check_gguf_file(path)
    except ModelError as error:
        raise ModelError(f"{source}: {error}") from None


def resolve_models(cli_roi: str | os.PathLike[str] | None = None, cli_bt: str | os.PathLike[str] | None = None,
                   cli_model: str | os.PathLike[str] | None = None) -> dict[str, ModelChoice]:
    """The model for each role, by the precedence in the module docstring."""
    cli = {"roi": cli_roi, "bt": cli_bt}
    config = _config_models()
    found = models_in_directory()
    choices: dict[str, ModelChoice] = {}
    for role in ROLES:
        if cli[role]:
            flag = "--roi-model" if role == "roi" else "--bt-model"
            choices[role] = ModelChoice(role, _checked(Path(cli[role]).expanduser(), flag), flag)
        elif cli_model:
            choices[role] = ModelChoice(role, _checked(Path(cli_model).expanduser(), "--model"), "--model")
        elif os.environ.get(ROLE_ENV[role]):
            name = ROLE_ENV[role]
            choices[role] = ModelChoice(role, _checked(Path(os.environ[name]).expanduser(), name), name)
        elif os.environ.get(SHARED_ENV):
            choices[role] = ModelChoice(role, _checked(Path(os.environ[SHARED_ENV]).expanduser(), SHARED_ENV), SHARED_ENV)
        elif role in config:
            source = f"{config_file()} models.{role}"
            choices[role] = ModelChoice(role, _checked(config[role], source), source)
        elif found:
            choices[role] = ModelChoice(role, found[0] if role == "roi" else found[-1], f"models dir {models_dir()}")
        else:
            choices[role] = ModelChoice(role, embedded_model_path(), f"embedded ({EMBEDDED_MODEL})")
    return choices


def list_models(cli_roi: str | None = None, cli_bt: str | None = None, cli_model: str | None = None) -> tuple[list[FoundModel], dict[str, ModelChoice] | str]:
    """Every model we can see (models dir, embedded, role choices) with its metadata and the roles using it.

    The second value is the role resolution, or the text of the error that stopped it.
    """
    try:
        choices: dict[str, ModelChoice] | str = resolve_models(cli_roi, cli_bt, cli_model)
    except ModelError as error:
        choices = str(error)
    candidates: dict[Path, str] = {}
    for path in models_in_directory():
        candidates[path.resolve()] = "models dir"
    try:
        candidates.setdefault(embedded_model_path().resolve(), f"embedded ({EMBEDDED_MODEL})")
    except ModelError:
        pass
    if isinstance(choices, dict):
        for choice in choices.values():
            candidates.setdefault(choice.path.resolve(), choice.source)
    found = []
    for path, origin in candidates.items():
        roles = tuple(role for role, choice in (choices.items() if isinstance(choices, dict) else [])
                      if choice.path.resolve() == path)
        info: Any = None
        problem = ""
        try:
            info = read_gguf_info(path)
            if not info.supported:
                problem = f"architecture {info.architecture} is not supported"
        except ModelError as error:
            problem = str(error)
        found.append(FoundModel(path, origin, roles, info, problem))
    return found, choices
