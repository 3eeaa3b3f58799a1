"""A person named by the place they work at is at that place when nothing else says where (issue 29):
"the cloakroom attendant hangs up coats", "the bar staff chat", "a pharmacy assistant restocks shelves".
The nouns before a worker's noun that are exactly a place of the world (its whole name or an alias) say
where that worker is, for a group that stays (wait, queue, converse, wander) and has no place of its
own. A place word that is part of another kind of person ("coach company reps") is no workplace: only a
noun of work (attendant, staff, assistant, ...) takes its place so."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.model import GroupReading
from grove_tui.language.places import PlaceIndex
from grove_tui.language.tokens import lemma, phrase_lemmas

# Nouns of someone working at a place, which a place before them names ("the kitchen staff").
WORKER_NOUNS = frozenset(
    "attendant staff staffer assistant worker clerk employee crew team volunteer cashier keeper "
    "operator supervisor manager steward stewardess barista server waiter waitress porter".split())


def _workplace(index: PlaceIndex, group: GroupReading) -> str | None:
    words = [w.strip(".,;:!?()").lower() for w in group.who.split()]
    heads = [x for x, w in enumerate(words) if lemma(w) in WORKER_NOUNS or w in WORKER_NOUNS]
    if not heads:
        return None
    head = heads[-1]
    first = head
    while first > 0 and words[first - 1].isalpha() and words[first - 1] not in lx.DETERMINERS and \
            words[first - 1] not in lx.NUMBER_WORDS and lemma(words[first - 1]) not in lx.PERSON_NOUNS:
        first -= 1
    said = words[first:head]
    if not 1 <= len(said) <= 3:
        return None
    match = index.match(tuple(phrase_lemmas(said)))
    return match.name if match is not None and match.exact else None


def at_their_workplace(index: PlaceIndex, groups: tuple[GroupReading, ...]) -> tuple[GroupReading, ...]:
    """The groups, each worker named by a place and placed nowhere else now at that place."""
    out: list[GroupReading] = []
    for group in groups:
        if group.intent in lx.STATIONARY_INTENTS and not (group.start or group.destination or group.location or group.via):
            place = _workplace(index, group)
            group = replace(group, location=place) if place is not None else group
        out.append(group)
    return tuple(out)
