"""One person said by a name and where they work (round 28): "Sam from security walks to the gate",
"Bob from accounts pops into the kitchen". The reader took the workplace for a start it could not
place and the name for no person, and found a vague crowd; a workplace the world has no place for
only says who the named person is, so it is left out before the sentence is read: "Sam walks to the
gate", one person. A workplace the world has is kept, as where the person starts ("Anna from the
cafe walks ..."). Only a capitalised name no list knows, right before "from" and one to three words
of a workplace, then a verb said of one person ("dashes", "walked"), is read so."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.named_roles import _a_name
from grove_tui.language.tokens import verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceIndex

_FROM = re.compile(r"(?<![\w'’-])([A-Z][a-z]+)\s+from\s+(?:the\s+|our\s+|their\s+)?"
                   r"((?:[A-Za-z][\w&-]*\s+){0,2}?[A-Za-z][\w&-]*)\s+(?=([a-z]+)\b)")


def without_named_workplaces(text: str, index: PlaceIndex) -> str:
    """The text with "from <workplace>" after a name left out (see the module doc); a workplace the
    world has a place for is kept, as where the person starts ("Anna from the cafe walks ...")."""
    def cut(m: re.Match[str]) -> str:
        name, place, after = m.group(1), m.group(2), m.group(3)
        said_of_one = after.endswith(("s", "ed")) and not after.endswith("ss") and verb_lemma(after) != after
        if not (_a_name(name) and said_of_one) or name.lower() in lx.INTENT_VERBS or \
                any(w.lower() in lx.STOPWORDS or index.knows(w.lower()) for w in place.split()):
            return m.group(0)
        return f"{name} "
    return _FROM.sub(cut, text)
