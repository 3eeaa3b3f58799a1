"""Build a tiny random-weight Qwen3-architecture GGUF for tests (llm.md section 7).

No Qwen3 weights can be downloaded here, so the Qwen3 code path (architecture checks, the chat
template with its `enable_thinking` switch, the special tokens, grammar-constrained decoding) is
exercised with a model that has Qwen3's structure and tokenizer layout but 2 layers of 64 wide random
weights and a byte-level vocabulary. Same seed, same bytes.
"""

from __future__ import annotations

from pathlib import Path

import gguf
import numpy as np

# The tail of Qwen3's own template: ChatML plus the empty think block when thinking is off.
QWEN3_CHAT_TEMPLATE = (
    "{%- for message in messages %}"
    "{{- '<|im_start|>' + message['role'] + '\\n' + message['content'] + '<|im_end|>' + '\\n' }}"
    "{%- endfor %}"
    "{%- if add_generation_prompt %}"
    "{{- '<|im_start|>assistant\\n' }}"
    "{%- if enable_thinking is defined and enable_thinking is false %}"
    "{{- '<think>\\n\\n</think>\\n\\n' }}"
    "{%- endif %}"
    "{%- endif %}"
)

MERGES = ["Ġ t", "o u", "r o", "e s"]
SPECIAL_CONTROL = ["<|endoftext|>", "<|im_start|>", "<|im_end|>"]
SPECIAL_USER = ["<think>", "</think>"]


def _byte_tokens() -> list[str]:
    """GPT-2's byte-to-unicode table: printable bytes map to themselves, the rest to U+0100 onwards."""
    printable = list(range(ord("!"), ord("~") + 1)) + list(range(ord("¡"), ord("¬") + 1)) + list(range(ord("®"), ord("ÿ") + 1))
    mapping = {byte: chr(byte) for byte in printable}
    extra = 0
    for byte in range(256):
        if byte not in mapping:
            mapping[byte] = chr(256 + extra)
            extra += 1
    return [mapping[byte] for byte in range(256)]


def build_tiny_qwen3(path: str | Path, seed: int = 0, context_length: int = 2048, chat_template: str = QWEN3_CHAT_TEMPLATE,
                     architecture: str = "qwen3") -> Path:
    path = Path(path)
    rng = np.random.default_rng(seed)
    n_embd, n_ff, n_head, n_head_kv, head_dim, n_layer = 64, 128, 4, 2, 16, 2
    tokens = _byte_tokens() + ["".join(merge.split()) for merge in MERGES] + SPECIAL_CONTROL + SPECIAL_USER
    types = ([gguf.TokenType.NORMAL] * (256 + len(MERGES)) + [gguf.TokenType.CONTROL] * len(SPECIAL_CONTROL)
             + [gguf.TokenType.USER_DEFINED] * len(SPECIAL_USER))
    n_vocab = len(tokens)
    endoftext, im_end = tokens.index("<|endoftext|>"), tokens.index("<|im_end|>")

    writer = gguf.GGUFWriter(str(path), architecture)
    writer.add_name("tiny-qwen3-test")
    writer.add_context_length(context_length)
    writer.add_embedding_length(n_embd)
    writer.add_block_count(n_layer)
    writer.add_feed_forward_length(n_ff)
    writer.add_head_count(n_head)
    writer.add_head_count_kv(n_head_kv)
    writer.add_key_length(head_dim)
    writer.add_value_length(head_dim)
    writer.add_rope_freq_base(1e6)
    writer.add_layer_norm_rms_eps(1e-6)
    writer.add_file_type(gguf.LlamaFileType.ALL_F32)
    writer.add_tokenizer_model("gpt2")
    writer.add_tokenizer_pre("qwen2")
    writer.add_token_list(tokens)
    writer.add_token_types(types)
    writer.add_token_merges(MERGES)
    writer.add_bos_token_id(endoftext)
    writer.add_pad_token_id(endoftext)
    writer.add_eos_token_id(im_end)
    writer.add_add_bos_token(False)
    writer.add_chat_template(chat_template)

    def weights(*shape: int) -> np.ndarray:
        return (rng.standard_normal(shape) * 0.02).astype(np.float32)

    def ones(size: int) -> np.ndarray:
        return np.ones(size, dtype=np.float32)  # 1-D tensors must be float32 (f16 norms crash at the first step)

    writer.add_tensor("token_embd.weight", weights(n_vocab, n_embd))
    for layer in range(n_layer):
        prefix = f"blk.{layer}"
        writer.add_tensor(f"{prefix}.attn_norm.weight", ones(n_embd))
        writer.add_tensor(f"{prefix}.attn_q.weight", weights(n_head * head_dim, n_embd))
        writer.add_tensor(f"{prefix}.attn_k.weight", weights(n_head_kv * head_dim, n_embd))
        writer.add_tensor(f"{prefix}.attn_v.weight", weights(n_head_kv * head_dim, n_embd))
        writer.add_tensor(f"{prefix}.attn_q_norm.weight", ones(head_dim))
        writer.add_tensor(f"{prefix}.attn_k_norm.weight", ones(head_dim))
        writer.add_tensor(f"{prefix}.attn_output.weight", weights(n_embd, n_head * head_dim))
        writer.add_tensor(f"{prefix}.ffn_norm.weight", ones(n_embd))
        writer.add_tensor(f"{prefix}.ffn_gate.weight", weights(n_ff, n_embd))
        writer.add_tensor(f"{prefix}.ffn_up.weight", weights(n_ff, n_embd))
        writer.add_tensor(f"{prefix}.ffn_down.weight", weights(n_embd, n_ff))
    writer.add_tensor("output_norm.weight", ones(n_embd))

    writer.write_header_to_file()
    writer.write_kv_data_to_file()
    writer.write_tensors_to_file()
    writer.close()
    return path
