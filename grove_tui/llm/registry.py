"""Which GGUF serves which role.

Two roles, as in the paper's multi-model strategy: `roi` (a light model picks the regions of
interest) and `bt` (a stronger model writes the behavior trees). Each role is resolved, first match wins:

1. the command line: --roi-model / --bt-model, or --model for both;
2. the environment: GROVE_ROI_MODEL / GROVE_BT_MODEL, or GROVE_MODEL for both;
3. the config file (settings.config_file(), so GROVE_CONFIG_FILE is honoured):
   models: {roi: PATH, bt: PATH}  (relative to that file);
4. the models directory (models_dir(), where `grove models pull` writes): the smallest GGUF for
   roi, the largest for bt;
5. the embedded model (models/embedded.py).

An explicitly named file that is missing or not a GGUF is an error, never a silent fallback.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

from grove_tui.settings import GroveSettings, config_file, load_settings, models_dir
from grove_tui.llm.embedded import EMBEDDED_MODEL, embedded_model_path
from grove_tui.errors import ModelError
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


def models_in_directory(directory: Path | None = None) -> list[Path]:
    """GGUF files in the models directory, smallest first (partial downloads are hidden dot-files)."""
    folder = models_dir() if directory is None else directory
    if not folder.is_dir():
        return []
    files = [path for path in folder.glob("*.gguf") if path.is_file() and not path.name.startswith(".")]
    return sorted(files, key=lambda path: (path.stat().st_size, path.name))


def _checked(path: Path, source: str) -> Path:
    """The path of a readable GGUF whose tensors are all there (a truncated download is refused here,
    before a worker process tries to load it)."""
    try:
        checked = check_gguf_file(path)
        read_gguf_info(checked)
        return checked
    except ModelError as error:
        raise ModelError(f"{source}: {error}") from None


def _complete(path: Path) -> bool:
    try:
        read_gguf_info(path)
        return True
    except ModelError:
        return False


def resolve_models(cli_roi: str | os.PathLike[str] | None = None, cli_bt: str | os.PathLike[str] | None = None,
                   cli_model: str | os.PathLike[str] | None = None,
                   settings: GroveSettings | None = None) -> dict[str, ModelChoice]:
    """The model for each role, by the precedence in the module docstring (settings: read now if None)."""
    settings = load_settings() if settings is None else settings
    cli = {"roi": cli_roi, "bt": cli_bt}
    environment = {"roi": settings.roi_model, "bt": settings.bt_model}
    # Damaged files in the models folder are skipped (`models list` shows them with the reason).
    found = [path for path in models_in_directory() if _complete(path)]
    choices: dict[str, ModelChoice] = {}
    for role in ROLES:
        explicit = cli[role]
        configured = settings.model_file(role)
        if explicit:
            flag = "--roi-model" if role == "roi" else "--bt-model"
            choices[role] = ModelChoice(role, _checked(Path(explicit).expanduser(), flag), flag)
        elif cli_model:
            choices[role] = ModelChoice(role, _checked(Path(cli_model).expanduser(), "--model"), "--model")
        elif environment[role]:
            name = ROLE_ENV[role]
            choices[role] = ModelChoice(role, _checked(Path(str(environment[role])).expanduser(), name), name)
        elif settings.model:
            choices[role] = ModelChoice(role, _checked(Path(settings.model).expanduser(), SHARED_ENV), SHARED_ENV)
        elif configured is not None:
            source = f"{config_file()} models.{role}"
            choices[role] = ModelChoice(role, _checked(configured, source), source)
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
        info: GGUFInfo | None = None
        problem = ""
        try:
            info = read_gguf_info(path)
            if not info.supported:
                problem = f"architecture {info.architecture} is not supported"
        except ModelError as error:
            problem = str(error)
        found.append(FoundModel(path, origin, roles, info, problem))
    return found, choices
