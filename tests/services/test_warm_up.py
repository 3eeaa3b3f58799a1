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


def test_a_generation_before_the_warm_up_loads_what_is_missing_as_its_loading_stage_with_an_eta():
    """Issue 31: progress from the first second. A generation asked while the warm-up still loads shows
    a stage "loading" part by part, each with the seconds it took last time, then the pipeline's stages."""
    import threading
    import time

    from helpers.app import FakeLLM, lexical_retriever

    from grove_tui.generation.pipeline import StageFinished, StageStarted
    from grove_tui.services.session import LoadingProgress

    loading = threading.Event()

    def slow_model(role, choice):
        loading.set()
        time.sleep(1.0)
        return FakeLLM()

    session = GroveSession(llm_factory=slow_model, retriever_factory=lexical_retriever)
    session.step_seconds.update({"models": 4.0, "reader": 2.0})
    warm = session.start_warm_up("hospital", "queuing")
    assert loading.wait(30)
    # While the model loads: the world and the model status answer at once, not after the load.
    started = time.perf_counter()
    session.load_world("museum")
    assert all(not status.loaded for status in session.model_status())
    assert time.perf_counter() - started < 0.5
    events: list[object] = []
    session.prepare("hospital", "queuing", on_event=events.append)
    warm.join(60)
    assert isinstance(events[0], StageStarted) and events[0].stage == "loading"
    parts = [e for e in events if isinstance(e, LoadingProgress)]
    assert parts and parts[0].part == "models" and parts[0].expected_seconds == 4.0
    assert [p.index for p in parts] == list(range(1, len(parts) + 1)) and parts[-1].later_seconds == 0
    assert isinstance(events[-1], StageFinished) and events[-1].stage == "loading"
    assert session.step_seconds["models"] >= 0.9, "what the load took is the next ETA"
    # Everything warm now: the next generation has no loading stage.
    again: list[object] = []
    session.prepare("hospital", "queuing", on_event=again.append)
    assert again == []


def test_close_does_not_wait_for_a_model_still_loading_and_the_load_keeps_nothing():
    import threading
    import time

    from helpers.app import FakeLLM

    from grove_tui.errors import Cancelled

    loading, closed = threading.Event(), []
    model = FakeLLM()

    def slow_model(role, choice):
        loading.set()
        time.sleep(1.5)
        return model

    session = GroveSession(llm_factory=slow_model)
    errors: list[BaseException] = []
    loader = threading.Thread(target=lambda: _catch(session.load_models, errors))
    loader.start()
    assert loading.wait(30)
    started = time.perf_counter()
    session.close()
    closed.append(time.perf_counter() - started)
    loader.join(30)
    assert closed[0] < 0.5, f"close waited {closed[0]:.2f} s for the load"
    assert errors and isinstance(errors[0], Cancelled)
    assert not model.running and session.loaded_models() == []


def _catch(call, errors):
    try:
        call()
    except BaseException as exc:  # noqa: BLE001 - the test inspects it
        errors.append(exc)
