"""People taken somewhere by someone, said in the passive (round 17): "a pupil is taken to the medical
room by the school nurse", "the visitors are ushered out by a steward". The reader knows the active
form ("the school nurse takes a pupil to the medical room": the taker walks, the taken follow), so
the clause is said again in the active before the sentence is read; the parse shows the passive
subject, the verb and the "by" phrase, whose order alone would give the taken the walk and leave
the taker waiting with nowhere to go.
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word
from grove_tui.language.tokens import third_person

# Words for the taker that name no person: "taken to the hall by bus", "carried by the crowd" is kept. A way
# out is the way they are taken, no taker ("are got out by the fire exit", "taken out by the side door").
_NOT_TAKERS = frozenset("bus coach car taxi train lift elevator escalator stairs hand ambulance van shuttle "
                        "wheelchair stretcher trolley road foot escape stairwell staircase route".split()) | lx.DOOR_WORDS


def _span(words: Sequence[Word], head: int) -> tuple[int, int]:
    """The first and last word of the phrase headed at `head` (its subtree)."""
    inside = {head}
    changed = True
    while changed:
        changed = False
        for w in words:
            if w.i not in inside and w.head in inside and w.head != w.i:
                inside.add(w.i)
                changed = True
    return min(inside), max(inside)


def to_active(text: str, words: Sequence[Word]) -> str | None:
    """The text with each passive of taking someone somewhere by a person said in the active ("X is
    taken to Y by Z" -> "Z takes X to Y"); None when there is none."""
    out = text
    # From the last so the character offsets of earlier clauses still hold.
    for verb in sorted((w for w in words if w.tag == "VBN" and w.lemma in lx.LEADING_VERBS), key=lambda w: -w.i):
        kids = [w for w in words if w.head == verb.i and w.i != verb.i]
        subject = next((w for w in kids if w.dep == "nsubjpass"), None)
        agent = next((w for w in kids if w.dep == "agent" and w.lower == "by"), None)
        if subject is None or agent is None or agent.i == len(words) - 1:
            continue
        taker = next((w for w in words if w.head == agent.i and w.dep == "pobj"), None)
        if taker is None or taker.pos not in ("NOUN", "PROPN") or taker.lemma in _NOT_TAKERS:
            continue
        first, last = _span(words, subject.i)
        taker_first, taker_last = _span(words, taker.i)
        # "by a nurse from the canteen to ...": the route hung on the taker is not the taker's
        taker_last = next((j - 1 for j in range(taker.i + 1, taker_last + 1) if words[j].lower in _ROUTE_WORDS),
                          taker_last)
        between = words[last + 1:verb.i]
        # only "is", "are being", "gets" between the taken and the verb; the "by" phrase after the route,
        # or right after the verb with the route after it ("is taken by a PCSO from X to Y")
        if not between or any(w.dep not in ("auxpass", "aux", "advmod", "neg") for w in between) or \
                taker_first != agent.i + 1 or any(w.sentence != verb.sentence for w in between):
            continue
        if agent.i == verb.i + 1 and not _route_follows(words, taker_last):
            continue
        singular = taker.tag in ("NN", "NNP") and not any(w.lower == "and" for w in words[taker_first:taker_last + 1])
        active = third_person(verb.lemma) if singular else verb.lemma
        taker_text = text[words[taker_first].start:words[taker_last].end]
        taken_text = text[words[first].start:words[last].end]
        route = text[verb.end:agent.start].rstrip() if agent.i > verb.i + 1 else ""
        if first == 0:  # the taker now opens the sentence; the taken's article is inside it
            taker_text = taker_text[:1].upper() + taker_text[1:]
            taken_text = taken_text[:1].lower() + taken_text[1:] if words[first].pos == "DET" else taken_text
        out = out[:words[first].start] + f"{taker_text} {active} {taken_text}{route}" + out[words[taker_last].end:]
    return None if out == text else out


_ROUTE_WORDS = frozenset("from to into out up down across through over round around back towards toward onto".split())


def _route_follows(words: Sequence[Word], taker_last: int) -> bool:
    """Whether the route is said right after the taker ("... by a PCSO from the desk to the room")."""
    nxt = taker_last + 1
    return nxt < len(words) and words[nxt].lower in _ROUTE_WORDS and words[nxt].sentence == words[taker_last].sentence
