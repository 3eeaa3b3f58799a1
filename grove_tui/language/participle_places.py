"""A place said by what is done there in a participle after its head, with no "where", "that" or
"which": "the place serving tea and scones", "the counter selling stamps", "the spot handing out maps".
The participle starts a clause like "that serves tea and scones", read by meaning as such clauses are.
"""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Participles that say where a person is or goes, not what is done at the place: "the spot facing the
# stage", "the place leading to the exit" say where it is, and "the area heading north" nothing.
_NOT_DONE = frozenset("facing leading heading overlooking near nearing next adjoining bordering following "
                      "including according during regarding concerning pending notwithstanding".split())


def participle_starts(s: Sentence, j: int) -> bool:
    """Whether word j, right after a bare place head ("the place"), is a participle saying what is done
    there ("serving", "selling", "doing"), with words after it for what."""
    return j + 1 < s.n and s.w[j].tag == "VBG" and s.low[j].endswith("ing") and s.low[j] not in _NOT_DONE and \
        not s.is_punct(j + 1)


def participle_said(s: Sentence, first: int, said: str) -> str:
    """The clause at `first` said as people doing it there: "serving tea and scones" is "they serve tea
    and scones", nearer in meaning to the names of the place where it is done."""
    if first >= s.n or s.w[first].tag != "VBG" or not said.startswith(s.low[first]):
        return said
    return "they " + s.w[first].lemma.lower() + said[len(s.low[first]):]
