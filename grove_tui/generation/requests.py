"""What a generation is asked for beyond the sentence: the robot's start and goal. A plain value with no
dependencies, so a front end can build it without loading the planner (services hands it out)."""

from __future__ import annotations

from dataclasses import dataclass

# The longest prompt read (after whitespace is folded): a scenario is a sentence or two, and the model's
# context must hold the prompt beside the retrieved nodes. One limit for the CLI, the app, jobs and batch.
MAX_PROMPT_CHARS = 2000
# A run length asked with no number (`--simulate` alone, a job's "simulate": true): the scenario's own
# length (generation/run_length.py), said as a value no real length takes.
SCENARIO_LENGTH = -1.0

__all__ = ["Point", "RobotRequest"]

Point = tuple[float, float]


@dataclass(frozen=True)
class RobotRequest:
    """What the user asked of the robot; None parts are chosen by the pipeline. Strings are RoI names."""

    start: Point | str | None = None
    goal: Point | str | None = None
    enabled: bool = True
