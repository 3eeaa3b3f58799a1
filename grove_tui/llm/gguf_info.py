"""GGUF metadata without loading the model: what `grove models list` shows and what we check first.

llama.cpp reports a bad file only as "Failed to load model from file" (or crashes), so every file is
checked here before it reaches llama.cpp: magic bytes, architecture, and a memory estimate.
The header is scanned directly (gguf's GGUFReader builds Python objects for every vocabulary entry
and takes seconds on a 150k-token vocabulary); value types and names come from the gguf package.
"""

from __future__ import annotations

import mmap
import os
import struct
from dataclasses import dataclass, field
from pathlib import Path

import gguf

from grove_tui.errors import ModelError

GGUF_MAGIC = b"GGUF"
# gguf knows these architectures, but they embed, encode or tokenize audio: nothing to chat with.
NON_GENERATIVE_ARCHITECTURES = frozenset({
    "clip", "bert", "modern-bert", "nomic-bert", "nomic-bert-moe", "neo-bert", "jina-bert-v2", "jina-bert-v3",
    "eurobert", "t5encoder", "wavtokenizer-dec", "gemma-embedding", "llama-embed", "pangu-embedded",
})
SUPPORTED_ARCHITECTURES = frozenset(gguf.MODEL_ARCH_NAMES.values()) - NON_GENERATIVE_ARCHITECTURES
QWEN3_ARCHITECTURES = frozenset({"qwen3", "qwen3moe"})
# llama.cpp's own buffers (compute graph, scratch) on top of weights and KV, measured roughly on CPU.
RUNTIME_OVERHEAD_BYTES = 256 * 1024 * 1024

GGUFScalar = int | float | bool | str  # a metadata value (arrays are read as their length only)
_SCALAR_FORMATS = {
    gguf.GGUFValueType.UINT8: "<B", gguf.GGUFValueType.INT8: "<b", gguf.GGUFValueType.UINT16: "<H",
    gguf.GGUFValueType.INT16: "<h", gguf.GGUFValueType.UINT32: "<I", gguf.GGUFValueType.INT32: "<i",
    gguf.GGUFValueType.FLOAT32: "<f", gguf.GGUFValueType.BOOL: "<?", gguf.GGUFValueType.UINT64: "<Q",
    gguf.GGUFValueType.INT64: "<q", gguf.GGUFValueType.FLOAT64: "<d",
}


