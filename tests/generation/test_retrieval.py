"""Retrieval: offline index, preset filtering, Recall@8 on the labelled set, index lifecycle.

Every index lives under tmp_path; the network is blocked by tests/conftest.py.
"""

from __future__ import annotations

from helpers.paths import REPO
import shutil
import warnings
from pathlib import Path

import numpy as np
import pytest

from grove_tui.bt.format.manifest import NODES
from grove_tui.paths import node_db_dir
from grove_tui.generation.retrieval import (
    EMBEDDING_FUNCTION_NAME,
    NodeRetriever,
    RetrievalError,
    content_tokens,
    evaluate,
    load_eval_set,
    packaged_model_dir,
    phrase_in_prompt,
)

SOCIAL_NODES = {"Converse", "Wander", "FollowAgent", "ApproachAgent", "GoTo", "Queue"}


@pytest.fixture(scope="module")
def fresh_retriever(tmp_path_factory: pytest.TempPathFactory) -> NodeRetriever:
    return NodeRetriever(index_dir=tmp_path_factory.mktemp("chroma"))


@pytest.fixture
def small_node_db(tmp_path: Path) -> Path:
    """A few documents of the shipped database: enough to exercise the index lifecycle cheaply."""
    root = tmp_path / "node_db"
    (root / "nodes").mkdir(parents=True)
    (root / "templates").mkdir()
    for name in ("GoTo", "Queue", "Wait", "FollowVelocityField", "JoinGroup"):
        shutil.copy(node_db_dir() / "nodes" / f"{name}.md", root / "nodes")
    for name in ("queue_at_counter", "evacuation_group"):
        shutil.copy(node_db_dir() / "templates" / f"{name}.yaml", root / "templates")
    return root


@pytest.mark.slow
def test_recall_at_8_on_the_labelled_set_is_at_least_095(fresh_retriever: NodeRetriever):
    result = evaluate(fresh_retriever, load_eval_set(), k=8)
    misses = [(case.prompt, missing) for case, _, missing in result.per_case if missing]
    assert result.recall() >= 0.95, misses
    for preset in result.presets():
        assert result.recall(preset) >= 0.9, (preset, misses)


def test_labelled_set_is_broad_and_its_labels_are_retrievable(fresh_retriever: NodeRetriever):
    cases = load_eval_set()
    assert len(cases) >= 40
    assert {c.world for c in cases} >= {"hospital", "office", "residential"}
    assert {c.preset for c in cases} >= {"emergency", "queuing", "normal", "vanilla"}
    for case in cases:
        allowed = {node for name in fresh_retriever.document_names(case.preset)
                   for node in fresh_retriever.database.by_name()[name].nodes}
        for need in case.needs:
            assert need <= set(NODES), (case.prompt, need)
            assert need & allowed, f"{case.prompt!r}: {sorted(need)} cannot be retrieved under {case.preset}"


@pytest.mark.slow
def test_results_are_sorted_and_typed(fresh_retriever: NodeRetriever):
    results = fresh_retriever.retrieve("ten patients queue at the pharmacy", "queuing", k=8)
    assert len(results) == 8
    assert [r.score for r in results] == sorted((r.score for r in results), reverse=True)
    assert len({r.name for r in results}) == 8
    for item in results:
        assert item.kind in ("node", "template")
        assert item.document.strip()
        if item.kind == "node":
            assert item.nodes == (item.name,)
        else:
            assert len(item.nodes) >= 1 and set(item.nodes) <= set(NODES)
    assert {"Queue", "GoTo"} <= {n for r in results for n in r.nodes}


@pytest.mark.slow
@pytest.mark.parametrize("preset", ["emergency", "queuing", "normal", "vanilla"])
def test_every_result_is_allowed_for_its_preset(fresh_retriever: NodeRetriever, preset: str):
    documents = fresh_retriever.database.by_name()
    for prompt in ("people chat and wander around the lobby, then queue at the counter",
                   "fire alarm, everyone runs to the exit", "a child follows her father to the garden"):
        for item in fresh_retriever.retrieve(prompt, preset, k=12):
            assert preset in documents[item.name].presets, (preset, item.name)


@pytest.mark.slow
def test_emergency_offers_only_velocity_field_navigation(fresh_retriever: NodeRetriever):
    results = fresh_retriever.retrieve("visitors chat, wander around and follow the guide to the cafeteria", "emergency", k=20)
    used = {n for r in results for n in r.nodes}
    assert not used & SOCIAL_NODES, used & SOCIAL_NODES
    assert "FollowVelocityField" in used


