"""People named by a noun and an agent noun made from a verb: "shelf stackers", "trolley pushers",
"dog walkers", "ticket checkers", "window cleaners". The small model often parses the first noun as
the subject and the agent noun as another ("Three shelf stackers walk": "shelf" nsubj of "stackers"),
so neither is found as a person and the count is lost; the pair is a person when the agent noun's
verb is an English word and the phrase does what people do. A hyphen may join the two ("sun-seekers",
"thrill-seekers"), and the count may be a noun ("a dozen bargain hunters", round 23)."""

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
    m = i - 2 if i >= 3 and s.w[i - 1].tag == "HYPH" else i - 1  # "sun-seekers": the noun before the hyphen
    if i < 1 or s.w[i].pos not in ("NOUN", "PROPN") or s.w[m].pos not in ("NOUN", "PROPN"):
        return False
    if (s.w[m].head != i and m == i - 1) or s.w[m].dep not in ("compound", "nsubj", "amod"):
        return False
    lem = s.lemma(i)
    if lem == s.low[i] and not (m >= 1 and s.low[m - 1] in ("a", "an", "the")):
        return False  # "three aunties chatter": a plural's verb, no "-er" person
    if s.lemma(m) in lx.PERSON_NOUNS:
        return False  # "the nurses chatter": people, then their verb
    if lem in lx.NON_PEOPLE or lem in lx.NON_PLACES or s.index.knows(lem) or s.index.knows(s.lemma(m)):
        return False
    if s.low[m] in lx.ROBOT_WORDS or not any(known_word(stem) for stem in _verb_stems(lem)):
        return False
    word = s.w[i]
    if word.dep in ("nsubj", "nsubjpass") and word.head != i:
        return s.verb(word.head) not in lx.THING_VERBS or _idling(s, word.head)  # "two leaf blowers hum": things
    return m >= 1 and (s.w[m - 1].pos == "NUM" or s.w[m - 1].dep == "nummod")  # "three shelf stackers", "a dozen ..."


def _idling(s: Sentence, v: int) -> bool:
    """Whether a verb of things is said with a particle of people passing time ("hang about", "hang
    around"), no object after it ("lights hang around the bar"): what people do."""
    if v + 1 >= s.n or s.low[v + 1] not in ("about", "around", "round"):
        return False
    return v + 2 >= s.n or s.w[v + 2].pos not in ("DET", "NOUN", "PROPN", "NUM", "ADJ")  # not "around the bar"
