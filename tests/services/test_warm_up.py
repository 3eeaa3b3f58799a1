"""Warm start: GroveSession.warm_up loads what the first generation would otherwise load, and says so."""

from __future__ import annotations

import pytest

from grove_tui.generation import retrieval
from grove_tui.services.session import GroveSession, WarmUpStatus


pytestmark = [pytest.mark.usefixtures("shared_index"), pytest.mark.slow]


@pytest.fixture
def unloaded_embedder(monkeypatch):
    """The process's embedding model and query encoder forgotten (restored after), its loads counted."""
    import sentence_transformers

    monkeypatch.setattr(retrieval, "_model", None)
    monkeypatch.setattr(retrieval, "_query_encoder", None)
    retrieval._embed_query_cached.cache_clear()
    loads = []
    real = sentence_transformers.SentenceTransformer

    def counted(*args, **kwargs):
        loads.append(args)
        return real(*args, **kwargs)

    monkeypatch.setattr(sentence_transformers, "SentenceTransformer", counted)
    yield loads
    retrieval._embed_query_cached.cache_clear()


def _no_models(role, choice):
    raise AssertionError("this test loads no GGUF model")


def test_warm_up_loads_the_index_and_embedder_so_the_first_retrieval_loads_nothing(unloaded_embedder, monkeypatch):
    session = GroveSession(llm_factory=lambda role, choice: object())
    statuses: list[WarmUpStatus] = []
    done = session.warm_up("hospital", "queuing", on_status=statuses.append)
    assert [s.step for s in done] == ["models", "retrieval", "reader", "planner", "prompt"]
    assert all(s.state == "done" for s in done), [s.text for s in done]
    assert session.warm
    assert len(unloaded_embedder) == 1, "the warm-up loads the embedder once"
    assert statuses[0].text == "loading the models…" and statuses[-1].step == "ready"

    opened = []
    monkeypatch.setattr(retrieval.NodeRetriever, "_open_or_build",
                        lambda self, force: opened.append(force) or pytest.fail("the index was opened again"))
    found = session.retriever().retrieve("six patients queue at the pharmacy counter")
    assert found, "the real index answers"
    assert len(unloaded_embedder) == 1, "the first retrieval loaded the embedder again"
    assert opened == []


def test_without_warm_up_the_first_retrieval_loads_the_embedder(unloaded_embedder):
    # The control for the test above: the same first retrieval, cold, does load it.
    session = GroveSession(llm_factory=_no_models)
    assert session.retriever().retrieve("six patients queue at the pharmacy counter")
    assert len(unloaded_embedder) == 1


def test_a_failing_step_is_reported_and_the_others_still_run(unloaded_embedder):
    from grove_tui.errors import ModelError

    def broken(role, choice):
        raise ModelError("bt.gguf: not a GGUF file")

    session = GroveSession(llm_factory=broken)
    statuses: list[WarmUpStatus] = []
    done = session.start_warm_up(on_status=statuses.append)
    done.join(timeout=300)
    states = {s.step: s for s in statuses if s.state != "running"}
    assert states["models"].state == "failed" and "not a GGUF file" in states["models"].text
    assert states["retrieval"].state == "done" and states["reader"].state == "done"
    assert states["ready"].state == "failed" and not session.warm
