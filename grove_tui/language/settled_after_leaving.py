"""Leaving a place and then settling somewhere is going there (issue 29): "my roommate heads out of the
restroom and flops onto the couch", "a porter steps out of the lift and sinks into a chair in the
lounge", "the nurse leaves the ward and sits down at the station". As with coming in (coming_in.py), a
verb of sitting or slumping down said after a verb of going out of a place does not make the clause a
wait: they walk from the place they left, and where they settle is where they go."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.posture_verbs import POSTURE_VERBS
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Verbs of sitting or slumping down somewhere to stay (with the lexicon's and posture_verbs.py's).
_SETTLING = frozenset({"sit", "settle", "perch", "sink", "collapse", "plonk", "plop"}) | POSTURE_VERBS
# Verbs of staying hidden somewhere, which the lexicon reads as no intent of their own ("and hides in X").
_HIDING = frozenset({"hide", "hid", "hides", "hiding"})
_OUT = frozenset({"out", "from", "off", "away"})  # "runs off and hides in the bathroom": gets away, then goes there
_LEAVING = frozenset({"leave", "exit", "emerge", "quit"})
_FORMS = {"flops": "flop", "flopped": "flop", "flopping": "flop", "slumps": "slump", "sinks": "sink",
          "sank": "sink", "plonks": "plonk", "plops": "plop", "sprawls": "sprawl", "collapses": "collapse"}


def _lemma(s: Sentence, i: int, verb: str) -> str:
    return _FORMS.get(s.low[i]) or verb_lemma(s.low[i]) or verb


def _settling(s: Sentence, candidates: Sequence[tuple[int, str, str]]) -> tuple[int, str, str] | None:
    """The verb of settling among the candidates, or "and hides" after a walk ("runs off and hides in X")."""
    sat = next((c for c in candidates if c[1] == "wait" and (c[2] in _SETTLING or _lemma(s, c[0], c[2]) in _SETTLING)),
               None)
    if sat is not None or not candidates:
        return sat
    first = min(c[0] for c in candidates)
    return next(((k, "wait", "hide") for k in range(first + 2, s.n) if s.low[k] in _HIDING and s.low[k - 1] in
                 ("and", "then")), None)


def settled_after_leaving(s: Sentence, candidates: Sequence[tuple[int, str, str]]) -> tuple[int, str, str] | None:
    """The verb of going out of a place said before a verb of settling somewhere ("heads out of the
    restroom and flops onto the couch"): the clause is walking there (module doc). None otherwise."""
    sat = _settling(s, candidates)
    if sat is None or any(c[1] not in ("walk", "wait") for c in candidates):
        return None
    if not any(s.low[x] in ("on", "onto", "into", "in", "at", "down", "under", "behind", "beneath")
               for x in range(sat[0] + 1, min(s.n, sat[0] + 3))):
        return None  # "leaves the ward and sits": no place said where they settle
    return next((c for c in candidates if c[1] == "walk" and c[0] < sat[0] and (
        c[2] in _LEAVING or any(s.low[x] in _OUT for x in range(c[0] + 1, min(s.n, c[0] + 3))))), None)


def settled_at(s: Sentence, candidates: Sequence[tuple[int, str, str]]) -> int:
    """Where the verb of settling is (for the places said after it, where they go); -1 if none."""
    sat = _settling(s, candidates)
    return -1 if sat is None else sat[0]
