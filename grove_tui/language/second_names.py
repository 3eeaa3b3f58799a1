"""One person said twice, the second time set off by commas (round 23): "The pilot, Captain Ames,
strolls to gate A2", "Our receptionist, Mrs Patel, walks to the boardroom", "The duty manager, a tall
man called Pete, waits by gate A1". The words between the commas name the same one person again, so
they are no group of their own (a list goes on with "and": "the nurse, a porter and two visitors").
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.mention import Mention
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Words that give the second name a name of its own: "a tall man called Pete", "a porter named Sid".
_CALLED = frozenset({"called", "named", "known"})


def _one(m: Mention) -> bool:
    return m.relation is None and not m.whole_zone and m.collective is None and (
        m.count is None or (m.count.kind in ("exact", "implied") and m.count.value == 1))


def _second_name(s: Sentence, before: Mention, m: Mention) -> bool:
    """Whether m names `before` again between commas, with the verb of both after it."""
    if m.first < 2 or s.low[m.first - 1] != "," or before.last != m.first - 2 or not (_one(before) and _one(m)):
        return False
    if s.w[before.first].sentence != s.w[m.first].sentence or before.count is None and m.count is None:
        return False
    after = m.last + 1
    if after < s.n and s.low[after] in _CALLED:
        after += 2 if s.low[after] != "known" else 3  # "called Pete", "known as Pete"
    if after + 1 >= s.n or s.low[after] != ",":
        return False
    verb = after + 1
    while verb < s.n and s.w[verb].pos == "ADV":
        verb += 1  # "..., Captain Ames, slowly strolls"
    # the verb, or an "-s" word the lexicon knows as one, which the parser took for a noun in apposition
    return verb < s.n and (s.w[verb].pos in ("VERB", "AUX") or s.w[verb].tag in ("VBZ", "VBD") or (
        s.w[verb].tag == "NNS" and verb_lemma(s.low[verb]) != s.low[verb]))


def without_second_names(s: Sentence, mentions: Sequence[Mention]) -> list[Mention]:
    """The mentions but a second name of the one person before it (module doc)."""
    dropped = {k for k in range(1, len(mentions)) if _second_name(s, mentions[k - 1], mentions[k])}
    if not dropped or any(m.relation is not None for m in mentions):
        return list(mentions)
    return [m for k, m in enumerate(mentions) if k not in dropped]
