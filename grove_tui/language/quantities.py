"""Deterministic reading of the prompt: word normalisation and the head counts it states.

Small models miscount, so the numbers a user writes ("ten", "a dozen", "20 people", "a family of
four") are read here, without the model, and post-processing makes the population match them.
The same light lemmatiser feeds the strategic layer's token matching.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from grove_tui.language.lexicon import BIG_SCALES as _BIG_SCALES
from grove_tui.language.lexicon import NUMBER_WORDS, PERSON_NOUNS, STOPWORDS
from grove_tui.language.lexicon import SCALES as _SCALES
from grove_tui.language.lexicon import TENS as _TENS
from grove_tui.language.lexicon import UNITS as _UNITS
from grove_tui.language.tokens import lemma, semantic_tokens, words

__all__ = ["NUMBER_WORDS", "PERSON_NOUNS", "STOPWORDS", "Quantity", "extract_quantities", "lemma", "semantic_tokens",
           "words"]

# Words that end a counted phrase without being stopwords for matching ("waiting" names a room).
_PHRASE_STOPS = frozenset("go goes going walk walks walking stand stands standing wait waits waiting sit sits sitting".split())

# Vague quantities get a fixed, documented reading so the same prompt always gives the same crowd.
VAGUE = {"few": 3, "handful": 4, "several": 4, "some": 3, "couple": 2, "pair": 2, "dozens": 24, "many": 12}
_VAGUE_EXACT = {"couple", "pair"}  # "a couple of" means two, not "about two"

# Collectives whose size follows an "of N" ("a family of four", "a group of 5 friends").
COLLECTIVES = frozenset({"family", "group", "team", "party", "crowd", "couple", "queue", "line", "bunch", "circle"})
# Words after a bare number that show it counts the people of an earlier phrase ("and ten in the lobby").
_ELLIPSIS_FOLLOWERS = frozenset({"in", "at", "from", "inside", "near", "by", "on", "outside", "more", "others", "other"})
# A bare number after these is a time or a label ("at 3 in the afternoon", "bed 4 in ward a").
_NOT_A_HEAD_COUNT_BEFORE = frozenset({"at", "until", "till", "after", "before", "since", "room", "ward", "bed",
                                      "floor", "level", "gate", "number", "no", "desk", "table", "platform"})
# How many people a collective means when the prompt gives no size ("a family walks to the exit"):
# one family is not one person. These counts are marked inexact.
TYPICAL_SIZE = {"family": 4, "group": 4, "team": 5, "party": 4, "crowd": 15, "bunch": 5, "circle": 4,
                "queue": 6, "line": 6}


@dataclass(frozen=True)
class Quantity:
    """A head count the prompt states, attached to the phrase it counts."""

    count: int
    noun: str  # lemma of the counted noun: "patient", "family", "person"
    phrase: str  # the prompt words from the number to the end of the noun: "ten patients"
    start: int  # character span of `phrase` in the prompt
    end: int
    exact: bool  # False for vague words (few, several)
    implied: bool = False  # no number at all ("visitors walk in"): adds a missing group, never resizes one

    @property
    def label_tokens(self) -> frozenset[str]:
        return frozenset(t for t in semantic_tokens(self.phrase) if t not in NUMBER_WORDS)


_TOKEN = re.compile(r"\d{1,3}(?:,\d{3})+|\d+|[A-Za-z]+(?:'[A-Za-z]+)?")


_CLAUSE_STARTERS = frozenset("while whilst and but as meanwhile then when".split())
_SUBJECT_MODIFIERS = frozenset("the some other more many all tired young old elderly busy waiting".split())
BARE_PLURAL_COUNT = 4  # "visitors walk to ward a": some visitors, not none


def _bare_plurals(prompt: str, toks: list[tuple[str, int, int]], low: list[str], found: list[Quantity]) -> list[Quantity]:
    """Plural person nouns that open a clause with no number ("... while visitors walk to ward a"):
    a vague head count, so the group is not lost."""
    covered = [(q.start, q.end) for q in found]
    out: list[Quantity] = []
    for k, w in enumerate(low):
        noun = lemma(w)
        if noun == w or noun not in PERSON_NOUNS or noun in COLLECTIVES:
            continue  # singular, not a person, or a collective ("families" is handled as a count)
        if any(a <= toks[k][1] < b for a, b in covered) or (k + 1 < len(low) and low[k + 1] == "of"):
            continue
        j = k - 1
        while j >= 0 and low[j] in _SUBJECT_MODIFIERS:
            j -= 1
        if j >= 0 and low[j] not in _CLAUSE_STARTERS:
            continue  # "queue with patients", "help the nurses": not who the clause is about
        q = _quantity(prompt, toks, j + 1, k, BARE_PLURAL_COUNT, noun, False)
        out.append(Quantity(q.count, q.noun, q.phrase, q.start, q.end, q.exact, implied=True))
    return out


def extract_quantities(prompt: str) -> list[Quantity]:
    """Every stated head count, in prompt order; each person phrase is counted once. A plural person
    noun opening a clause without a number counts as a vague group of BARE_PLURAL_COUNT."""
    toks = [(m.group(0), m.start(), m.end()) for m in _TOKEN.finditer(prompt)]
    low = [t[0].lower() for t in toks]
    found: list[Quantity] = []
    used_until = -1
    i = 0
    while i < len(toks):
        if i <= used_until:
            i += 1
            continue
        parsed = _read_number(low, i)
        if parsed is None:
            i += 1
            continue
        value, exact, j = parsed  # j: first token after the number words
        # "a family of four", "a group of 5 nurses": the collective noun sits before the number.
        if i >= 2 and low[i - 1] == "of" and lemma(low[i - 2]) in COLLECTIVES and not _is_counted_noun(low, j):
            noun_index = i - 2
            begin = noun_index - 1 if noun_index >= 1 and low[noun_index - 1] in ("a", "an", "one") else noun_index
            found.append(_quantity(prompt, toks, begin, j - 1, value, lemma(low[noun_index]), exact))
            used_until = j - 1
            i = j
            continue
        noun_at = _find_noun(low, j)
        if noun_at is None and low[j - 1] in ("couple", "pair") and low[i] in ("a", "one"):
            noun_at = j - 1  # "a couple walks in": the couple is the counted noun
        if (noun_at is None and found and j < len(low) and low[j] in _ELLIPSIS_FOLLOWERS and exact
                and (i == 0 or low[i - 1] not in _NOT_A_HEAD_COUNT_BEFORE)):
            # "twenty people in the cafeteria and ten in the pharmacy": the number borrows the noun
            found.append(_quantity(prompt, toks, i, j - 1, value, found[-1].noun, exact))
            used_until = j - 1
            i = j
            continue
        if noun_at is None:
            i = j
            continue
        noun = lemma(low[noun_at])
        if noun in COLLECTIVES and noun_at + 2 < len(low) and low[noun_at + 1] == "of":
            # "two groups of three" -> 6 people; "a group of nurses" -> the collective word's count.
            inner = _read_number(low, noun_at + 2)
            if inner is not None:
                value, exact, end = value * inner[0], exact and inner[1], inner[2]
                tail = _find_noun(low, end)
                last = tail if tail is not None and tail <= end + 1 else end - 1
                found.append(_quantity(prompt, toks, i, last, value, noun, exact))
                used_until = last
                i = last + 1
                continue
            member = _find_noun(low, noun_at + 2)
            if member is not None and member <= noun_at + 3 and lemma(low[member]) in PERSON_NOUNS:
                if value == 1 and low[i] in ("a", "an"):
                    # "a group of nurses" states no number: the group's size is the model's choice.
                    i = member + 1
                    used_until = member
                    continue
        if noun in TYPICAL_SIZE:
            value, exact = value * TYPICAL_SIZE[noun], False
        found.append(_quantity(prompt, toks, i, noun_at, value, noun, exact))
        used_until = noun_at
        i = noun_at + 1
    return sorted(found + _bare_plurals(prompt, toks, low, found), key=lambda q: q.start)


def _quantity(prompt: str, toks: list[tuple[str, int, int]], first: int, last: int, value: int, noun: str, exact: bool) -> Quantity:
    start, end = toks[first][1], toks[last][2]
    return Quantity(count=value, noun=noun, phrase=prompt[start:end], start=start, end=end, exact=exact)


def _is_counted_noun(low: list[str], j: int) -> bool:
    return j < len(low) and lemma(low[j]) in PERSON_NOUNS and lemma(low[j]) not in COLLECTIVES


def _find_noun(low: list[str], j: int) -> int | None:
    """The person noun a number counts: within three words ("ten tired old patients"), before any verb-like stop."""
    for k in range(j, min(j + 4, len(low))):
        w = low[k]
        if w == "of" and k == j:
            continue  # "a dozen of the nurses"
        if w in ("the", "them", "those", "these") and k <= j + 1:
            continue
        if lemma(w) in PERSON_NOUNS:
            return k
        if (w in STOPWORDS or w in _PHRASE_STOPS) and w != "of":
            return None
    return None


def _read_number(low: list[str], i: int) -> tuple[int, bool, int] | None:
    """(value, exact, index after) for a number expression starting at token i, else None."""
    w = low[i]
    n = len(low)
    nxt = low[i + 1] if i + 1 < n else ""
    if re.fullmatch(r"\d{1,3}(?:,\d{3})+|\d+", w):
        value = int(w.replace(",", ""))
        if nxt == "dozen":
            return value * 12, True, i + 2
        if nxt in _SCALES:
            return value * _SCALES[nxt], True, i + 2
        return value, True, i + 1
    if w in ("a", "an"):
        if nxt == "dozen":
            return 12, True, i + 2
        if nxt in ("couple", "pair"):
            j = i + 2
            return 2, True, j + 1 if j < n and low[j] == "of" else j
        if nxt in ("few", "handful"):
            j = i + 2
            return VAGUE[nxt], False, j + 1 if j < n and low[j] == "of" else j
        if nxt in _SCALES:
            return _SCALES[nxt], True, i + 2
        if nxt and lemma(nxt) in PERSON_NOUNS:
            return 1, True, i + 1
        return None
    if w in ("few", "several", "dozens", "handful"):
        j = i + 1
        return VAGUE[w], w in _VAGUE_EXACT, j + 1 if j < n and low[j] == "of" else j
    if w in _UNITS or w in _TENS:
        value, j = _spelled(low, i)
        if j < n and low[j] == "dozen":
            return value * 12, True, j + 1
        return value, True, j
    if w == "dozen":
        return 12, True, i + 1
    return None


def _spelled(low: list[str], i: int) -> tuple[int, int]:
    """Spelled-out whole numbers up to the thousands: "twenty five", "two hundred and ten"."""
    total, current, j = 0, 0, i
    while j < len(low):
        w = low[j]
        if w in _UNITS:
            current += _UNITS[w]
        elif w in _TENS:
            current += _TENS[w]
        elif w in _SCALES and (current or total):
            current = max(current, 1) * _SCALES[w]
            if w in _BIG_SCALES:
                total, current = total + current, 0
        elif w == "and" and j + 1 < len(low) and (low[j + 1] in _UNITS or low[j + 1] in _TENS) and (current >= 100 or total):
            pass
        else:
            break
        j += 1
    return total + current, j
