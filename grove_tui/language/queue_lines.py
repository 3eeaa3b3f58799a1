"""A queue said by the line people make or join, with words between (round 28): "form a long line at
the servery", "stand in an orderly queue", "join the back of the long queue for the till", "get in a
long line for tea". The lexicon's phrases say these with nothing between the verb and the line; here
a verb of making, joining or standing in a line, then up to five words of the phrase (determiners,
adjectives, "in", "back of"), then the word for the line, is queueing. Not "a line of chairs" (a
line of things) and not a line named after a place people go to ("the Northern line")."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Verbs whose object, or whose "in", is the line people stand in.
_LINING_VERBS = frozenset("form make join get stand wait fall".split()) | frozenset(
    "stick stuck sit stay remain be trap trapped".split())  # "are stuck in a long line at", "sit in a long queue"
# The words for the line itself.
_LINE_WORDS = frozenset({"line", "queue", "queues", "lines"})
# Words that may stand between the verb and the line: "in", "at", "the back of", an article.
_BETWEEN = frozenset("a an the in into at to back end tail of their his her its our one two single".split())


def lined_queue(s: Sentence, i: int) -> tuple[str, ...] | None:
    """The phrase of queueing starting at the verb at i ("form a long line", "join the back of the
    snaking queue"), or None."""
    if verb_lemma(s.low[i]) not in _LINING_VERBS and s.verb(i) not in _LINING_VERBS:
        return None
    for k in range(i + 1, min(i + 7, s.n)):
        w = s.low[k]
        if s.is_punct(k):
            return None
        if w in _LINE_WORDS:
            if k == i + 1:
                return None  # "form lines", "join queue": the lexicon's phrases or no phrase at all
            if k + 1 < s.n and s.low[k + 1] == "of" and w in ("line", "lines"):
                return None  # "form a line of chairs": a line of things
            return tuple(s.low[i:k + 1])
        if w in _BETWEEN or s.w[k].pos == "ADJ" or w.endswith(("ing", "ly")) and s.w[k].pos != "VERB":
            continue
        return None
    return None
