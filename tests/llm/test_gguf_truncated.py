"""`models list` must not show a cut-short GGUF as healthy: the tensor table says how long it must be."""

from __future__ import annotations

import pytest

from grove_tui.errors import ModelError
from grove_tui.llm.gguf_info import read_gguf_info
from grove_tui.llm.registry import embedded_model_path


def test_the_embedded_model_is_complete():
    info = read_gguf_info(embedded_model_path())
    assert info.size_bytes > 0


@pytest.mark.parametrize("keep", [0.5, 0.999])
def test_a_truncated_model_is_named_truncated(tmp_path, keep):
    source = embedded_model_path()
    data = source.read_bytes()
    cut = tmp_path / "cut.gguf"
    cut.write_bytes(data[: int(len(data) * keep)])
    with pytest.raises(ModelError, match=r"truncated: its tensors need [\d,]+ bytes but the file has"):
        read_gguf_info(cut)


def test_a_file_cut_inside_the_header_is_truncated(tmp_path):
    cut = tmp_path / "cut.gguf"
    cut.write_bytes(embedded_model_path().read_bytes()[:4096])
    with pytest.raises(ModelError, match="truncated"):
        read_gguf_info(cut)
