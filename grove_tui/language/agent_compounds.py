"""People named by a noun and an agent noun made from a verb: "shelf stackers", "trolley pushers",
"dog walkers", "ticket checkers", "window cleaners". The small model often parses the first noun as
the subject and the agent noun as another ("Three shelf stackers walk": "shelf" nsubj of "stackers"),
so neither is found as a person and the count is lost; the pair is a person when the agent noun's
verb is an English word and the phrase does what people do."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import known_word
from grove_tui.language.sentence import Sentence


def _verb_stems(word: str) -> list[str]:
    """The verbs an "-er" noun may be made from: "stacker" stack, "shopper" shop, "dancer" dance."""
    if not word.endswith("er") or len(word) < 5:
        return []
    stem = word[:-2]
    stems = [stem, stem + "e"]
    if len(stem) > 2 and stem[-1] == stem[-2]:
        stems.append(stem[:-1])  # "shopper" -> "shop"
    return stems


def agent_of_a_verb(word: str, near: str) -> bool:
    """Whether a word is an "-er" noun of an English verb ("pickers", "stackers"), not a misspelling of
    the person noun `near` one edit away: "pickers" is no "packers", but "visiters" are visitors (the
    same verb's person)."""
    base = word[:-1] if word.endswith("ers") else word
    return any(known_word(stem) and not near.startswith(stem) for stem in _verb_stems(base))


def agent_compound(s: Sentence, i: int) -> bool:
    """Whether word i is the agent noun of a noun + verb-"er" compound naming people (see the module
    doc): a noun before it that hangs on it, the noun's stem an English word, and no thing so named
    (a place, an animal or object, a time) doing only what things do."""
    if i < 1 or s.w[i].pos not in ("NOUN", "PROPN") or s.w[i - 1].pos not in ("NOUN", "PROPN"):
        return False
    if s.w[i - 1].head != i or s.w[i - 1].dep not in ("compound", "nsubj", "amod"):
        return False
    lem = s.lemma(i)
    if lem == s.low[i] and not (i >= 2 and s.low[i - 2] in ("a", "an", "the")):
        return False  # "three aunties chatter": a plural's verb, no "-er" person
    if s.lemma(i - 1) in lx.PERSON_NOUNS:
        return False  # "the nurses chatter": people, then their verb
    if lem in lx.NON_PEOPLE or lem in lx.NON_PLACES or s.index.knows(lem) or s.index.knows(s.lemma(i - 1)):
        return False
    if s.low[i - 1] in lx.ROBOT_WORDS or not any(known_word(stem) for stem in _verb_stems(lem)):
        return False
    word = s.w[i]
    if word.dep in ("nsubj", "nsubjpass") and word.head != i:
        return s.verb(word.head) not in lx.THING_VERBS  # "two leaf blowers hum": things
    return i >= 2 and s.w[i - 2].pos == "NUM"  # "three shelf stackers", however the parse hangs them
