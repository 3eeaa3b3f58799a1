"""The model's worker process starts even when the UI has captured stdout/stderr (fileno -1)."""

from __future__ import annotations

import subprocess
import sys
import textwrap

import pytest

pytestmark = pytest.mark.slow  # every test here runs a real model


def test_worker_starts_when_stderr_has_no_file_descriptor():
    # A fresh interpreter, so the resource tracker has not been started by earlier tests.
    code = textwrap.dedent(
        """
        import sys

        class Captured:
            # what Textual installs while the app runs
            def write(self, text): return len(text)
            def flush(self): pass
            def isatty(self): return True
            def fileno(self): return -1

        from grove_tui.llm.local import LocalLLM
        from grove_tui.llm.registry import resolve_models

        choice = resolve_models(None, None, None)["bt"]
        real = sys.stderr
        sys.stderr = Captured()
        try:
            llm = LocalLLM(choice.path, role="bt", n_ctx=512)
            out = llm.generate("Say hi.", grammar='root ::= "hi"', max_tokens=8, temperature=0.0, seed=1)
            llm.close()
        finally:
            sys.stderr = real
        print("OK", out.completion_tokens)
        """
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr[-2000:]
    assert result.stdout.startswith("OK")
