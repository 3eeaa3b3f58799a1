"""How many a plural group is, said by a collective or a vague share of "them" set off by commas
(round 43): "toddlers in ski suits, a small gaggle of them, waddle after the robot", "worried
relatives, a whole crowd of them, wait outside the ward". The apposition has no number, so it was not
read as one (mentions.py takes only exact or approximate counts so) and it became a second group,
or a subset of the first. It only says how many the group before is: one group, with the
apposition's count; so too when said last ("shoppers queue at the tills, a whole crowd of them."). Only
"a/an [words] <collective or vague word> of them" after a comma and a group said with no number is read so; "ten nurses, two of them students, ..." is untouched."""

from __future__ import annotations

from grove_tui.language.mention import Mention
from grove_tui.language.sentence import Sentence

_OPENERS = frozenset(("a", "an", "quite"))


def apposed_collective(s: Sentence, before: Mention, m: Mention) -> bool:
    """Whether m is "a/an ... <collective> of them" between commas, right after the plural group
    `before` said with no number (module doc)."""
    if m.first < 2 or s.low[m.first - 1] != "," or s.low[m.first] not in _OPENERS or m.count is None:
        return False
    if before.count is None or before.count.kind not in ("vague", "implied") or before.whole_zone or \
            before.collective is not None or m.relation is not None and not m.relation.startswith("subset_of:"):
        return False
    for of in (m.last - 1, m.last + 1):
        if not (m.first < of and of + 1 < s.n and s.low[of] == "of" and s.low[of + 1] == "them"):
            continue
        if of + 2 >= s.n or s.low[of + 2] in (".", "!", ";"):
            return True  # "shoppers queue at the tills, a whole crowd of them.": how many, said last
        return s.low[of + 2] == "," and not any(s.w[x].pos in ("VERB", "AUX") or s.low[x] in (",", ";", ":")
                                                for x in range(before.last + 1, m.first - 1))
    return False
