"""Random-weight Qwen3-architecture GGUFs: a tiny one for tests, full Qwen3 shapes for bench/models.py.

No Qwen3 weights can be downloaded here, so the Qwen3 code path (architecture checks, the chat
template with its `enable_thinking` switch, the special tokens, grammar-constrained decoding) is
exercised with models that have Qwen3's structure and tokenizer layout but random weights.

- `build_tiny_qwen3`: 2 layers of 64 wide F32 weights and a byte-level vocabulary, for tests.
- `build_qwen3_shaped`: Qwen3-0.6B, 1.7B or 4B's exact shape (layers, widths, heads, 151,936-entry
  vocabulary, tied embeddings) in a quantisation users run. llama.cpp's cost per token depends on a
  model's shape and quantisation, not on its weight values, so this times what a user would see.
  Its vocabulary is a real English BPE (the embedded SmolLM2's tokens and merges) padded to Qwen3's
  size, so prompts tokenize to realistic lengths and the grammar checks a realistic vocabulary.

Same seed, same bytes.
"""

from __future__ import annotations

from dataclasses import dataclass
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
QWEN3_VOCAB_SIZE = 151_936


@dataclass(frozen=True)
class Qwen3Shape:
    """The hyper-parameters that set llama.cpp's cost (from each model's config.json on the Hub)."""

    name: str
    n_layer: int
    n_embd: int
    n_ff: int
    n_head: int
    n_head_kv: int
    head_dim: int
    context_length: int = 40_960


TINY = Qwen3Shape("tiny", n_layer=2, n_embd=64, n_ff=128, n_head=4, n_head_kv=2, head_dim=16, context_length=2048)
# Qwen3-0.6B, 1.7B and 4B all tie the output layer to the token embeddings (no output.weight).
QWEN3_SHAPES = {
    "0.6b": Qwen3Shape("Qwen3-0.6B", n_layer=28, n_embd=1024, n_ff=3072, n_head=16, n_head_kv=8, head_dim=128),
    "1.7b": Qwen3Shape("Qwen3-1.7B", n_layer=28, n_embd=2048, n_ff=6144, n_head=16, n_head_kv=8, head_dim=128),
    "4b": Qwen3Shape("Qwen3-4B", n_layer=36, n_embd=2560, n_ff=9728, n_head=32, n_head_kv=8, head_dim=128),
}

Q = gguf.GGMLQuantizationType
# The quantisations gguf-py can write (gguf.quants quantizes Q8_0/Q4_0/Q4_1/Q5_0/Q5_1, not the K-quants):
# name -> (type of the layer matrices, type of the tied embedding/output matrix, file type).
# llama-quantize gives the tied output matrix Q6_K in a Q4_0 file; Q8_0 is the closest writable type
# (8.5 bits a weight against 6.56), so the 4B-shaped Q4_0 file is slightly slower at the output layer.
QUANTS = {
    "Q8_0": (Q.Q8_0, Q.Q8_0, gguf.LlamaFileType.MOSTLY_Q8_0),
    "Q4_0": (Q.Q4_0, Q.Q8_0, gguf.LlamaFileType.MOSTLY_Q4_0),
    "F32": (Q.F32, Q.F32, gguf.LlamaFileType.ALL_F32),
}


@dataclass(frozen=True)
class Vocabulary:
    tokens: list[str]
    types: list[int]
    merges: list[str]
    bos: int
    eos: int
    pre: str  # llama.cpp's pre-tokenizer name


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


def byte_level_vocabulary() -> Vocabulary:
    """256 byte tokens, four merges and Qwen3's special tokens: the tiny model's vocabulary."""
    tokens = _byte_tokens() + ["".join(merge.split()) for merge in MERGES] + SPECIAL_CONTROL + SPECIAL_USER
    types = ([int(gguf.TokenType.NORMAL)] * (256 + len(MERGES)) + [int(gguf.TokenType.CONTROL)] * len(SPECIAL_CONTROL)
             + [int(gguf.TokenType.USER_DEFINED)] * len(SPECIAL_USER))
    return Vocabulary(tokens, types, list(MERGES), tokens.index("<|endoftext|>"), tokens.index("<|im_end|>"), "qwen2")


def _string_array(reader: gguf.GGUFReader, key: str) -> list[str]:
    field = reader.fields[key]
    return [bytes(field.parts[index]).decode("utf-8") for index in field.data]


