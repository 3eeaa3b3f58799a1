"""A modifier joined by hyphens before a role word counts as one word (round 60): "Put a night-shift
replenisher in the freezer section", "Station a part-time steward by the gate". The parser hangs
"night" and the hyphen on "shift", not on the role word, so a walk back over the role's own
modifiers stopped at the hyphen and the placed role was never opened by its "a". The walk here takes
any word whose head lies inside the phrase so far, hyphens too, and counts hyphen-joined words as
one modifier."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_MODIFIER_DEPS = frozenset({"compound", "amod", "nmod"})


def modified_start(s: Sentence, i: int, floor: int) -> int:
    """The first word of noun i's modifiers, hyphen-joined ones included, not before `floor`."""
    first = i
    while first > floor:
        w = s.w[first - 1]
        if not first <= w.head <= i:
            break
        if w.tag != "HYPH" and w.dep not in _MODIFIER_DEPS:
            break
        first -= 1
    if first < i and s.w[first].tag == "HYPH":
        first += 1  # a hyphen never opens the phrase
    return first


def modifier_count(s: Sentence, first: int, i: int) -> int:
    """How many modifiers stand from `first` up to noun i, hyphen-joined words as one."""
    count = 0
    for k in range(first, i):
        if s.w[k].tag == "HYPH" or (k > first and s.w[k - 1].tag == "HYPH"):
            continue
        count += 1
    return count
