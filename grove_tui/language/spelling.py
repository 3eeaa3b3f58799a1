"""Misspellings the reader puts right: place words against the world's own names, and words for
people against the lexicon's (both one edit away, never a real English word turned into another)."""

from __future__ import annotations

from collections.abc import Sequence
from functools import lru_cache

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word, dictionary_word, known_word
from grove_tui.language.places import PlaceIndex
from grove_tui.language.text import plain
from grove_tui.language.tokens import lemma, verb_lemma
from grove_tui.language.person_shapes import person_shaped
from grove_tui.language.place_kind_words import makes_a_kind
from grove_tui.language.short_place_swaps import swapped_short_word


@lru_cache(maxsize=2048)
def near_person_noun(word: str) -> str | None:
    """The person noun a word is one insertion, deletion, substitution or swap of two neighbours
    away from, in its singular or plural (Damerau-Levenshtein distance 1); None if none is."""
    forms = _person_forms()
    for n in (len(word) - 1, len(word), len(word) + 1):
        for form, noun in sorted(forms.get(n, {}).items()):
            if one_edit(word, form):
                return noun
    return None


@lru_cache(maxsize=1)
def _person_forms() -> dict[int, dict[str, str]]:
    """Length -> {written form: person noun}, for the typo check."""
    by_length: dict[int, dict[str, str]] = {}
    irregular = {"children": "child", "people": "person", "women": "woman", "men": "man"}
    for noun in lx.PERSON_NOUNS:
        plural = noun[:-1] + "ies" if noun.endswith("y") else noun + "s"
        for form in (noun, plural, noun + "es"):
            if len(form) >= 5:
                by_length.setdefault(len(form), {}).setdefault(form, noun)
    for form, noun in irregular.items():
        by_length.setdefault(len(form), {})[form] = noun
    return by_length


def one_edit(a: str, b: str) -> bool:
    """Whether a and b are one insertion, deletion, substitution or swap of neighbours apart."""
    if a == b:
        return False
    if len(a) == len(b):
        diff = [k for k in range(len(a)) if a[k] != b[k]]
        return len(diff) == 1 or (len(diff) == 2 and diff[1] == diff[0] + 1 and a[diff[0]] == b[diff[1]]
                                  and a[diff[1]] == b[diff[0]])
    if len(a) > len(b):
        a, b = b, a
    return any(b[:k] + b[k + 1:] == a for k in range(len(b)))


def correct_places(text: str, words: Sequence[Word], index: PlaceIndex,
                   skip: frozenset[int] = frozenset()) -> tuple[str, list[str]]:
    """The prompt with misspelt place words put right, and what was put right ("read 'kitchn' as
    'kitchen'"). Conservative, so a real word is never turned into a place: a word is corrected only
    when the world has no place word like it, it is no word for people and no verb the lexicon knows,
    and exactly one word of the world's place names is one edit away (an insertion, deletion,
    substitution or swap of neighbours), or, of several, exactly one completes a name with the word
    next to it ("intensive cair": care, not chair). Short words (3-4 letters) and real English words ("sever") are
    corrected only when the correction completes a name with the word next to them ("sever room" ->
    "server room"), never alone ("left" is not "lift"). Two words of a name run together are split
    ("livingroom" -> "living room"). The words at the indices in `skip` are left as written."""
    edits: list[tuple[int, int, str, str]] = []
    for k, w in enumerate(words):
        replacement = None if k in skip else _correction(words, k, index)  # skip: kept as written
        if replacement is None:
            continue
        if w.text[:1].isupper():
            replacement = replacement[:1].upper() + replacement[1:]
        edits.append((w.start, w.end, replacement, w.text))
    if not edits:
        return text, []
    out = text
    for start, end, replacement, _ in reversed(edits):
        out = out[:start] + replacement + out[end:]
    return out, [f"read '{original}' as '{replacement}'" for _, _, replacement, original in edits]


def correction_of(words: Sequence[Word], k: int, index: PlaceIndex) -> str | None:
    """What word k is corrected to, or None when it is left as written."""
    return _correction(words, k, index)