def english_bpe_vocabulary(source_gguf: str | Path, size: int = QWEN3_VOCAB_SIZE) -> Vocabulary:
    """A real English BPE (the tokens and merges of `source_gguf`, e.g. the embedded SmolLM2) with
    Qwen3's special tokens, padded to `size` entries.

    The padding tokens are pairs of the source's own tokens ("Ġthe" + "ing"): the BPE never produces
    them (no merge makes them), so prompts tokenize as with the source, but the grammar and the
    sampler see word pieces like a real 152k vocabulary's, not byte-cheap placeholders.
    """
    reader = gguf.GGUFReader(str(source_gguf))
    tokens = _string_array(reader, "tokenizer.ggml.tokens")
    merges = _string_array(reader, "tokenizer.ggml.merges")
    type_field = reader.fields["tokenizer.ggml.token_type"]
    types = [int(type_field.parts[index][0]) for index in type_field.data]
    for special in SPECIAL_CONTROL:
        if special in tokens:
            types[tokens.index(special)] = int(gguf.TokenType.CONTROL)
        else:
            tokens.append(special)
            types.append(int(gguf.TokenType.CONTROL))
    for special in SPECIAL_USER:
        if special not in tokens:
            tokens.append(special)
            types.append(int(gguf.TokenType.USER_DEFINED))
    if len(tokens) > size:
        raise ValueError(f"{source_gguf} has {len(tokens)} tokens, more than the {size} asked for")
    seen = set(tokens)
    normal = [token for token, kind in zip(tokens, types) if kind == gguf.TokenType.NORMAL]
    rng = np.random.default_rng(151_936)
    while len(tokens) < size:
        first, second = rng.integers(len(normal), size=2)
        candidate = normal[first] + normal[second].replace("Ġ", "")
        if candidate not in seen:
            seen.add(candidate)
            tokens.append(candidate)
            types.append(int(gguf.TokenType.NORMAL))
    return Vocabulary(tokens, types, merges, tokens.index("<|endoftext|>"), tokens.index("<|im_end|>"), "qwen2")


class _RandomMatrices:
    """Random weights of std 0.02 in a quantisation: each matrix gathers rows from a pool of
    quantized random rows per width, so a 4B-shaped file takes a minute, not an hour of numpy.
    The values do not matter to llama.cpp's speed; only shapes and types do."""

    POOL_ROWS = 4096

    def __init__(self, rng: np.random.Generator) -> None:
        self.rng = rng
        self.pools: dict[tuple[int, int], np.ndarray] = {}

    def __call__(self, rows: int, cols: int, qtype: gguf.GGMLQuantizationType) -> np.ndarray:
        if qtype == Q.F32:
            return (self.rng.standard_normal((rows, cols)) * 0.02).astype(np.float32)
        key = (cols, int(qtype))
        if key not in self.pools:
            floats = (self.rng.standard_normal((self.POOL_ROWS, cols)) * 0.02).astype(np.float32)
            self.pools[key] = gguf.quants.quantize(floats, qtype)
        return self.pools[key][self.rng.integers(self.POOL_ROWS, size=rows)]


