"""The one error the gym package raises; exit codes follow the CLI's (2 bad input, 3 runtime failure)."""

from __future__ import annotations

from grove_tui.errors import GroveError

BAD_INPUT = 2
RUNTIME_FAILURE = 3


class GymError(GroveError):
    """A bad environment argument (bundle, kinematics, action) or a scenario the robot cannot run in.

    `hint` says what to do about it; `exit_code` is the CLI's code for this kind of problem.
    """

    def __init__(self, message: str, hint: str = "", exit_code: int = BAD_INPUT) -> None:
        super().__init__(f"{message} ({hint})" if hint else message)
        self.hint = hint
        self.exit_code = exit_code
