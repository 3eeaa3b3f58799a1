"""What people did before the scene, said in a relative clause between them and their verb (issue 29):
"twenty kids who've sat through the safety film pile out of the video room", "the pupils who watched
the demo walk to the hall". The small parser reads the clause's object and the main verb as one noun
("the safety film pile") and the clause's verb ("sat") as theirs, so they wait at a place "through" names.
The clause says who they are, not what they do in the scene: it is left out before parsing when a verb
of going (or a phrasal verb of leaving) follows its object with a particle or a preposition after it.
A clause with a preposition of where they were ("who have waited in the lounge") is kept."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.leaving import LEAVING_PHRASES
from grove_tui.language.tokens import verb_lemma

_RELATIVE = re.compile(
    r"\s+who(?:'ve|’ve|\s+have|\s+had|'d|’d)?\s+(?:just\s+|already\s+|all\s+)?(?P<verb>[a-z]+)"
    r"(?:\s+(?:through|over|along\s+to|to))?\s+(?:the|a|an|their|his|her|this|that|some)"
    r"(?P<rest>(?:\s+[a-z][a-z-]*){2,6})")
_AFTER_GOING = lx.PLACE_PREPOSITIONS | {"out", "up", "off", "back", "away", "over", "inside", "outside", "in"}


def without_relative_pasts(text: str) -> str:
    """The text without a relative clause of what its people did, before their verb of going (module doc)."""
    out: list[str] = []
    at = 0
    for m in _RELATIVE.finditer(text):
        if verb_lemma(m.group("verb")) == m.group("verb"):
            continue  # no past verb: "who work here"
        words = m.group("rest").split()
        # the object's last word, then a verb of going and its particle: "the safety film | pile out"
        main = next((k for k in range(1, min(len(words) - 1, 5)) if _going(words[k], words[k + 1])), None)
        if main is None:
            continue
        out.append(text[at:m.start()])
        at = m.start("rest") + len(" ".join([""] + words[:main]))
    out.append(text[at:])
    return "".join(out)


def _going(word: str, after: str) -> bool:
    v = verb_lemma(word)
    if (v, after) in LEAVING_PHRASES:
        return True
    return lx.INTENT_VERBS.get(v) in ("walk", "wander", "evacuate") and after in _AFTER_GOING
