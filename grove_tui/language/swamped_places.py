"""A place crowded by people said in the passive, with where they come from ("the book shop is swamped by
a coachload of pensioners drifting over from the eating area", "the bar gets mobbed by fans pouring in from
the stands"): the place is where the people go, not where they are. The place comes first as the passive's
subject, and the people after "by" move in a participle clause ("-ing") that says a route; the clause is
said again in the active with the place as its destination: "a coachload of pensioners drifts over from
the eating area to the book shop". Read before the rest (language/reading.py), as passive_escort is."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.parser import Word
from grove_tui.language.passive_escort import _ROUTE_WORDS, _span
from grove_tui.language.tokens import third_person

_CROWDING = frozenset("swamp mob invade overrun flood besiege throng crowd pack fill overwhelm inundate "
                      "descend mob jam".split())
_COUNTED = frozenset("two three four five six seven eight nine ten some dozens hundreds scores".split())
_ENDS = frozenset({",", ".", ";", "and", "while", "as", "but", "then", "!", "?"})
# At most this many words between "by" and the participle ("by a coachload of noisy pensioners").
_PEOPLE_WORDS = 7


def crowded_places_to_active(text: str, words: Sequence[Word]) -> str | None:
    """The text with each crowded place's passive said as the people going there (module doc); None
    when there is none."""
    for verb in words:
        if verb.tag != "VBN" or verb.lemma not in _CROWDING or verb.i + 2 >= len(words) or \
                words[verb.i + 1].lower != "by":
            continue
        subject = next((w for w in words if w.head == verb.i and w.dep == "nsubjpass"), None)
        if subject is None:
            continue
        first, last = _span(words, subject.i)
        between = words[last + 1:verb.i]
        if not between or any(w.dep not in ("auxpass", "aux", "advmod", "neg") for w in between):
            continue
        by = verb.i + 1
        moving = next((w for w in words[by + 2:by + 2 + _PEOPLE_WORDS] if w.tag == "VBG"), None)
        if moving is None or any(w.lower in _ENDS for w in words[by + 1:moving.i]) or moving.i + 1 >= len(words):
            continue
        end = next((w.i for w in words[moving.i + 1:] if w.lower in _ENDS or w.sentence != moving.sentence), len(words))
        route = [w.lower for w in words[moving.i + 1:end]]
        if "from" not in route or not set(route) & _ROUTE_WORDS:
            continue  # "swamped by fans wanting autographs": no route, no going
        people = words[by + 1:moving.i]
        plural = people[-1].tag in ("NNS", "NNPS") and not any(w.lower == "of" for w in people) or \
            people[0].lower in _COUNTED
        finite = moving.lemma if plural else third_person(moving.lemma)
        place = text[words[first].start:words[last].end]
        if first == 0 and words[first].pos == "DET":
            place = place[:1].lower() + place[1:]
        people_text = text[people[0].start:people[-1].end]
        if first == 0:
            people_text = people_text[:1].upper() + people_text[1:]
        rest = text[moving.end:words[end - 1].end]
        said = f"{people_text} {finite}{rest} to {place}"
        return text[:words[first].start] + said + text[words[end - 1].end:]
    return None
