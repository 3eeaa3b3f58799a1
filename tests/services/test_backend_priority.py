"""Issue 21: keys answer while the model writes because the app's model processes run below the app's
priority. Real llama.cpp worker processes (the tiny random-weight Qwen3), real setpriority."""

from __future__ import annotations

import os

import pytest

from grove_tui.llm.grammar import schema_to_gbnf
from grove_tui.llm.local import LocalLLM
from grove_tui.services.backend import LOWEST_PRIORITY, MODEL_NICENESS, EngineBackend

pytestmark = [pytest.mark.skipif(not hasattr(os, "setpriority"), reason="no process priorities on this platform"),
              pytest.mark.slow]  # the model workers are real llama.cpp processes


def backend_with(tiny_path, tmp_path, **kwargs):
    return EngineBackend(llm_factory=lambda role, choice: LocalLLM(tiny_path, role=role, n_ctx=256, n_threads=1),
                         runs_dir=tmp_path / "runs", **kwargs)


def test_model_processes_run_below_the_app_and_only_once(tiny_path, tmp_path):
    backend = backend_with(tiny_path, tmp_path)
    try:
        assert backend.yield_cpu_to_the_app() == [], "nothing loaded: nothing to change, nothing loaded for it"
        models = backend.load_models()
        for llm in {id(m): m for m in models.values()}.values():
            llm.start()
        pids = sorted({m.worker_pid for m in models.values()})
        assert sorted(backend.yield_cpu_to_the_app()) == pids
        below = min(os.getpriority(os.PRIO_PROCESS, 0) + MODEL_NICENESS, LOWEST_PRIORITY)
        assert [os.getpriority(os.PRIO_PROCESS, pid) for pid in pids] == [below] * len(pids)
        assert backend.yield_cpu_to_the_app() == [], "already below: left as it is"
        answer = models["bt"].generate("go", grammar=schema_to_gbnf({"const": "ok"}), max_tokens=8)
        assert answer.text == '"ok"', "the model still answers"
    finally:
        backend.close()


def test_niceness_zero_leaves_the_model_processes_alone(tiny_path, tmp_path):
    backend = backend_with(tiny_path, tmp_path, model_niceness=0)
    try:
        models = backend.load_models()
        models["bt"].start()
        assert backend.yield_cpu_to_the_app() == []
        assert os.getpriority(os.PRIO_PROCESS, models["bt"].worker_pid) == os.getpriority(os.PRIO_PROCESS, 0)
    finally:
        backend.close()