@pytest.mark.slow
def test_queuing_prioritises_the_queue_subtree(fresh_retriever: NodeRetriever):
    neutral = "people in the hospital"
    queuing = [r.name for r in fresh_retriever.retrieve(neutral, "queuing", k=3)]
    assert "queue_at_counter" in queuing and "Queue" in queuing
    normal = [r.name for r in fresh_retriever.retrieve(neutral, "normal", k=3)]
    assert "queue_at_counter" not in normal


@pytest.mark.slow
def test_a_preset_object_is_read_through_its_retrieval_filter(fresh_retriever: NodeRetriever):
    class PresetLike:
        name = "my-evacuation"
        retrieval_filter = "emergency"

    names = [r.name for r in fresh_retriever.retrieve("everyone leaves", PresetLike(), k=20)]
    assert names == [r.name for r in fresh_retriever.retrieve("everyone leaves", "emergency", k=20)]


def test_unknown_preset_is_a_clear_error(fresh_retriever: NodeRetriever):
    with pytest.raises(RetrievalError, match="no preset filter 'home'.*emergency, queuing, normal, vanilla"):
        fresh_retriever.retrieve("anything", "home")


@pytest.mark.slow
def test_no_preset_searches_everything(fresh_retriever: NodeRetriever):
    names = {r.name for r in fresh_retriever.retrieve("evacuate and queue and chat", None, k=100)}
    assert names == set(fresh_retriever.document_names(None))


def test_documents_for_returns_the_model_facing_text_in_order(fresh_retriever: NodeRetriever):
    texts = fresh_retriever.documents_for(["Queue", "queue_at_counter", "Sequence"])
    assert texts[0].startswith("# Queue (action)") and "---" not in texts[0].splitlines()[0]
    assert texts[1].startswith("# Template: queue at a service point")
    assert '"node": "Queue"' in texts[1]
    assert texts[2].startswith("# Sequence (control)")  # documented although never retrieved
    with pytest.raises(RetrievalError, match="no document 'Teleport'"):
        fresh_retriever.documents_for(["Teleport"])


@pytest.mark.slow
def test_index_uses_our_registered_embedding_function(fresh_retriever: NodeRetriever):
    fresh_retriever.ensure_index()
    configuration = fresh_retriever._collection.configuration
    assert configuration["embedding_function"].name() == EMBEDDING_FUNCTION_NAME
    assert configuration["hnsw"]["space"] == "cosine"
    assert not configuration["embedding_function"].is_legacy()


def test_model_comes_from_the_installed_package():
    model_dir = packaged_model_dir()
    assert model_dir.name == "model" and (model_dir / "model.safetensors").exists()
    assert "site-packages" in str(model_dir) or "dist-packages" in str(model_dir)


@pytest.mark.slow
def test_index_is_reused_until_the_node_database_changes(small_node_db: Path, tmp_path: Path):
    index = tmp_path / "index"
    first = NodeRetriever(small_node_db, index).ensure_index()
    assert first.built and first.documents == 7
    again = NodeRetriever(small_node_db, index).ensure_index()
    assert not again.built
    template = small_node_db / "templates" / "queue_at_counter.yaml"
    template.write_text(template.read_text(encoding="utf-8").replace("ticket booth", "ticket office"), encoding="utf-8")
    changed = NodeRetriever(small_node_db, index)
    assert changed.ensure_index().built
    assert changed.retrieve("people line up at the counter", "queuing", k=1)[0].name in ("Queue", "queue_at_counter")


@pytest.mark.slow
def test_a_corrupt_index_is_rebuilt_with_a_warning(small_node_db: Path, tmp_path: Path):
    index = tmp_path / "index"
    index.mkdir()
    (index / "chroma.sqlite3").write_bytes(b"this is not a database" * 100)
    retriever = NodeRetriever(small_node_db, index)
    with pytest.warns(UserWarning, match="unusable"):
        results = retriever.retrieve("fire alarm, everyone evacuates", "emergency", k=2)
    assert {r.name for r in results} == {"FollowVelocityField", "evacuation_group"}


@pytest.mark.slow
def test_rebuilding_a_corrupt_index_leaves_other_retrievers_working(small_node_db: Path, tmp_path: Path,
                                                                   fresh_retriever: NodeRetriever):
    before = [r.name for r in fresh_retriever.retrieve("patients queue at the pharmacy", "queuing", k=3)]
    index = tmp_path / "index"
    index.mkdir()
    (index / "chroma.sqlite3").write_bytes(b"\0garbage" * 512)
    with pytest.warns(UserWarning, match="unusable"):
        NodeRetriever(small_node_db, index).ensure_index()
    assert [r.name for r in fresh_retriever.retrieve("patients queue at the pharmacy", "queuing", k=3)] == before
    # Chroma keeps one System per directory; a second client on the same directory must share it,
    # never open the same sqlite file twice.
    from chromadb.api.shared_system_client import SharedSystemClient

    assert str(fresh_retriever.index_dir) in SharedSystemClient._identifier_to_system


