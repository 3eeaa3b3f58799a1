"""Numbers and quantities as people write them: digits and words ("twenty five", "a dozen", "10
million"), approximations ("about 20", "fifteen or so", "twenty-odd"), ranges ("two or three",
"between 5 and 8"), vague words ("a few", "lots of"), durations ("half an hour"), and the counts
they make (language/model.py `Count`, ranges documented in language/lexicon.py)."""

from __future__ import annotations

import math
import re
from typing import NamedTuple

from grove_tui.language import lexicon as lx
from grove_tui.language.acronym_units import acronym_before_noun
from grove_tui.language.described_ranges import couple_or_more, is_described_estimate
from grove_tui.language.model import Count
from grove_tui.language.quantity_nouns import VAGUE_QUANTITY_RANGES, quantity_noun_at
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma

_DECIMAL = re.compile(r"\d+\.\d+")
# Words a school year or stage is named by, before its number ("year 6", "grade 9", "class 3").
COHORT_WORDS = frozenset("year grade class form level stage standard".split())


class Quantifier(NamedTuple):
    """A count expression: its value (0 for vague words), kind ("exact", "approximate", "range",
    "vague:<word>"), the word index after it, and the top of a range."""

    value: int
    kind: str
    end: int
    high: int | None = None
    low: int | None = None  # the bottom of an approximate count with its own bounds ("2.5": 2-3)


def number_at(s: Sentence, i: int) -> tuple[int, int] | None:
    """(value, index after) of a number written at word i: digits, words, "a dozen", "twenty five"."""
    if i >= s.n:
        return None
    low = s.low
    w = low[i].replace(",", "")
    if w.isdigit():
        value, j = int(w), i + 1
        if j < s.n and low[j] in lx.SCALES:  # "10 million people": read, so it can be refused
            value, j = value * lx.SCALES[low[j]], j + 1
    elif w in lx.UNITS or w in lx.TENS:
        total, current, j = 0, 0, i
        while j < s.n:
            x = low[j]
            if x in lx.UNITS and j > i and low[j - 1] in lx.UNITS:
                break  # "ten five-a-side regulars": a number word after a unit starts another word
            if x in lx.UNITS:
                current += lx.UNITS[x]
            elif x in lx.TENS:
                current += lx.TENS[x]
            elif x == "-" and j + 1 < s.n and low[j + 1] in lx.UNITS and current % 10 == 0 and current:
                pass  # "twenty-five"
            elif x in lx.SCALES and (current or total):
                current = max(current, 1) * lx.SCALES[x]
                if x in lx.BIG_SCALES:
                    total, current = total + current, 0
            elif x == "and" and j + 1 < s.n and low[j + 1] in lx.UNITS and current >= 100:
                pass
            else:
                break
            j += 1
        value = total + current
    elif w == "dozen":
        value, j = 12, i + 1
    elif w in ("a", "an") and i + 1 < s.n and (low[i + 1] == "dozen" or low[i + 1] in lx.SCALES):
        # "a thousand", "a billion people": read as numbers, so check_population refuses them.
        value, j = (12 if low[i + 1] == "dozen" else lx.SCALES[low[i + 1]]), i + 2
    elif w == "half" and tuple(low[i + 1:i + 3]) == ("a", "dozen"):
        value, j = 6, i + 3  # "half a dozen"
    else:
        return None
    if j < s.n and low[j] == "dozen" and w != "dozen":
        value, j = value * 12, j + 1
    return value, j


def decimal_at(s: Sentence, i: int) -> tuple[float, int] | None:
    """(value, index after) of a number with a fraction ("2.5"): people come whole, so it is read
    as an approximate count between the whole numbers around it."""
    if i < s.n and _DECIMAL.fullmatch(s.low[i]):
        return float(s.low[i]), i + 1
    return None


def cohort_number(s: Sentence, i: int) -> bool:
    """Whether the number at word i names a school year or stage ("four year 6 pupils"): after a
    cohort word and before a noun, it counts nobody."""
    return (0 < i < s.n - 1 and s.low[i - 1] in COHORT_WORDS and s.w[i].pos == "NUM" and number_at(s, i) is not None
            and number_at(s, i + 1) is None and s.w[i + 1].pos in ("NOUN", "PROPN", "ADJ")
            and lemma(s.low[i + 1]) not in lx.DURATION_UNITS)