def write_qwen3_gguf(path: str | Path, shape: Qwen3Shape, vocabulary: Vocabulary, quant: str = "F32", seed: int = 0,
                     chat_template: str = QWEN3_CHAT_TEMPLATE, architecture: str = "qwen3",
                     context_length: int | None = None, tied_output: bool = True) -> Path:
    """Write a random-weight GGUF of `shape` with `vocabulary` in `quant` (a key of QUANTS)."""
    path = Path(path)
    matrix_type, embedding_type, file_type = QUANTS[quant]
    rng = np.random.default_rng(seed)
    matrices = _RandomMatrices(rng)
    n_vocab, n_embd, head_dim = len(vocabulary.tokens), shape.n_embd, shape.head_dim

    writer = gguf.GGUFWriter(str(path), architecture)
    writer.add_name(f"{shape.name}-shaped random {quant}" if shape is not TINY else "tiny-qwen3-test")
    writer.add_context_length(context_length or shape.context_length)
    writer.add_embedding_length(n_embd)
    writer.add_block_count(shape.n_layer)
    writer.add_feed_forward_length(shape.n_ff)
    writer.add_head_count(shape.n_head)
    writer.add_head_count_kv(shape.n_head_kv)
    writer.add_key_length(head_dim)
    writer.add_value_length(head_dim)
    writer.add_rope_freq_base(1e6)
    writer.add_layer_norm_rms_eps(1e-6)
    writer.add_file_type(file_type)
    writer.add_tokenizer_model("gpt2")
    writer.add_tokenizer_pre(vocabulary.pre)
    writer.add_token_list(vocabulary.tokens)
    writer.add_token_types(vocabulary.types)
    writer.add_token_merges(vocabulary.merges)
    writer.add_bos_token_id(vocabulary.bos)
    writer.add_pad_token_id(vocabulary.bos)
    writer.add_eos_token_id(vocabulary.eos)
    writer.add_add_bos_token(False)
    writer.add_chat_template(chat_template)

    def add_matrix(name: str, rows: int, cols: int, qtype: gguf.GGMLQuantizationType) -> None:
        data = matrices(rows, cols, qtype)
        if qtype == Q.F32:
            writer.add_tensor(name, data)
        else:
            writer.add_tensor(name, data, raw_dtype=qtype)  # uint8 rows; gguf derives the shape

    def ones(size: int) -> np.ndarray:
        return np.ones(size, dtype=np.float32)  # 1-D tensors must be float32 (f16 norms crash at the first step)

    add_matrix("token_embd.weight", n_vocab, n_embd, embedding_type)
    for layer in range(shape.n_layer):
        prefix = f"blk.{layer}"
        writer.add_tensor(f"{prefix}.attn_norm.weight", ones(n_embd))
        add_matrix(f"{prefix}.attn_q.weight", shape.n_head * head_dim, n_embd, matrix_type)
        add_matrix(f"{prefix}.attn_k.weight", shape.n_head_kv * head_dim, n_embd, matrix_type)
        add_matrix(f"{prefix}.attn_v.weight", shape.n_head_kv * head_dim, n_embd, matrix_type)
        writer.add_tensor(f"{prefix}.attn_q_norm.weight", ones(head_dim))
        writer.add_tensor(f"{prefix}.attn_k_norm.weight", ones(head_dim))
        add_matrix(f"{prefix}.attn_output.weight", n_embd, shape.n_head * head_dim, matrix_type)
        writer.add_tensor(f"{prefix}.ffn_norm.weight", ones(n_embd))
        add_matrix(f"{prefix}.ffn_gate.weight", shape.n_ff, n_embd, matrix_type)
        add_matrix(f"{prefix}.ffn_up.weight", shape.n_ff, n_embd, matrix_type)
        add_matrix(f"{prefix}.ffn_down.weight", n_embd, shape.n_ff, matrix_type)
    writer.add_tensor("output_norm.weight", ones(n_embd))
    if not tied_output:
        add_matrix("output.weight", n_vocab, n_embd, embedding_type)

    writer.write_header_to_file()
    writer.write_kv_data_to_file()
    writer.write_tensors_to_file()
    writer.close()
    return path


def build_tiny_qwen3(path: str | Path, seed: int = 0, context_length: int = 2048, chat_template: str = QWEN3_CHAT_TEMPLATE,
                     architecture: str = "qwen3") -> Path:
    """2 layers of 64 wide F32 random weights, byte-level vocabulary, output tied to the embeddings."""
    return write_qwen3_gguf(path, TINY, byte_level_vocabulary(), "F32", seed=seed, chat_template=chat_template,
                            architecture=architecture, context_length=context_length)


def build_qwen3_shaped(path: str | Path, size: str, quant: str, bpe_source: str | Path, seed: int = 0,
                       context_length: int = 8192) -> Path:
    """A Qwen3-`size`-shaped GGUF ("0.6b", "1.7b", "4b") in `quant`, with `bpe_source`'s English BPE.

    Written beside `path` and renamed into place, so an interrupted build never leaves a file that
    looks finished. The context length is what the product asks for (4096) with room; the real
    models' 40,960 changes nothing but the metadata.
    """
    path = Path(path)
    staging = path.with_name(f".{path.name}.partial")
    try:
        write_qwen3_gguf(staging, QWEN3_SHAPES[size], english_bpe_vocabulary(bpe_source), quant, seed=seed,
                         context_length=context_length)
        staging.replace(path)
    finally:
        staging.unlink(missing_ok=True)
    return path


def shaped_file_name(size: str, quant: str) -> str:
    return f"qwen3-{size}-shaped-{quant.lower()}.gguf"
