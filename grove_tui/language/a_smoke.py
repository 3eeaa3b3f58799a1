"""A smoke one goes out for or has is a cigarette, not a hazard (round 46): "steps out to the balcony
for a smoke", "nip outside for a quick smoke", "having a crafty smoke by the bins". The noun "smoke" is a
hazard that makes going out an evacuation; counted ("a smoke", "another smoke") after "for" or after a
verb of having, it is the act of smoking. Smoke as a hazard is not counted so ("smoke fills the hall",
"a cloud of smoke", "thick smoke in the kitchen")."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_COUNTED = frozenset("a an another one their his her my our your".split())
_ADJECTIVES = frozenset("quick crafty sneaky short cheeky last quiet brief little final swift".split())
_HAVING = frozenset("have grab enjoy take sneak need want fancy".split())


def a_smoke_had(s: Sentence, i: int) -> bool:
    """Whether the word "smoke" at i is a smoke had or gone out for (module doc)."""
    if s.low[i] != "smoke":
        return False
    j = i - 1
    while j >= 0 and s.low[j] in _ADJECTIVES:
        j -= 1
    if j < 1 or s.low[j] not in _COUNTED:
        return False
    before = s.low[j - 1]
    return before in ("for", "with") or verb_lemma(before) in _HAVING
