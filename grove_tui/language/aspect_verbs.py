"""Verbs that say only how another verb goes on ("keeps following", "starts wandering", "tries to
follow"): what the subject does is the verb they govern, so a subject no list names ("Stan keeps
following it") is judged a person by that verb, not by "keep"."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Verbs of aspect and attempt: their subject is whoever does the verb after them.
ASPECT_VERBS = frozenset("keep start begin continue try stop carry attempt".split())


def governed_verb(s: Sentence, head: int) -> int:
    """The verb that says what the subject of `head` does: the one it governs when `head` is a verb of
    aspect ("keeps following": following), else `head` itself."""
    if s.verb(head) not in ASPECT_VERBS:
        return head
    return next((k for k in range(head + 1, min(head + 4, s.n))
                 if s.w[k].head == head and s.w[k].dep == "xcomp" and s.w[k].pos == "VERB"), head)
