"""What the pipeline tells whoever runs it, stage by stage: progress events, plain values with no
dependencies, so a front end can tell them apart without loading the pipeline (services hands them out)."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["AttemptStarted", "Event", "StageFinished", "StageStarted", "TokenStreamed"]


@dataclass(frozen=True)
class StageStarted:
    stage: str


@dataclass(frozen=True)
class StageFinished:
    stage: str
    seconds: float
    prompt_tokens: int = 0
    completion_tokens: int = 0
    detail: str = ""


@dataclass(frozen=True)
class TokenStreamed:
    stage: str
    text: str


@dataclass(frozen=True)
class AttemptStarted:
    """The model is asked again within a stage: the tokens streamed so far belong to a discarded attempt."""

    stage: str
    attempt: int  # 2 for the first retry
    reason: str  # why the previous attempt was discarded ("cut off at 512 tokens", "invalid draft: ...")


Event = StageStarted | StageFinished | TokenStreamed | AttemptStarted
