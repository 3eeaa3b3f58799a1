"""A counted group's stay with a duration said in chat shorthand, with what they do there (round 32):
"3 ppl lookin at cacti 2 mins then off to tills", "2 teens @ fountain 5 mins then off to food court",
"4 lads browsing the mags 10 mins then to the tills". As with one person's chat wait (chat_waits.py), the
text is written out as the sentence it stands for ("3 people wait at cacti for 2 minutes, then go to
tills"): the group starts where they stay, stays the time said, then walks on."""

from __future__ import annotations

import re

from grove_tui.language.chat_waits import _AMOUNT, _STAYING, _UNIT

_DOING = (r"(?:looking|lookin|browsing|browsin|staring|gazing|chatting|chattin|nattering|hanging\s+out|"
          r"milling\s+about|milling\s+around|gathered|huddled|crowded|" + _STAYING[3:-1] + r")")
_COUNT = r"(\d+|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|a\s+couple\s+of|a\s+few|a\s+pair\s+of)"
_CHAT_WAIT = re.compile(
    r"^" + _COUNT + r"\s+([a-z]+(?:\s+[a-z]+)??)\s+(?:" + _DOING + r"\s+)?(?:at|around|round|by|near)?\s*"
    r"((?:[\w'-]+\s+){0,3}?[\w'-]+)\s+(?:for\s+)?" + _AMOUNT + r"\s+" + _UNIT + r"\s*,?\s*(?:and\s+)?then\s+"
    r"(?:(?:are\s+|is\s+)?off\s+|heads?\s+(?:off\s+)?|go(?:es)?\s+|walks?\s+|wanders?\s+(?:off\s+)?|nips?\s+|"
    r"moves?\s+(?:on\s+)?)?(to|back\s+to|out\s+to)\s+", re.I)
_NOT_PEOPLE = frozenset("robot robots it bot bots droid they he she we i you there minutes mins".split())


def as_counted_chat_wait(text: str) -> str:
    """The text with a counted group's chat-shorthand stay written out; other text as it is."""
    m = _CHAT_WAIT.match(text)
    if m is None or m.group(2).split()[0].lower() in _NOT_PEOPLE:
        return text
    return (f"{m.group(1)} {m.group(2)} wait at {m.group(3)} for {m.group(4)} {m.group(5)}, then go {m.group(6)} "
            + text[m.end():])
