"""The second item of a placing imperative said with a verb of its own ("Put a PCSO behind the front
counter and get a pair of officers waiting in IR1", "Put a porter in ward A and have two nurses
sitting at the pharmacy", "Station a guard at reception and stick one more by the lifts"): after a
sentence that opens with "Put" (placing verbs are written so by `placing_verbs.py`), "and" then
"get", "have", "leave", "keep", "stick", "post", "station" or "put" before a count or a determiner
only repeats the placing (unless a verb follows, "have a detective stroll over to ...": what they are
made to do), so the verb is dropped and both groups are read as "Put A ... and B ..."."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import verb_lemma

_NUMBER = "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha()), key=len, reverse=True))
_SECOND = re.compile(r"(\band\s+)(?:get|have|leave|keep|stick|post|station|put|plonk|plant|pop|bung|drop|seat|sit)\s+"
                     r"(?=(?:a|an|one|another|some|\d+|" + _NUMBER + r")\s)", re.IGNORECASE)
_PUT_START = re.compile(r"(?:^|[.!?;:]\s+)Put\s+")


def placing_lists(text: str) -> str:
    """The text with a repeated placing verb after "and" dropped in a "Put ..." sentence (module doc)."""
    out: list[str] = []
    last = 0
    for m in _SECOND.finditer(text):
        starts = [p.end() for p in _PUT_START.finditer(text, 0, m.start())]
        ends = [i for i in (text.rfind(c, 0, m.start()) for c in ".!?;") if i >= 0]
        if not starts or (ends and max(ends) > max(starts)):
            continue  # no "Put" opens this sentence
        item = re.split(r"[,.;!?]", text[m.end():], maxsplit=1)[0].lower().split()
        if any(verb_lemma(w) == w and (w in lx.INTENT_VERBS or w in lx.PEOPLE_GOING_VERBS) for w in item[1:]):
            continue  # "and have a detective stroll over to ...": what they are made to do, no placing
        if not _placed_item(item):
            continue  # "and have a porter wheel a bed out of ...": a verb and its object, no placing
        out.append(text[last:m.start()] + m.group(1))
        last = m.end()
    out.append(text[last:])
    return "".join(out)


_PLACED = frozenset("in at by on near behind beside inside outside next round around under over up down".split())
_COUNTED = frozenset("a an one another some pair trio couple of".split())


def _placed_item(item: list[str]) -> bool:
    """Whether an item is a short noun phrase, then a place's preposition or a word in "-ing"
    ("a pair of nurses waiting at ...", "two students in the ..."), not a verb with an object."""
    end = next((k for k, w in enumerate(item) if w in _PLACED or (w.endswith("ing") and len(w) > 4)), None)
    if end is None:
        return False
    noun = [w for w in item[:end] if w not in _COUNTED and not w.isdigit() and w not in lx.NUMBER_WORDS]
    return 1 <= len(noun) <= 2
