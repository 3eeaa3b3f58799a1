"""A wait with a duration said in chat shorthand (round 30): "temp stuck @ copier 2 mins then off to
fridge", "guard @ cashpoint 2 mins then off to the west exit", "nurse at desk 10 min then to ward 3".
No article, no verb of waiting and no "for": the parser finds no person and no wait. The text is
written out as the sentence it stands for ("a temp waits at copier for 2 minutes, then goes to fridge"),
which the reader already reads: one person, a wait where they start, then the walk.
"""

from __future__ import annotations

import re

_STAYING = r"(?:stuck|waits?|waiting|sat|sits?|sitting|stands?|standing|stood|hangs?\s+about|hanging\s+about|" \
           r"hangs?\s+around|hanging\s+around|queues?|queuing|queueing|parked|camped)"
_AMOUNT = r"(\d+(?:\.\d+)?|a|an|one|two|three|four|five|six|seven|eight|nine|ten|fifteen|twenty|thirty|forty|half\s+an)"
_UNIT = r"(seconds?|secs?|minutes?|mins?|hours?|hrs?)"
_CHAT_WAIT = re.compile(
    r"^(?:(a|an|the|one|our|my|some)\s+)?([a-z]+(?:\s+[a-z]+)??)\s+(?:" + _STAYING + r"\s+)?at\s+((?:[\w'-]+\s+){0,3}?"
    r"[\w'-]+)\s+(?:for\s+)?" + _AMOUNT + r"\s+" + _UNIT + r"\s*,?\s*(?:and\s+)?then\s+(?:(?:is\s+)?off\s+|heads?\s+(?:off\s+)?|"
    r"goes\s+|walks?\s+|wanders?\s+(?:off\s+)?|nips?\s+|moves?\s+(?:on\s+)?)?(to|back\s+to|out\s+to)\s+", re.I)
_NOT_PEOPLE = frozenset("robot it bot droid they he she we i you there".split())


def as_chat_wait(text: str) -> str:
    """The text with a chat-shorthand wait written out; other text as it is."""
    m = _CHAT_WAIT.match(text)
    if m is None or m.group(1) is not None or m.group(2).split()[0].lower() in _NOT_PEOPLE:
        return text
    who = m.group(2)
    article = "an" if who[0].lower() in "aeiou" else "a"
    return (f"{article} {who} waits at {m.group(3)} for {m.group(4)} {m.group(5)}, then goes {m.group(6)} "
            + text[m.end():])
