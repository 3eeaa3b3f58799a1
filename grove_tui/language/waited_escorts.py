"""Someone taken along after their taker's wait: "a porter waits at reception for five minutes, then
wheels a patient to x-ray", "hca hangs on 5 mins @ nurse stn then wheels pt down to xray", "a guide
waits in the foyer, then leads four visitors to the café". The one who waits stays where they are for
the time said, then takes the others to the place: the taker's wait ends in a walk from there to it,
and the taken follow them (as "a porter wheels a patient to x-ray" reads). A group led by a person
who only waits was left walking on its own, the taker never leaving.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.mention import Mention
from grove_tui.language.model import GroupReading
from grove_tui.language.people import People
from grove_tui.language.sentence import Sentence
from grove_tui.language.sequences import shared_subject
from grove_tui.language.tokens import verb_lemma


def _taker(s: Sentence, people: People, mentions: Sequence[Mention], k: int) -> bool:
    """Whether mention k is the object of a verb of taking along whose subject, shared across the
    joining words before it ("..., then wheels"), is the mention before it."""
    p = mentions[k].first - 1
    if k < 1 or p < 1 or verb_lemma(s.low[p]) not in lx.LEADING_VERBS:
        return False
    subject = shared_subject(s, people, p - 1)
    return subject is not None and mentions[k - 1].first <= subject <= mentions[k - 1].last


def with_escorts_after_a_wait(s: Sentence, people: People, mentions: Sequence[Mention],
                              groups: Sequence[GroupReading]) -> list[GroupReading]:
    """The groups (one per mention first, in order) with each group taken along after its taker's
    wait following the taker, and the taker going there after the wait (see the module doc)."""
    out = list(groups)
    for k in range(1, min(len(mentions), len(out))):
        leader, taken = out[k - 1], out[k]
        if leader.intent != "wait" or leader.destination is not None or leader.location is None or \
                taken.intent != "walk" or taken.destination is None or not _taker(s, people, mentions, k):
            continue
        out[k] = replace(taken, intent="follow", follows=leader.who, start=taken.start or leader.location)
        out[k - 1] = replace(leader, start=leader.start or leader.location, destination=taken.destination)
    return out
