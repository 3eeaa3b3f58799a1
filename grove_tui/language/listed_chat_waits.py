"""Counted groups' stay with a duration in chat, said after a comma or of two groups at once (round 43):
"6 kiddies + 2 instructors waitin @ ski school desk, 10 mins then out thru chairlift door", "4 lads at the
bar, 20 mins then off to the exit". As for one counted group (counted_chat_waits.py), the text is written
out as the sentence it stands for ("6 kiddies and 2 instructors wait at ski school desk for 10 minutes,
then go out through chairlift door"): every group starts where they stay, stays the time said, then
walks on; "then out through X" is a walk out through X."""

from __future__ import annotations

import re

from grove_tui.language.chat_waits import _AMOUNT, _UNIT
from grove_tui.language.counted_chat_waits import _DOING

_COUNT = r"(?:\d+|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|a\s+couple\s+of|a\s+few|a\s+pair\s+of|1|one|a|an)"
_GROUP = r"(?:" + _COUNT + r"|the|his|her|their|our)\s+[a-z]+(?:\s+[a-z]+)??"
_CHAT_WAIT = re.compile(
    r"^(" + _COUNT + r"\s+[a-z]+(?:\s+[a-z]+)??(?:\s+and\s+" + _GROUP + r")?)\s+(?:(?:are\s+|is\s+)?" + _DOING
    + r"\s+)?(?:at|around|round|by|near|in)\s+((?:[\w'-]+\s+){0,3}?[\w'-]+)\s*(,)?\s*(?:for\s+)?" + _AMOUNT + r"\s+"
    + _UNIT + r"\s*(,)?\s*(?:and\s+)?then\s+(?:(?:are\s+|is\s+)?off\s+|heads?\s+(?:off\s+)?|go(?:es)?\s+|walks?\s+|"
    r"wanders?\s+(?:off\s+)?|nips?\s+|moves?\s+(?:on\s+)?)?(out\s+through|out\s+of|out\s+to|back\s+to|to|through)\s+",
    re.I)
_NOT_PEOPLE = frozenset("robot robots it bot bots droid they he she we i you there minutes mins".split())


def as_listed_chat_wait(text: str) -> str:
    """The text with counted groups' chat stay written out (module doc); other text as it is. Only a stay
    with a comma before its time or of two groups joined by "and" (one group without: counted_chat_waits.py)."""
    m = _CHAT_WAIT.match(text)
    if m is None:
        return text
    subject = m.group(1)
    heads = [part.split()[-1].lower() for part in re.split(r"\s+and\s+", subject)]
    if any(h in _NOT_PEOPLE for h in heads) or subject.split()[1].lower() in _NOT_PEOPLE:
        return text
    if " and " not in subject and not m.group(3):
        return text  # "a temp waits at X for 2 minutes, then goes to Y": written out already
    one = " and " not in subject and subject.split()[0].lower() in ("a", "an", "1", "one")
    return (f"{subject} {'waits' if one else 'wait'} at {m.group(2)} for {m.group(4)} {m.group(5)}, then go {m.group(7)} " + text[m.end():])