def negative_at(s: Sentence, i: int) -> bool:
    """Whether a negative number starts at word i ("-5 people", "minus 3 nurses"), not a range ("3-5")."""
    word = s.low[i]
    if word[:1] in ("-", "\u2212") and word[1:].replace(",", "").isdigit():
        return True
    if word in ("minus", "negative") and number_at(s, i + 1) is not None:
        return True
    return word in ("-", "\u2212") and number_at(s, i + 1) is not None and (i == 0 or number_at(s, i - 1) is None)


# Counts said by a bound ("over 40 passengers", "under a dozen guests", "no more than 10"): the
# labelling convention reads a bound as about that number (+-20 %), like "at least" and "up to".
BOUND_PHRASES: tuple[tuple[str, ...], ...] = (
    ("no", "more", "than"), ("not", "more", "than"), ("no", "fewer", "than"), ("no", "less", "than"),
    ("more", "than"), ("fewer", "than"), ("less", "than"), ("well", "over"), ("well", "under"),
    ("over",), ("under",), ("nearer",), ("getting", "on", "for"))


def bound_at(s: Sentence, k: int) -> int | None:
    """The index of the number after a bound phrase at word k, else None."""
    for phrase in BOUND_PHRASES:
        if tuple(s.low[k:k + len(phrase)]) == phrase and number_at(s, k + len(phrase)) is not None:
            return k + len(phrase)
    return None


def strong_size(s: Sentence, k: int) -> tuple[int, int] | None:
    """(size, index after) of "8-strong" / "eight strong" at word k (after "a"/"an" if any): how many
    a collective after it has ("an 8-strong jury", "a forty-strong coach party")."""
    if k < s.n and s.low[k] in ("a", "an"):
        k += 1
    num = number_at(s, k)
    if num is None:
        return None
    after = num[1] + 1 if num[1] < s.n and s.low[num[1]] == "-" else num[1]
    if after < s.n and s.low[after] == "strong" and num[0] > 0:
        return num[0], after + 1
    return None


