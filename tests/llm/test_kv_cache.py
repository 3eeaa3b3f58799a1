"""The fixed prefix's KV cache (issue 20): live, persisted and restored, it never changes what the model sees.

A chat request's prompt is evaluated as the fixed prefix (everything before the last message's
content) and the rest, each in batches from its own start; the prefix's KV state is written under
the cache dir and restored by a fresh worker. These tests compare the digest of the next-token
logits (what every sampler draws from) and the sampled text, cold, warm and restored, on the tiny
Qwen3 (real llama.cpp), and check when a persisted prefix is used or rebuilt.
"""

from __future__ import annotations

import os

import pytest

from helpers.tiny_qwen3 import build_tiny_qwen3

from grove_tui.llm.grammar import schema_to_gbnf
from grove_tui.llm.local import LocalLLM

pytestmark = pytest.mark.slow  # every test here runs a real model

# Longer than one batch (512) in the tiny model's byte-level vocabulary, so the prefix has two batches.
SYSTEM = " ".join(f"Rule {i}: people walk from zone_{i} to zone_{i + 1} and queue at counter_{i}." for i in range(14))
# A bounded answer, so every generation ends by itself; free text samples from nearly the whole vocabulary.
GRAMMAR = schema_to_gbnf({"type": "object", "properties": {"s": {"type": "string", "minLength": 16, "maxLength": 16}},
                          "required": ["s"], "additionalProperties": False})
USERS = ["Ten patients queue at the pharmacy counter", "Two nurses chat at the nurse station"]


def messages(user: str, system: str = SYSTEM) -> list[dict[str, str]]:
    return [{"role": "system", "content": system}, {"role": "user", "content": user}]


@pytest.fixture()
def kv_dir(tmp_path, monkeypatch):
    monkeypatch.setenv("GROVE_CACHE_DIR", str(tmp_path / "cache"))
    return tmp_path / "cache" / "kv"


@pytest.fixture(scope="module")
def tiny_path_2k(tmp_path_factory):
    return build_tiny_qwen3(tmp_path_factory.mktemp("kv") / "tiny-qwen3.gguf", context_length=2048)


def fresh(tiny_path_2k) -> LocalLLM:
    return LocalLLM(tiny_path_2k, role="kv-test", n_ctx=2048, n_threads=1)


def test_cold_warm_and_restored_prefixes_give_identical_logits_and_text(tiny_path_2k, kv_dir):
    label = "hospital-abc-queuing-v2"
    with fresh(tiny_path_2k) as llm:
        cold = llm.evaluate(messages(USERS[0]), label)
        assert cold["cache_source"] == "cold" and cold["cached_tokens"] == 0
        assert len(list(kv_dir.glob("*.kv"))) == 1, "the prefix was persisted"
        other = llm.evaluate(messages(USERS[1]), label)  # the live prefix is reused for another sentence
        assert other["cache_source"] == "live" and other["cached_tokens"] > 512
        again = llm.evaluate(messages(USERS[0]), label)  # after another request: same logits
        assert again["logits_sha256"] == cold["logits_sha256"]
        text = llm.generate(messages(USERS[0]), grammar=GRAMMAR, max_tokens=40, seed=5, temperature=1.0, prefix_label=label).text
        repeat = llm.generate(messages(USERS[0]), grammar=GRAMMAR, max_tokens=40, seed=5, temperature=1.0, prefix_label=label)
        assert repeat.text == text and repeat.cache_source == "live"
    with fresh(tiny_path_2k) as llm:  # a fresh worker: the first request restores the prefix from disk
        restored = llm.evaluate(messages(USERS[0]), label)
        assert restored["cache_source"] == "disk" and restored["cached_tokens"] > 512
        assert restored["logits_sha256"] == cold["logits_sha256"]
    with fresh(tiny_path_2k) as llm:
        first = llm.generate(messages(USERS[0]), grammar=GRAMMAR, max_tokens=40, seed=5, temperature=1.0, prefix_label=label)
        assert first.cache_source == "disk" and first.cached_tokens > 512
        assert first.text == text
    for path in kv_dir.glob("*.kv"):
        path.unlink()
    with fresh(tiny_path_2k) as llm:  # no file at all: cold again, same text
        cold_text = llm.generate(messages(USERS[0]), grammar=GRAMMAR, max_tokens=40, seed=5, temperature=1.0, prefix_label=label)
        assert cold_text.cache_source == "cold" and cold_text.text == text


