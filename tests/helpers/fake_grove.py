"""`grove` for the terminal tests of the UI: the real app, worlds, presets, pipeline and simulation in a
real terminal, with a scripted model (helpers.app.FakeLLM) and a lexical retriever in place of a GGUF
and the embedder, so a test about the UI does not wait for a model.

    PYTHONPATH=. python tests/helpers/fake_grove.py [--world W] [--preset P] [--draft TEXT]
                                                     [--load-seconds S] [--token-seconds S]

`--load-seconds` makes loading the model take that long (the app's warm-up shows it); `--token-seconds`
spaces the streamed tokens (a generation long enough to press a key during it); `--list-seconds` delays
the list of worlds (a key pressed before the lists are in).
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # tests/, for helpers.*

from helpers.app import QUEUE_DRAFT, FakeLLM, lexical_retriever  # noqa: E402

from grove_tui.services.session import GroveSession  # noqa: E402
from grove_tui.tui.app import run_app  # noqa: E402


class PacedLLM(FakeLLM):
    """FakeLLM whose tokens come `token_seconds` apart (and whose loading takes `load_seconds`)."""

    def __init__(self, text: str, token_seconds: float) -> None:
        super().__init__(text)
        self.token_seconds = token_seconds

    def generate(self, messages, grammar=None, *, on_token=None, cancel=None, **kwargs):  # noqa: ANN001, ANN201
        def paced(token: str) -> None:
            if self.token_seconds:
                time.sleep(self.token_seconds)
            if on_token is not None:
                on_token(token)

        return super().generate(messages, grammar, on_token=paced, cancel=cancel, **kwargs)


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--world")
    parser.add_argument("--preset")
    parser.add_argument("--draft", default=QUEUE_DRAFT)
    parser.add_argument("--load-seconds", type=float, default=0.0)
    parser.add_argument("--token-seconds", type=float, default=0.0)
    parser.add_argument("--list-seconds", type=float, default=0.0,
                        help="listing the worlds takes this long (a loaded machine's first second)")
    args = parser.parse_args()
    model = PacedLLM(args.draft, args.token_seconds)

    def load(role, info):  # noqa: ANN001, ANN202
        time.sleep(args.load_seconds)
        return model

    class PacedSession(GroveSession):
        def list_worlds(self) -> list[str]:
            time.sleep(args.list_seconds)
            return super().list_worlds()

    session = PacedSession(llm_factory=load, retriever_factory=lexical_retriever, model_niceness=10,
                      remember_step_seconds=True)  # as GroveSession.for_app
    return run_app(world=args.world, preset=args.preset, session=session)


if __name__ == "__main__":
    raise SystemExit(main())
