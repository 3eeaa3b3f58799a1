"""A model process that crashes leaves its reason in its log (issue 35: "stopped unexpectedly while loading the
model (exit code 1)" with nothing in the log, and the run passed when repeated: the restart had emptied it)."""

from __future__ import annotations

import multiprocessing

from grove_tui.llm import worker


def test_a_crashing_worker_leaves_its_reason_and_the_next_start_keeps_it(tmp_path):
    log = tmp_path / "logs" / "llm-roi.log"
    log.parent.mkdir()
    log.write_text("lines of the worker before\n")
    context = multiprocessing.get_context("spawn")

    def start() -> int:
        parent, child = context.Pipe(duplex=True)
        cancel = context.Event()  # kept alive until the child has it
        process = context.Process(target=worker.serve, args=(child, cancel, str(tmp_path / "none.gguf"),
                                                             512, 1, "llama", str(log), None))
        process.start()
        child.close()
        parent.close()  # the worker's answer has nowhere to go: it dies of a BrokenPipeError
        process.join(120)
        return process.exitcode

    assert start() == 1
    first = log.read_text()
    assert first.startswith("lines of the worker before\n")  # appended to, not emptied
    assert f"for {tmp_path / 'none.gguf'} ---" in first
    assert "stopped: BrokenPipeError" in first and "Traceback" in first
    assert start() == 1  # the restart after a crash keeps the crash's lines
    second = log.read_text()
    assert second.startswith(first) and second.count("--- model worker") == 4  # two starts, two stops
