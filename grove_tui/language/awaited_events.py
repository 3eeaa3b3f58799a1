"""A time clause that ends a wait (round 27): "two students wait in the café until the Glasgow coach
comes", "a family sits at the gate till their flight is called", "shoppers wait by the entrance until
the doors open". What is waited for is a vehicle, a call or a thing that opens, not people: its
words ("coach" is also a trainer) are no group of the scene, when someone else is named.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from grove_tui.language.mention import Mention
from grove_tui.language.sentence import Sentence

# Things waited for that are no people, though some name people too ("coach", "crew"'s "shift").
AWAITED = frozenset("coach bus train flight ferry boat plane tram shuttle taxi cab lift elevator car minibus "
                    "number name turn doors door gates gate shutters appointment call boarding announcement "
                    "service show film match kickoff kick-off".split())
_UNTIL = frozenset({"until", "till", "til", "'til", "untill"})
# "till" as a word of time: after no determiner nor preposition, before a clause's subject or a time.
_TILL = re.compile(r"(?<![A-Za-z'])(?<!the )(?<!a )(?<!an )(?<!at )(?<!by )(?<!to )(?<!from )(?<!near )(?<!shop )"
                   r"(?<!main )(?<!each )(?<!every )(?<!behind )(?<!nearest )(?<!its )(?<!his )(?<!her )"
                   r"(?:till|'til|til)(?= (?:the|their|his|her|its|our|my|your|it|they|he|she|we|you|everyone|"
                   r"everybody|someone|closing|close|lunch|lunchtime|noon|midnight|then|late|\d))", re.IGNORECASE)
_STEPS = 5  # words from "until" to the awaited thing's noun


def with_until(text: str) -> str:
    """"till" as a word of time written "until", so it is never the shop's till: "waits by the door till
    the coach comes"; "queues at the till", "the main till" stay."""
    return _TILL.sub("until", text)


def _awaited(s: Sentence, m: Mention) -> bool:
    if s.lemma(m.last) not in AWAITED and s.low[m.last] not in AWAITED:
        return False
    for k in range(m.first - 1, max(-1, m.first - 1 - _STEPS), -1):
        if s.is_punct(k):
            return False
        if s.low[k] in _UNTIL:
            return True
    return False


def without_awaited_things(s: Sentence, mentions: Sequence[Mention]) -> list[Mention]:
    """The mentions but the things an "until" clause waits for, when someone else is named."""
    dropped = {k for k, m in enumerate(mentions) if m.relation is None and _awaited(s, m)}
    if not dropped or len(dropped) == len(mentions):
        return list(mentions)
    return [m for k, m in enumerate(mentions) if k not in dropped]
