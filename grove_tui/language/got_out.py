"""An order to get people out (round 44): "Fuel leak in the workshop: get the 30-odd parents in the
viewing gallery out by the café street door", "Fire in the kitchen: move the twenty diners in the canteen
out through the fire exit", "Get everyone on platform 2 out via the footbridge". The people are the
order's object, so no subject names them and the parser makes the order's verb the only verb; read so,
they are found nowhere, or stay where they are. Said as their own clause ("the 30-odd parents in the
viewing gallery get out by the café street door"), they leave from where they are by the way said, an
evacuation when the prompt names a hazard, as any group that gets out. Only an object that names people
(a word for people, "everyone", "all of them") is read so: "get the bins out" is left alone."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

_ORDERS = r"(?:get|move|usher|hurry|shepherd|herd|clear|take|send|bring)"
_ORDER = re.compile(rf"(^|[.!?;:]\s+|\b(?:and|then|so)\s+)(?:please\s+)?({_ORDERS})\s+"
                    r"(?P<who>(?:the|all|all\s+the|every|everyone|everybody|those|these|our|any|\d+|[a-z]+-odd)\b"
                    r"[^,.;:!?]*?)\s+(?P<out>out|outside)\b(?!\s+of\s+the\s+way)", re.IGNORECASE)
_EVERYONE = frozenset({"everyone", "everybody", "all"})


def _names_people(who: str) -> bool:
    words = [w.strip("'’").lower() for w in who.replace("-", " ").split()]
    head = [w for w in words if w not in ("in", "on", "at", "by", "the", "of")]
    before = words[:words.index("in")] if "in" in words else words  # "the parents in the viewing gallery"
    for cut in ("on", "at", "by", "near"):
        before = before[:before.index(cut)] if cut in before else before
    return bool(head) and (any(w in _EVERYONE for w in before[:2]) or
                           any(lemma(w) in lx.PERSON_NOUNS or w in lx.PERSON_NOUNS for w in before))


def as_got_out(text: str) -> str:
    """The text with an order to get people out said as their own clause (module doc)."""
    def said(m: re.Match[str]) -> str:
        who = m.group("who")
        if not _names_people(who) or any(w.lower() in lx.ROBOT_WORDS for w in who.split()):
            return m.group(0)
        start = m.group(1)
        if not start.strip() or start.rstrip()[-1:] in ".!?":
            who = who[:1].upper() + who[1:]
        return f"{start}{who} get {m.group('out').lower()}"
    return _ORDER.sub(said, text)