@pytest.mark.slow
def test_a_foreign_collection_is_rebuilt_with_a_warning(small_node_db: Path, tmp_path: Path):
    import chromadb
    from chromadb.config import Settings

    from grove_tui.generation.retrieval import COLLECTION, embedding_function_class

    index = tmp_path / "index"
    client = chromadb.PersistentClient(path=str(index), settings=Settings(anonymized_telemetry=False, allow_reset=True))
    foreign = client.create_collection(COLLECTION, embedding_function=embedding_function_class()())
    foreign.add(ids=["x"], embeddings=[[0.1] * 384], metadatas=[{"document": "x"}])
    retriever = NodeRetriever(small_node_db, index)
    with pytest.warns(UserWarning, match="not written by GROVE-TUI"):
        state = retriever.ensure_index()
    assert state.built and state.documents == 7
    assert retriever.retrieve("patients queue", "queuing", k=1)[0].name in ("Queue", "queue_at_counter")


@pytest.mark.slow
def test_an_index_dir_holding_other_files_is_never_deleted(small_node_db: Path, tmp_path: Path):
    index = tmp_path / "not_an_index"
    index.mkdir()
    (index / "thesis.tex").write_text("precious", encoding="utf-8")
    (index / "chroma.sqlite3").mkdir()  # makes opening fail
    retriever = NodeRetriever(small_node_db, index)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(RetrievalError):
            retriever.ensure_index()
    assert (index / "thesis.tex").read_text(encoding="utf-8") == "precious"


def test_missing_node_database_is_a_clear_error(tmp_path: Path):
    with pytest.raises(RetrievalError, match="grove rag sync"):
        NodeRetriever(tmp_path / "empty", tmp_path / "index")


def test_lexical_matching_is_stemmed_and_order_free():
    prompt = frozenset(content_tokens("Patients are queueing and lining up at the counters"))
    assert phrase_in_prompt(content_tokens("line up"), prompt)
    assert phrase_in_prompt(content_tokens("queue"), prompt)
    assert phrase_in_prompt(content_tokens("counter"), prompt)
    assert not phrase_in_prompt(content_tokens("wait in line"), prompt)
    assert phrase_in_prompt(content_tokens("FollowVelocityField"), frozenset(content_tokens("use follow velocity fields")))


@pytest.mark.slow
def test_query_embeddings_match_document_embeddings():
    from grove_tui.generation.retrieval import embed_query, embed_texts

    texts = ["evacuate", "ten patients queue at the pharmacy counter",
             "a family of four wanders around the lobby together while a curious child approaches the robot " * 8]
    for text in texts:
        query = embed_query(text)
        assert query.shape == (1, 384)
        assert abs(float(np.linalg.norm(query)) - 1.0) < 1e-5
        assert float(np.abs(query - embed_texts([text])).max()) < 1e-4, text


@pytest.mark.slow
def test_two_processes_building_one_index_both_succeed(small_node_db: Path, tmp_path: Path):
    import subprocess
    import sys

    index = tmp_path / "shared_index"
    # The children block the network themselves: conftest's guard does not reach other processes.
    code = ("import socket, sys\n"
            "def _blocked(*args, **kwargs): raise OSError('network blocked in test child')\n"
            "socket.socket.connect = socket.create_connection = socket.getaddrinfo = _blocked\n"
            "from grove_tui.generation.retrieval import NodeRetriever;"
            "r = NodeRetriever(sys.argv[1], sys.argv[2]); s = r.ensure_index();"
            "print(s.built, r.retrieve('patients queue at the counter', 'queuing', k=1)[0].name)")
    root = REPO
    env = {**__import__("os").environ, "PYTHONPATH": str(root)}
    runs = [subprocess.Popen([sys.executable, "-c", code, str(small_node_db), str(index)], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=env, cwd=root) for _ in range(2)]
    outputs = [run.communicate(timeout=600) for run in runs]
    assert all(run.returncode == 0 for run in runs), [err for _, err in outputs]
    built = sorted(out.split()[0] for out, _ in outputs)
    assert built == ["False", "True"]  # one built it, the other waited and reused it
    assert all(out.split()[1] in ("Queue", "queue_at_counter") for out, _ in outputs)
