"""Someone whose turn ends, in a fronted time clause (round 44): "Once the warm-up comedian wraps up, Dana
Price comes out of her dressing room ...", "When the support band finishes their set, forty fans head to
the bar", "After the speaker is done, the delegates file out". The clause says when the scene happens; the
one who finishes is its moment, not one of its groups, when someone else is the subject after its comma
("..., he takes a bow" keeps him: the pronoun is his). The clause is left out before parsing, as a fronted
arrival is (awaited_arrivals.py)."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

_ENDING = (r"(?:wraps?\s+up|wrapped\s+up|finish(?:es|ed)?|(?:is|'s|has)\s+(?:done|finished|through)|ends|ended|"
           r"winds?\s+up|wound\s+up|signs?\s+off|signed\s+off|comes?\s+off(?:\s+stage)?|came\s+off(?:\s+stage)?|"
           r"takes?\s+(?:a|their|his|her)\s+bows?)")
_FRONTED = re.compile(
    r"(?:^|(?<=[.;!?])\s+)(?:[Oo]nce|[Ww]hen|[Aa]fter|[Aa]s\s+soon\s+as)\s+(?P<who>(?:the|a|an|our|their|his|her)\s+"
    r"[^,.;!?]{1,40}?)\s+" + _ENDING + r"(?:\s+(?:his|her|their|the|its)\s+[a-z-]+)?,\s+(?=(?P<next>[A-Za-z]+))")
_PRONOUNS = frozenset({"he", "she", "they", "it", "his", "her", "their", "him", "them"})
# Words for performers the people lexicon lacks: the turn on a stage.
_PERFORMERS = frozenset({"comedian", "comic", "speaker", "dj", "compere", "magician", "headliner", "soloist",
                         "preacher"})
# Gatherings that end ("When the chess club finishes, ...") are read by the rules of gatherings (events.py).
_GATHERINGS = lx.MEMBERS_NAME_COLLECTIVES | lx.MODIFYING_COLLECTIVES | frozenset(lx.IMPLIED_RANGES) | {"band", "act"}
_PERSON_ENDS = ("er", "or", "ist", "ian", "ant", "ent")


def a_performer(who: str) -> bool:
    """Whether the words name one who performs or works, not a gathering."""
    head = who.lower().replace("-", " ").split()[-1]
    if head in _GATHERINGS or lemma(head) in _GATHERINGS:
        return False
    return head in _PERFORMERS or lemma(head) in lx.PERSON_NOUNS or head in lx.PERSON_NOUNS or \
        (head.endswith(_PERSON_ENDS) and len(head) > 4)


def without_finished_acts(text: str) -> str:
    """The text without a fronted "Once <someone> wraps up," clause (module doc)."""
    return without_fronted(text, _FRONTED)


def without_fronted(text: str, fronted: re.Pattern[str]) -> str:
    """The text without each fronted clause `fronted` finds (groups `who` and `next`) whose subject is a
    performer and is not taken up again by a pronoun after the comma."""
    out: list[str] = []
    at = 0
    for m in fronted.finditer(text):
        if m.group("next").lower() in _PRONOUNS or not a_performer(m.group("who")):
            continue
        out.append(text[at:m.start()] + (" " if m.start() > 0 else ""))
        at = m.end()  # the people after it as written ("twelve staff leave ...")
    out.append(text[at:])
    return "".join(out)