def quantifier(s: Sentence, j: int) -> Quantifier | None:
    """The count expression at word j, if one starts there."""
    low = s.low
    if j >= s.n:
        return None
    if cohort_number(s, j):
        return None  # "four year 6 pupils": the 6 is their school year
    approx = False
    k = j
    if low[k] in lx.APPROXIMATE_WORDS and k + 1 < s.n and (number_at(s, k + 1) is not None
                                                           or decimal_at(s, k + 1) is not None):
        approx, k = True, k + 1
    else:
        for phrase in lx.APPROXIMATE_PHRASES:
            if tuple(low[k:k + len(phrase)]) == phrase and number_at(s, k + len(phrase)) is not None:
                approx, k = True, k + len(phrase)
                break
    bounded = bound_at(s, k) if not approx else None
    if bounded is not None:
        approx, k = True, bounded
    size = strong_size(s, k)
    if size is not None:
        return Quantifier(size[0], "strong", size[1])  # "an 8-strong jury": one party of that many
    if low[k] == "between" and number_at(s, k + 1):
        a = number_at(s, k + 1)
        if a is not None and a[1] < s.n and low[a[1]] == "and":
            b = number_at(s, a[1] + 1)
            if b is not None:
                return Quantifier(a[0], "range", b[1], b[0])
    fraction = decimal_at(s, k)
    if fraction is not None and fraction[0] > 0:
        value, after = fraction
        return Quantifier(max(1, math.floor(value + 0.5)), "approximate", after, max(1, math.ceil(value)),
                          max(1, math.floor(value)))
    num = number_at(s, k)
    if num is not None and num[1] < s.n and low[num[1]] in lx.DETERMINERS and not approx and \
            not (num[1] + 1 < s.n and s.joins(num[1] + 1)):  # "Two A-level students": a word, no "a"
        return None  # "At nine the porters come in": a time, then the phrase; a number counts no "the ..."
    if num is not None and num[1] < s.n and low[num[1]] in ("am", "pm", "a.m", "p.m", "o'clock", "oclock") and not approx:
        return None  # "the 9 am class", "the 2 pm tour": a time, no count
    if num is not None:
        return _number_quantifier(s, num, approx)
    if low[k] == "both" and k + 1 < s.n and not s.is_punct(k + 1):
        return Quantifier(2, "exact", k + 1)  # "both guards", "both of them"
    noun = quantity_noun_at(s, k)
    if noun is not None:  # "a score of pupils": twenty; "a classful of children": a class
        return Quantifier(noun.value, "exact" if noun.value else f"vague:{noun.word}", noun.end)
    if low[k] in ("a", "an") and k + 1 < s.n:
        nxt = low[k + 1]
        if (more := couple_or_more(s, k)) is not None:
            return Quantifier(2, "approximate", more[1], more[0], 2)  # "a couple or three visitors": about 2-3
        if nxt == "couple" and tuple(low[k + 2:k + 4]) == ("of", "dozen"):
            return Quantifier(24, "approximate", k + 4)  # "a couple of dozen tourists": about 24
        if nxt in ("couple", "pair") and k + 2 < s.n and low[k + 2] == "of":
            return Quantifier(2, "exact", k + 3)
        if nxt == "few" and k + 2 < s.n and low[k + 2] == "dozen":
            return Quantifier(0, "vague:few dozen", k + 3)  # "a few dozen students": some 24 to 48
        if tuple(low[k + 2:k + 4]) == ("or", "two") and s.w[k + 1].pos in ("NOUN", "PROPN"):
            return Quantifier(1, "range", k + 1, 2)  # "a student or two": one or two
        if nxt in ("few", "handful", "number", "lot"):
            after = k + 2
            if tuple(low[after:after + 2]) == ("or", "so"):
                after += 2  # "a handful or so of porters"
            if after < s.n and low[after] == "of":
                after += 1
            return Quantifier(0, f"vague:{nxt}", after)
        return None
    if low[k] == "several" and k + 1 < s.n and low[k + 1] == "dozen":
        return Quantifier(0, "vague:several dozen", k + 2)  # "several dozen fans"
    if low[k] in ("few", "several", "some", "many", "lots", "dozens", "various", "multiple", "numerous", "scores",
                  "hundreds", "loads", "heaps", "tons"):
        after = k + 1
        if after < s.n and low[after] == "of" and low[k] in ("lots", "dozens", "scores", "hundreds", "loads", "heaps",
                                                            "tons"):
            after += 1
        return Quantifier(0, f"vague:{low[k]}", after)
    return None


# Scale words a range of two numbers may share: "one or two dozen", "a dozen or two".
_RANGE_SCALES = {"dozen": 12, "hundred": 100}


def _number_quantifier(s: Sentence, num: tuple[int, int], approx: bool) -> Quantifier:
    low = s.low
    value, after = num
    if tuple(low[after:after + 2]) == ("or", "so"):
        return Quantifier(value, "approximate", after + 2)  # "fifteen or so women"
    if tuple(low[after:after + 2]) == ("or", "thereabouts"):
        return Quantifier(value, "approximate", after + 2)  # "forty or thereabouts"
    if after < s.n and low[after] == "odd":
        return Quantifier(value, "approximate", after + 1)  # "twenty-odd customers"
    if tuple(low[after:after + 2]) in (("-", "odd"), ("-", "some")):  # "sixty-some moviegoers": about sixty
        return Quantifier(value, "approximate", after + 2)
    if after + 1 < s.n and low[after] in ("to", "-", "or"):
        b = number_at(s, after + 1)
        scale = _RANGE_SCALES.get(low[b[1] - 1], 0) if b is not None else 0
        first_scale = _RANGE_SCALES.get(low[after - 1], 0) if low[after] == "or" else 0
        if b is not None and scale and value < b[0] // scale:
            value *= scale  # "one or two dozen", "two or three hundred": the scale is both numbers'
        elif b is not None and first_scale and value < b[0] * first_scale:
            return Quantifier(value, "range", b[1], b[0] * first_scale)  # "a dozen or two teens": 12 to 24
        if b is not None and b[0] > value:
            return Quantifier(value, "range", b[1], b[0])
    return Quantifier(value, "approximate" if approx else "exact", after)


