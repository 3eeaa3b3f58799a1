"""Adjectives said as people, with no noun after them: "a drunk kicks the robot", "a regular sits at
the bar", "a local asks the way" (one person), "the injured wait in triage", "the elderly rest in the
lounge" (some people). The word is a person noun only where a noun would stand: after a
determiner (describing words between: "an aggressive drunk"), with a verb, a preposition or the end
after it ("a blind man" keeps its noun)."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

# One person, after "a"/"an"/"the"/"another"/"one" ("a drunk", "the local").
SINGULAR_ADJECTIVE_PEOPLE = frozenset("drunk regular local native".split())
# People in general, after "the" ("the injured", "the elderly"): a plural, however singular the word looks.
PLURAL_ADJECTIVE_PEOPLE = frozenset("injured wounded homeless sick elderly infirm bereaved unemployed disabled "
                                    "blind deaf".split())
PLURAL_WORDS = frozenset({"people", "staff", "police", "crowd"}) | PLURAL_ADJECTIVE_PEOPLE
_SINGULAR_DETERMINERS = frozenset({"a", "an", "the", "another", "one", "this", "that"})
# What may follow a noun-less adjective that heads its phrase: its verb, a preposition, a relative.
_AFTER_HEAD = frozenset({"VERB", "AUX", "ADP", "PUNCT", "CCONJ", "ADV", "PART"})


def adjective_person(s: Sentence, i: int) -> bool:
    """Whether word i is an adjective standing for a person or people (see the module doc)."""
    word = s.low[i]
    if i == 0 or (word not in SINGULAR_ADJECTIVE_PEOPLE and word not in PLURAL_ADJECTIVE_PEOPLE):
        return False
    d = i - 1
    while d > 0 and d > i - 4 and s.w[d].pos in ("ADJ", "ADV") and s.low[d] not in _SINGULAR_DETERMINERS:
        d -= 1  # "an aggressive drunk", "the seriously injured": describing words before the adjective
    det = s.low[d]
    if not (det in _SINGULAR_DETERMINERS and word in SINGULAR_ADJECTIVE_PEOPLE or
            det == "the" and word in PLURAL_ADJECTIVE_PEOPLE):
        return False
    if i + 1 >= s.n:
        return True
    nxt = i + 1
    if s.low[nxt] in ("who", "that", "and", "or") or s.w[nxt].pos in _AFTER_HEAD:
        return True
    # The small model tags the verb after an adjective a noun ("a drunk kicks the robot"): an "-s"
    # word the lexicon knows as a verb or the parser makes the sentence's root ("a drunk staggers to
    # the exit"), or a verb's base form after a plural ("the injured wait").
    verb = s.verb(nxt)
    return s.w[nxt].pos in ("NOUN", "PROPN") and s.low[nxt].endswith("s") and (
        verb != s.low[nxt] or s.w[nxt].dep == "ROOT") or \
        word in PLURAL_ADJECTIVE_PEOPLE and (verb in lx.INTENT_VERBS or verb in lx.HUMAN_SUBJECT_VERBS)