@dataclass(frozen=True)
class GGUFInfo:
    path: Path
    size_bytes: int
    architecture: str
    name: str
    quantization: str
    context_length: int | None
    block_count: int | None
    embedding_length: int | None
    head_count: int | None
    head_count_kv: int | None
    key_length: int | None
    value_length: int | None
    vocab_size: int | None
    chat_template: str | None
    metadata: dict[str, GGUFScalar] = field(repr=False, default_factory=dict)  # scalar keys only

    @property
    def is_qwen3(self) -> bool:
        return self.architecture in QWEN3_ARCHITECTURES

    @property
    def supported(self) -> bool:
        return self.architecture in SUPPORTED_ARCHITECTURES

    def kv_bytes_per_token(self) -> int:
        """f16 K and V for every layer; falls back to a generous guess when the file omits head sizes."""
        if not (self.block_count and self.head_count_kv and (self.key_length or (self.embedding_length and self.head_count))):
            return 160 * 1024
        head_dim = self.key_length or (self.embedding_length // self.head_count)  # type: ignore[operator]
        value_dim = self.value_length or head_dim
        return self.block_count * self.head_count_kv * (head_dim + value_dim) * 2

    def memory_estimate(self, n_ctx: int) -> int:
        return self.size_bytes + n_ctx * self.kv_bytes_per_token() + RUNTIME_OVERHEAD_BYTES


class _Scanner:
    def __init__(self, buffer: mmap.mmap | bytes, path: Path) -> None:
        self.buffer, self.offset, self.path = buffer, 0, path

    def take(self, size: int) -> bytes:
        end = self.offset + size
        if end > len(self.buffer):
            raise ModelError(f"{self.path}: the GGUF header is truncated (the download may be incomplete)")
        chunk = self.buffer[self.offset:end]
        self.offset = end
        return chunk

    def scalar(self, value_type: gguf.GGUFValueType) -> int | float | bool:
        fmt = _SCALAR_FORMATS[value_type]
        value: int | float | bool = struct.unpack(fmt, self.take(struct.calcsize(fmt)))[0]
        return value

    def whole(self, value_type: gguf.GGUFValueType = gguf.GGUFValueType.UINT64) -> int:
        """An integer field of the header (a length, a count, a type code): UINT32 or UINT64."""
        return int(self.scalar(value_type))

    def string(self) -> str:
        length = self.whole()
        return self.take(length).decode("utf-8", errors="replace")

    def skip_string(self) -> None:
        length = self.whole()
        self.offset += length
        if self.offset > len(self.buffer):
            raise ModelError(f"{self.path}: the GGUF header is truncated (the download may be incomplete)")

    def value(self, value_type: gguf.GGUFValueType) -> GGUFScalar | _ArrayLength:
        if value_type == gguf.GGUFValueType.STRING:
            return self.string()
        if value_type == gguf.GGUFValueType.ARRAY:
            item_type = gguf.GGUFValueType(self.whole(gguf.GGUFValueType.UINT32))
            count = self.whole()
            # Arrays are vocabularies and merges: we need their length, never their content.
            if item_type == gguf.GGUFValueType.STRING:
                for _ in range(count):
                    self.skip_string()
            elif item_type == gguf.GGUFValueType.ARRAY:
                raise ModelError(f"{self.path}: nested metadata arrays are not supported")
            else:
                self.offset += count * struct.calcsize(_SCALAR_FORMATS[item_type])
            return _ArrayLength(count)
        return self.scalar(value_type)


@dataclass(frozen=True)
class _ArrayLength:
    count: int


def check_gguf_file(path: str | os.PathLike[str]) -> Path:
    """Fail with a clear ModelError unless `path` is an existing file starting with the GGUF magic."""
    file = Path(path).expanduser()
    if not file.exists():
        raise ModelError(f"model file {file} does not exist")
    if not file.is_file():
        raise ModelError(f"model path {file} is not a file")
    with file.open("rb") as handle:
        magic = handle.read(4)
    if magic != GGUF_MAGIC:
        raise ModelError(f"{file} is not a GGUF model (it starts with {magic!r}, a GGUF file starts with b'GGUF'); "
                         "convert it with llama.cpp's convert_hf_to_gguf.py or download a .gguf file")
    return file


def read_gguf_info(path: str | os.PathLike[str]) -> GGUFInfo:
    """Read the header metadata of a GGUF file; ModelError if it is missing, not GGUF or damaged."""
    file = check_gguf_file(path)
    size = file.stat().st_size
    with file.open("rb") as handle, mmap.mmap(handle.fileno(), 0, access=mmap.ACCESS_READ) as buffer:
        scanner = _Scanner(buffer, file)
        scanner.take(4)
        version = scanner.whole(gguf.GGUFValueType.UINT32)
        if version not in (2, 3):
            raise ModelError(f"{file}: GGUF version {version} is not supported (expected 2 or 3)")
        tensor_count = scanner.whole()
        kv_count = scanner.whole()
        metadata: dict[str, GGUFScalar] = {}
        array_lengths: dict[str, int] = {}
        try:
            for _ in range(kv_count):
                key = scanner.string()
                value = scanner.value(gguf.GGUFValueType(scanner.whole(gguf.GGUFValueType.UINT32)))
                if isinstance(value, _ArrayLength):
                    array_lengths[key] = value.count
                else:
                    metadata[key] = value
        except (ValueError, KeyError, struct.error) as error:
            raise ModelError(f"{file}: damaged GGUF metadata ({error})") from None
        needed = _tensor_data_end(scanner, tensor_count, metadata)
    if needed > size:
        # The header is intact but the weights are cut short: an interrupted download or copy.
        raise ModelError(f"{file}: truncated: its tensors need {needed:,} bytes but the file has {size:,} "
                         f"(the download may be incomplete; fetch it again)")
    architecture = str(metadata.get("general.architecture", ""))
    if not architecture:
        raise ModelError(f"{file}: GGUF metadata has no general.architecture")

    def arch_int(suffix: str) -> int | None:
        value = metadata.get(f"{architecture}.{suffix}")
        return int(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else None

    file_type = metadata.get("general.file_type")
    if file_type is None:
        quantization = "unknown"
    else:
        try:
            if not isinstance(file_type, int):  # the key is a UINT32 in every file llama.cpp writes
                raise ValueError(file_type)
            quantization = gguf.LlamaFileType(file_type).name.removeprefix("MOSTLY_").removeprefix("ALL_")
        except ValueError:
            quantization = f"type {file_type}"
    vocab = arch_int("vocab_size") or array_lengths.get("tokenizer.ggml.tokens")
    template = metadata.get("tokenizer.chat_template")
    return GGUFInfo(
        path=file, size_bytes=size, architecture=architecture,
        name=str(metadata.get("general.name", file.stem)), quantization=quantization,
        context_length=arch_int("context_length"), block_count=arch_int("block_count"),
        embedding_length=arch_int("embedding_length"), head_count=arch_int("attention.head_count"),
        head_count_kv=arch_int("attention.head_count_kv") or arch_int("attention.head_count"),
        key_length=arch_int("attention.key_length"), value_length=arch_int("attention.value_length"),
        vocab_size=vocab, chat_template=template if isinstance(template, str) else None, metadata=metadata,
    )


def _tensor_data_end(scanner: _Scanner, tensor_count: int, metadata: dict[str, GGUFScalar]) -> int:
    """Where the last tensor's data ends, from the tensor infos after the metadata (GGUF v2/v3:
    name, n_dims, dims, type, offset relative to the aligned start of the data section)."""
    alignment = metadata.get("general.alignment", 32)
    if not isinstance(alignment, int) or isinstance(alignment, bool) or alignment <= 0:
        raise ModelError(f"{scanner.path}: damaged GGUF metadata (general.alignment is {alignment!r})")
    end_of_data = 0
    try:
        for _ in range(tensor_count):
            scanner.skip_string()
            n_dims = scanner.whole(gguf.GGUFValueType.UINT32)
            if n_dims > 8:
                raise ValueError(f"a tensor has {n_dims} dimensions")
            elements = 1
            for _ in range(n_dims):
                elements *= scanner.whole()
            tensor_type = gguf.GGMLQuantizationType(scanner.whole(gguf.GGUFValueType.UINT32))
            offset = scanner.whole()
            block_size, type_size = gguf.GGML_QUANT_SIZES[tensor_type]
            end_of_data = max(end_of_data, offset + elements // block_size * type_size)
    except (ValueError, KeyError, struct.error) as error:
        raise ModelError(f"{scanner.path}: damaged GGUF tensor table ({error})") from None
    data_start = -(-scanner.offset // alignment) * alignment
    return data_start + end_of_data


def available_memory_bytes() -> int | None:
    """MemAvailable from /proc/meminfo (Linux); None where that is unknown."""
    try:
        with open("/proc/meminfo", encoding="ascii") as handle:
            for line in handle:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        return None
    return None


def check_loadable(info: GGUFInfo, n_ctx: int, available: int | None = None) -> None:
    """ModelError if llama.cpp cannot run this file: unsupported architecture or not enough memory."""
    if not info.supported:
        raise ModelError(
            f"{info.path}: architecture {info.architecture!r} is not a text-generation model this llama.cpp can run "
            f"(Qwen3, Llama, Gemma, Phi and other decoder models are; embedding and vision encoders are not)")
    free = available_memory_bytes() if available is None else available
    needed = info.memory_estimate(n_ctx)
    if free is not None and needed > free:
        raise ModelError(
            f"{info.path}: not enough memory: the model needs about {needed / 2**30:.1f} GiB "
            f"({info.size_bytes / 2**30:.1f} GiB weights + {n_ctx} tokens of context) "
            f"but only {free / 2**30:.1f} GiB is available; use a smaller quantization or a smaller context")
