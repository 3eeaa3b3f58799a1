"""The Qwen3-shaped bench models (tests/helpers/tiny_qwen3.py): a real English BPE at Qwen3's vocabulary size."""

from __future__ import annotations

import gguf
import pytest
from helpers.tiny_qwen3 import QWEN3_VOCAB_SIZE, TINY, english_bpe_vocabulary, write_qwen3_gguf

from grove_tui.llm.embedded import embedded_model_path

pytestmark = pytest.mark.slow  # every test here runs a real model

SENTENCE = "Ten patients walk from the main waiting room to the pharmacy counter and queue there."


def test_padded_bpe_tokenizes_like_its_source_at_qwen3_size(tmp_path):
    from llama_cpp import Llama

    vocabulary = english_bpe_vocabulary(embedded_model_path())
    assert len(vocabulary.tokens) == QWEN3_VOCAB_SIZE == len(set(vocabulary.tokens))
    assert {"<|im_start|>", "<|im_end|>", "<think>", "</think>"} <= set(vocabulary.tokens)
    # A Qwen3 layout with the tiny widths (a 40 MB file), quantized as the 0.6B's Q8_0.
    path = write_qwen3_gguf(tmp_path / "bpe.gguf", TINY, vocabulary, "Q8_0")
    reader = gguf.GGUFReader(str(path))
    assert reader.fields["general.architecture"].contents() == "qwen3"
    embedding = next(t for t in reader.tensors if t.name == "token_embd.weight")
    assert embedding.tensor_type == gguf.GGMLQuantizationType.Q8_0
    assert int(embedding.shape[-1]) == QWEN3_VOCAB_SIZE

    shaped = Llama(model_path=str(path), vocab_only=True, verbose=False)
    source = Llama(model_path=str(embedded_model_path()), vocab_only=True, verbose=False)
    ours = shaped.tokenize(SENTENCE.encode(), add_bos=False)
    theirs = source.tokenize(SENTENCE.encode(), add_bos=False)
    assert len(ours) == len(theirs) == 16  # one token a word and the full stop, as with SmolLM2's own file
    assert shaped.detokenize(ours).decode() == SENTENCE
    assert shaped.n_vocab() == QWEN3_VOCAB_SIZE

