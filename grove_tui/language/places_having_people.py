"""People said as what a place or a team has (round 69): "the academy has six trainees in induction", "the
ward has a dozen patients in the day room", "the sales team has six reps in the boardroom", "the hospital
has ten porters at the main entrance". The place or the team was read as the subject, the people as its
object; said as the people being there ("six trainees are in the academy", "six reps are in the
boardroom"), they are a group of that many where the sentence puts them: at the place said after them
when the world names it, else at the place that has them, what follows kept ("in induction", "on a break"
is what they are doing; "in the day room" a place the world may lack, which the reader refuses). A person who has people ("she has two kids
in the car", "Mum has ...") is left alone; so is a queue a place has (has_a_queue.py)."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceIndex
from grove_tui.language.queue_lengths import _APPROX, _NUMBER
from grove_tui.language.tokens import lemma, phrase_lemmas, words

_COUNT = r"(?:(?:" + _APPROX + r")\s+)?(?:" + _NUMBER + r"|a\s+dozen|half\s+a\s+dozen|a\s+handful\s+of|a\s+couple\s+of)"
_HAS = re.compile(
    r"(?P<lead>^|[.!?;:,]\s+|\b(?:and|while|whilst|meanwhile|Meanwhile|but)\s+)"
    r"(?!(?:[Mm]eanwhile|[Aa]nd|[Ww]hile|[Ww]hilst|[Bb]ut|[Tt]hen|[Ss]o)\b)(?P<owner>(?:[Tt]he\s+|[Oo]ur\s+)?[A-Za-z][\w'&-]*(?:\s+[A-Za-z0-9][\w'&-]*){0,3}?)\s+"
    r"(?:has|had|has\s+got|'s\s+got)\s+(?P<count>" + _COUNT + r")\s+(?P<who>(?:[A-Za-z-]+\s+){0,2}[A-Za-z-]+s)\s+"
    r"(?P<prep>in|at|on|by|inside|beside|near)\s+(?P<rest>[^,;.!?]+?)(?=\s*(?:[,;.!?]|\band\b|\bwhile\b|$))")
_PEOPLE_OWNERS = frozenset("she he it they we i you someone everyone nobody who".split())


def with_places_having_people(text: str, index: PlaceIndex) -> str:
    """The text with "<place or team> has N people in/at Y" said as the people being there (module doc)."""
    return _HAS.sub(lambda m: _said(m, index), text)


def _said(m: re.Match[str], index: PlaceIndex) -> str:
    owner_words = words(m.group("owner"))
    if not owner_words or owner_words[0] in _PEOPLE_OWNERS or owner_words[-1] in lx.KIN_NAMES:
        return m.group(0)
    head = lemma(owner_words[-1])
    if (head in lx.PERSON_NOUNS or owner_words[-1] in lx.PERSON_NOUNS) and head not in lx.IMPLIED_RANGES:
        return m.group(0)  # "the nurse has three patients in ward B": hers, said as they are
    owner_place = index.match(tuple(phrase_lemmas(owner_words))) is not None
    owner_team = head in lx.IMPLIED_RANGES or head in lx.BUILDING_WORDS
    if not owner_place and not owner_team:
        return m.group(0)  # "Mum has two kids in the car", "the nurse has three patients in ward B"
    who = m.group("who")
    if lemma(words(who)[-1]) not in lx.PERSON_NOUNS and not who.lower().endswith(("ees", "ers", "ists", "ants")):
        return m.group(0)  # "the café has two tables in the window": no people
    rest = m.group("rest")
    rest_words = words(rest)
    found = index.match(tuple(phrase_lemmas(rest_words))) if rest_words else None
    said_place = found is not None and found.exact  # not "the queue" for a "queue display"
    count = m.group("count")
    lead = m.group("lead")
    if lead.strip() in ("", ".", "!", "?"):
        count = count[0].upper() + count[1:]
    if said_place or not owner_place:
        return f"{lead}{count} {who} are {m.group('prep')} {rest}"
    owner = m.group("owner")
    owner = owner[0].lower() + owner[1:] if owner.startswith(("The ", "Our ")) else owner
    return f"{lead}{count} {who} are in {owner}, {m.group('prep')} {rest}"