def count_of(s: Sentence, q: Quantifier, key: str, default: tuple[int, int] = lx.BARE_PLURAL_RANGE) -> Count:
    """The Count a quantifier makes; vague and ranged ones take a seeded value inside their range."""
    if q.kind in ("exact", "strong"):
        return Count("exact", q.value, q.value, q.value)
    if q.kind == "approximate" and q.low is not None and q.high is not None:
        return Count("approximate", q.value, q.low, q.high)  # "2.5 people": 3, between 2 and 3
    if q.kind == "approximate":
        spread = max(1, round(q.value * lx.APPROXIMATE_SPREAD))
        return Count("approximate", q.value, max(1, q.value - spread), q.value + spread)
    if q.kind == "range":
        high = q.high or q.value
        kind = "approximate" if is_described_estimate(s, q.end) else "vague"  # "nine or ten weekend decorators"
        return Count(kind, s.choose(q.value, high, key), q.value, high)
    word = q.kind.split(":", 1)[1]
    low_, high_ = lx.VAGUE_RANGES.get(word) or VAGUE_QUANTITY_RANGES.get(word, default)
    return Count("vague", s.choose(low_, high_, key), low_, high_)


def duration_at(s: Sentence, k: int) -> tuple[float, int] | None:
    """(seconds, index after) of "five minutes", "a minute", "half an hour", "a few minutes", and a unit
    and a half or a quarter more ("an hour and a half", "two hours and a quarter")."""
    found = _duration_at(s, k)
    if found is None:
        return None
    seconds, end = found
    part = {"half": 0.5, "quarter": 0.25}.get(s.low[end + 2]) if end + 2 < s.n else None
    if part and s.low[end:end + 2] == ["and", "a"] and lemma(s.low[end - 1]) in lx.DURATION_UNITS:
        return seconds + lx.DURATION_UNITS[lemma(s.low[end - 1])] * part, end + 3
    return found


def _duration_at(s: Sentence, k: int) -> tuple[float, int] | None:
    low = s.low
    if k >= s.n:
        return None
    if low[k] == "half" and k + 2 < s.n and low[k + 1] in ("a", "an") and lemma(low[k + 2]) in lx.DURATION_UNITS:
        return lx.DURATION_UNITS[lemma(low[k + 2])] / 2, k + 3
    many = {"two": 2, "three": 3, "2": 2, "3": 3}.get(low[k])
    if many and k + 4 < s.n and low[k + 1] == "quarters" and low[k + 2] == "of" and low[k + 3] in ("a", "an") \
            and lemma(low[k + 4]) in lx.DURATION_UNITS:
        return lx.DURATION_UNITS[lemma(low[k + 4])] * many / 4, k + 5  # "three quarters of an hour"
    j = k + 1 if low[k] in ("a", "one") else k
    if (j + 3 < s.n and low[j] == "quarter" and low[j + 1] == "of" and low[j + 2] in ("a", "an")
            and lemma(low[j + 3]) in lx.DURATION_UNITS):
        return lx.DURATION_UNITS[lemma(low[j + 3])] / 4, j + 4  # "a quarter of an hour"
    q = quantifier(s, k)
    if q is not None and q.end < s.n and lemma(low[q.end]) in lx.DURATION_UNITS and not acronym_before_noun(s, q.end):
        unit = lx.DURATION_UNITS[lemma(low[q.end])]
        value = float(q.value)
        if q.kind.startswith("vague"):
            low_, high_ = lx.VAGUE_RANGES.get(q.kind.split(":")[1], (2, 4))
            value = (low_ + high_) / 2
        elif q.kind == "range":
            value = (q.value + (q.high or q.value)) / 2
        return value * unit, q.end + 1
    if low[k] in ("a", "an", "one") and k + 1 < s.n and lemma(low[k + 1]) in lx.DURATION_UNITS and \
            not acronym_before_noun(s, k + 1):
        return lx.DURATION_UNITS[lemma(low[k + 1])], k + 2
    if low[k] in ("the", "all") and k + 1 < s.n and low[k + 1] in lx.DAY_PERIODS and k > 0 and \
            s.verb(k - 1) == "spend":
        return lx.DAY_PERIODS[low[k + 1]], k + 2  # "spends the afternoon in the bar"
    if low[k] in ("a", "an") and k + 2 < s.n and low[k + 1] in ("whole", "full", "entire", "good") and \
            lemma(low[k + 2]) in lx.DURATION_UNITS:
        return lx.DURATION_UNITS[lemma(low[k + 2])], k + 3  # "for a whole hour", "an entire minute"
    return None