def _correction(words: Sequence[Word], k: int, index: PlaceIndex) -> str | None:
    low = plain(words[k].lower)
    if not low.isalpha() or len(low) < 2:
        return None
    base = lemma(low)
    if base in index.vocabulary or low in index.vocabulary or base in lx.PERSON_NOUNS or \
            low in lx.STOPWORDS or low in lx.NUMBER_WORDS or low in lx.ROBOT_WORDS or \
            low in lx.PLACE_MODIFIERS or low in lx.PLACE_PARTS or \
            verb_lemma(low) in lx.INTENT_VERBS or verb_lemma(low) in lx.ROBOT_VERBS:
        return None
    if person_shaped(words, k):
        return None  # "two posties carry sacks": a person the lexicon lacks, not "posts"
    if makes_a_kind(base, *_content_neighbours(words, k)):
        return None  # "the post office": a kind of place (a world may lack), not "poster office"
    person = near_person_noun(low)
    if person is not None and person not in index.vocabulary:
        return None  # "docters": a person, read by the people rule ("securty" is both: a place here)
    joined = index.joined_pairs.get(low)
    if joined is not None:
        return None if known_word(low) else " ".join(joined)
    short = _shortened(words, k, low, index)
    if short is not None:
        return short
    if len(low) < 3:
        return None
    swapped = swapped_short_word(low, *_content_neighbours(words, k), index)
    if swapped is not None:
        return swapped  # "the rehab gmy": gym
    as_written = {v for v in index.name_words if abs(len(v) - len(low)) <= 1 and one_edit(low, v)}
    as_plural = {v for v in index.name_words if base != low and abs(len(v) - len(base)) <= 1 and one_edit(base, v)}
    found = sorted(as_written | as_plural)
    before, after = _content_neighbours(words, k)
    if len(low) >= 4 and not known_word(low):
        # "intensive cair": two edits from "care", which completes a name with the word before; a word
        # one edit from another name word ("chair") is still no guess between them
        farther = sorted(v for v in index.name_words if abs(len(v) - len(low)) <= 2 and _edits(low, v) == 2
                         and ((before, v) in index.name_pairs or (v, after) in index.name_pairs))
        completing = [v for v in found if (before, v) in index.name_pairs or (v, after) in index.name_pairs]
        if len(farther) == 1 and not completing:
            return farther[0]
    if len(found) > 1:
        # "intensive cair": "care" and "chair" are both one edit away; only "care" completes a name
        found = [v for v in found if (before, v) in index.name_pairs or (v, after) in index.name_pairs]
    if len(found) != 1:
        return None  # nothing near, or two names equally near: no guess
    replacement = found[0]
    if replacement not in as_written:
        replacement += low[len(base):] if low.startswith(base) else "s"  # "machnes" -> "machines"
    completes = (before, found[0]) in index.name_pairs or (found[0], after) in index.name_pairs
    if (len(low) < 5 or known_word(low) or (base != low and known_word(base))) and not completes:
        # "Two loaders": the plural of a real word ("loader") a list lacks is no misspelt name word
        return None  # "ticket hal" is the ticket hall; "hal" alone is nothing
    return replacement


_VOWELS = frozenset("aeiou")
# Words before a shortened place word that show it starts a place phrase ("at recep", "the caf").
_PLACE_LEADS = frozenset("the a an at to in into on from by near past towards toward this that".split())


def shortens(short: str, word: str) -> bool:
    """Whether `short` is a chat shortening of `word`: its first letters ("plat" of platform, "recep"
    of reception, "caf" of cafe), or a contraction that keeps its first and last letters and drops
    the vowels ("rm" of room, "bldg" of building) or keeps its first three ("dept" of department)."""
    if len(word) <= len(short) or len(word) > 3 * len(short):
        return False
    if len(short) >= 3 and word.startswith(short):
        return True
    vowels = sum(ch in _VOWELS for ch in short)
    if short[0] != word[0] or short[-1] != word[-1] or len(word) < len(short) + 2 or \
            (vowels and not (vowels == 1 and len(short) >= 4 and word.startswith(short[:3]))):
        return False  # a word with a vowel is a contraction only when it keeps the start ("dept"; "big" is no "booking")
    rest = iter(word)
    return all(ch in rest for ch in short)


def _shortened(words: Sequence[Word], k: int, low: str, index: PlaceIndex) -> str | None:
    """The word of the world's place names a chat shortening stands for ("plat 1": platform, "the
    recep desk": reception, "rm 3": room), when exactly one of them fits and it completes a name with
    the word next to it, or the shortening is no dictionary word and starts a place phrase ("at recep")."""
    found = sorted(v for v in index.name_words if shortens(low, v))
    if not found or (k > 0 and words[k - 1].tag == "TO" and words[k].tag == "VB" and known_word(low)):  # "to pay in"
        return None
    before, after = _content_neighbours(words, k)
    completing = [v for v in found if (before, v) in index.name_pairs or (v, after) in index.name_pairs]
    if len(completing) == 1:
        return completing[0]
    if len(low) <= 2 or low in lx.TITLES:
        return None  # "dr" alone is a doctor, not a door
    lead = plain(words[k - 1].lower) if k > 0 else ""
    if len(found) == 1 and not completing and lead in _PLACE_LEADS and \
            (not dictionary_word(low) or _inflected(low, found[0])) and \
            (not known_word(low) or len(found[0]) <= 2 * len(low)):
        return found[0]  # a dictionary word alone ("the pub") is itself, not a name it starts ("public")
    return None


_ENDINGS = ("s", "es", "r", "rs", "er", "ers", "ing", "d", "ed")


def _inflected(word: str, name_word: str) -> bool:
    """Whether a name word is the word with an ending ("smoke" of "smokers'"), not a longer word it
    only starts ("pub" of "public")."""
    stem = word[:-1] if word.endswith("e") else word
    return name_word.startswith(stem) and name_word[len(stem):] in _ENDINGS + tuple("e" + e for e in _ENDINGS)


def _edits(a: str, b: str) -> int:
    """The Levenshtein distance between two words (insertions, deletions and substitutions)."""
    row = list(range(len(b) + 1))
    for i, ca in enumerate(a, 1):
        previous, row[0] = row[0], i
        for j, cb in enumerate(b, 1):
            previous, row[j] = row[j], min(row[j] + 1, row[j - 1] + 1, previous + (ca != cb))
    return row[-1]


def _content_neighbours(words: Sequence[Word], k: int) -> tuple[str, str]:
    """The lemmas of the nearest content words before and after word k ("chek-in hall": "hall")."""
    def near(indices: range) -> str:
        for j in indices:
            low = plain(words[j].lower)
            if low.isalnum() and low not in lx.STOPWORDS:
                return lemma(low)
            if low.isalnum() and low not in ("in", "of", "-"):
                return ""
        return ""
    return near(range(k - 1, max(-1, k - 3), -1)), near(range(k + 1, min(len(words), k + 3)))
