"""A person named by the collective they belong to (round 29): "the night shift boss crosses to line 3",
"the youth club volunteers set out chairs", "the cleaning crew supervisor walks to the bay". The reader
split the phrase at the collective ("the night shift" and a "boss" beside them), two groups; the
collective with its first word only says which people they are, so it is joined to them before the
sentence is parsed ("the night-shift boss"), one group of the person noun's number."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_COLLECTIVES = "shift|crew|club|choir|troop|squad|band|committee|rota"
_PHRASE = re.compile(r"(?<![-\w])([A-Za-z]+)\s+(" + _COLLECTIVES + r")\s+([A-Za-z]+)\b", re.IGNORECASE)
# First words that are no part of a name for the collective ("the shift boss", "a crew member").
_NOT_FIRST = frozenset("the a an this that these those his her their our my your its each every "
                       "whole entire of and or with from to for by".split())


# Words that end a count said before the collective ("twelve or so club members", "thirty-odd crew
# members", "a dozen club members"): the count's, no name for the collective; joining them lost the count.
_COUNT_ENDS = frozenset("so odd ish plus more dozen score couple".split()) | lx.APPROXIMATE_WORDS | \
    frozenset(lx.VAGUE_RANGES) | frozenset(lx.SCALES)
_TIMED = frozenset("after before during breakfast".split())
_HEADS = frozenset("chief captain secretary chairman chairwoman treasurer".split())


def with_collective_roles(text: str) -> str:
    """The text with "the night shift boss" written "the night-shift boss" (see the module doc)."""
    def joined(m: re.Match[str]) -> str:
        first, collective, person = m.group(1), m.group(2), m.group(3)
        before = m.string[:m.start()].split()[-1:]
        if (before and before[0].lower() in _TIMED) or first.lower().startswith(("after", "before")):
            return m.group(0)  # "ten after school club kids": a club named by a time, the count kept
        if first.lower() in _NOT_FIRST | _COUNT_ENDS or first.lower() in lx.NUMBER_WORDS or not _is_person(person.lower()):
            return m.group(0)
        return f"{first}-{collective} {person}"
    return _PHRASE.sub(joined, text)


def _is_person(word: str) -> bool:
    """Whether a word is a person noun of the lexicon, singular or plural ("boss", "volunteers")."""
    forms = {word, word[:-1] if word.endswith("s") else word, word[:-2] if word.endswith("es") else word,
             word[:-3] + "y" if word.endswith("ies") else word}
    heads = any(f.endswith(lx.COMPOUND_PERSON_HEADS) for f in forms) or bool(forms & _HEADS)
    return (bool(forms & lx.PERSON_NOUNS) or heads) and word not in lx.MULTIWORD_COLLECTIVES
