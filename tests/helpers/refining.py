"""A scenario bundle to refine, generated through the real pipeline with a scripted model (a fixed
draft), so tests of follow-ups run in seconds and can count and read the model's requests."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from grove_tui.generation.pipeline import GenerationPipeline
from grove_tui.generation.presets import load_preset
from grove_tui.generation.retrieval import NodeRetriever
from grove_tui.llm.local import Generation
from grove_tui.scenario.bundle import write_bundle

PROMPT = ("ten patients queue at the pharmacy while two nurses walk to the cafeteria and a cleaner wanders in "
          "the main corridor")
# The queuing preset without retrieval offers GoTo and Queue, and the sentence's zones as places:
# reconciliation writes the cleaner's wandering.
DRAFT = ("10 patients from pharmacy: Sequence(GoTo(pharmacy), Queue(pharmacy))\n"
         "2 nurses from pharmacy: GoTo(cafeteria)\n"
         "1 cleaner from main_corridor: GoTo(main_corridor)")


class ScriptedLLM:
    """Answers with the next scripted draft and keeps what it was asked."""

    def __init__(self, *answers: str) -> None:
        self.answers = list(answers)
        self.path = Path("scripted.gguf")
        self.asked: list[Any] = []

    def generate(self, messages: Any, grammar: str | None = None, **_: Any) -> Generation:
        self.asked.append(messages)
        if not self.answers:
            raise AssertionError("the scripted model was asked more than it was scripted for")
        return Generation(self.answers.pop(0), "stop", 100, 40, 0.01, 0.001)


class NoRetrieval(NodeRetriever):
    """The real node documents; ranking is not under test, the preset's required nodes suffice."""

    def retrieve(self, prompt: str, preset: Any = None, k: int = 8) -> list[Any]:
        return []


def build_base_bundle(out: Path, world: Any, preset: str = "queuing", prompt: str = PROMPT, draft: str = DRAFT,
                      seed: int = 2) -> Path:
    pipeline = GenerationPipeline(world, load_preset(preset), None, ScriptedLLM(draft), NoRetrieval())
    return write_bundle(pipeline.run(prompt, seed=seed), out)