def test_the_persisted_prefix_is_rebuilt_when_model_label_or_prefix_change(tiny_path_2k, kv_dir, tmp_path):
    label = "hospital-abc-queuing-v2"
    with fresh(tiny_path_2k) as llm:
        llm.evaluate(messages(USERS[0]), label)
    assert len(list(kv_dir.glob("*.kv"))) == 1
    with fresh(tiny_path_2k) as llm:
        assert llm.evaluate(messages(USERS[1]), label)["cache_source"] == "disk"
    # Another world file, preset or template version is another label: that file is not used, a new one is built.
    for other in ("office-def-queuing-v2", "hospital-abc-normal-v2", "hospital-abc-queuing-v3"):
        with fresh(tiny_path_2k) as llm:
            assert llm.evaluate(messages(USERS[1]), other)["cache_source"] == "cold"
        with fresh(tiny_path_2k) as llm:
            assert llm.evaluate(messages(USERS[1]), other)["cache_source"] == "disk"
    assert len(list(kv_dir.glob("*.kv"))) == 4
    with fresh(tiny_path_2k) as llm:  # another prefix text (a world description or preset template edited)
        assert llm.evaluate(messages(USERS[0], SYSTEM + " One more rule."), label)["cache_source"] == "cold"
    count = len(list(kv_dir.glob("*.kv")))
    stat = os.stat(tiny_path_2k)
    os.utime(tiny_path_2k, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000_000))  # the model file replaced
    with fresh(tiny_path_2k) as llm:
        assert llm.evaluate(messages(USERS[0]), label)["cache_source"] == "cold"
    assert len(list(kv_dir.glob("*.kv"))) == count + 1
    other_model = build_tiny_qwen3(tmp_path / "other.gguf", seed=1, context_length=2048)
    with fresh(other_model) as llm:
        assert llm.evaluate(messages(USERS[0]), label)["cache_source"] == "cold"


def test_a_damaged_cache_file_is_ignored_and_rewritten(tiny_path_2k, kv_dir):
    label = "hospital-abc-queuing-v2"
    with fresh(tiny_path_2k) as llm:
        reference = llm.evaluate(messages(USERS[0]), label)["logits_sha256"]
    (path,) = kv_dir.glob("*.kv")
    path.write_bytes(path.read_bytes()[:200])
    with fresh(tiny_path_2k) as llm:
        result = llm.evaluate(messages(USERS[0]), label)
        assert result["cache_source"] == "cold" and result["logits_sha256"] == reference
    with fresh(tiny_path_2k) as llm:
        assert llm.evaluate(messages(USERS[0]), label)["cache_source"] == "disk"


def test_the_folder_keeps_only_the_most_recently_used_prefixes(tiny_path_2k, kv_dir):
    from grove_tui.llm.worker import PrefixStore

    kv_dir.mkdir(parents=True)
    for i in range(PrefixStore.KEEP_FILES + 8):
        stale = kv_dir / f"old-{i}.kv"
        stale.write_bytes(b"x")
        os.utime(stale, ns=(1_000_000_000 * (i + 1), 1_000_000_000 * (i + 1)))
    with fresh(tiny_path_2k) as llm:
        assert llm.evaluate(messages(USERS[0]), "hospital-abc-queuing-v2")["cache_source"] == "cold"
    kept = {p.name for p in kv_dir.glob("*.kv")}
    assert len(kept) == PrefixStore.KEEP_FILES
    assert any(name.startswith("hospital-abc-queuing-v2-") for name in kept)
    assert "old-0.kv" not in kept and f"old-{PrefixStore.KEEP_FILES + 7}.kv" in kept


def test_warming_the_prefix_serves_the_first_request_from_it(tiny_path_2k, kv_dir):
    # GroveSession.warm_up's "prompt" step: the world/preset system message evaluated before any
    # request, so the first scenario prefills only its own part (issue 20, first scenario vs warm).
    from grove_tui.generation.presets import load_preset
    from grove_tui.generation.synthesis import fixed_system_message, prefix_label, warm_prefix
    from grove_tui.world import load_world

    preset, world = load_preset("queuing"), load_world("hospital")
    request = [{"role": "system", "content": fixed_system_message(preset, world)},
               {"role": "user", "content": "Scenario: ten patients queue at the pharmacy counter"}]
    label = prefix_label(preset, world)
    with fresh(tiny_path_2k) as llm:  # the control: nothing warmed, nothing on disk
        cold = llm.evaluate(request, label)
    assert (cold["cache_source"], cold["cached_tokens"]) == ("cold", 0)
    for path in kv_dir.iterdir():
        path.unlink()  # as on a machine that never ran this world and preset
    with fresh(tiny_path_2k) as llm:
        warmed = warm_prefix(llm, preset, world)
        assert warmed is not None and warmed["cache_source"] == "cold"
        first = llm.evaluate(request, label)
    assert first["cache_source"] == "live" and first["cached_tokens"] > 0.5 * cold["prompt_tokens"]
    assert first["logits_sha256"] == cold["logits_sha256"]  # and the model sees the same thing


def test_the_thread_count_changes_no_logits(tiny_path_2k, kv_dir):
    """A request runs on the cores idle at that moment (cpu.py), and a prefix saved at one count is restored at
    another, so the logits must not depend on it."""
    digests = []
    for threads in (1, 2):
        with LocalLLM(tiny_path_2k, role="kv-test", n_ctx=2048, n_threads=threads) as llm:
            digests.append(llm.evaluate(messages(USERS[0]), "threads")["logits_sha256"])
    assert digests[0] == digests[1]
