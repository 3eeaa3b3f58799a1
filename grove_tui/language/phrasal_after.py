""""After" as the particle of a verb, not the start of a new clause (round 44): "to where staff look after
children who got separated from their parents", "the room where the nurses look after newborns". A
relative clause read up to a clause word stopped at "after" ("where staff look"), and its meaning
found the staff area instead of the lost-children point."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Verbs whose "after" is a particle: to look after, see after, tidy up after, run after someone.
_AFTER_VERBS = frozenset("look looks looked looking see sees seeing tend tends tending care cares caring run runs "
                         "ran running chase chases chased chasing tidy tidies tidying clean cleans cleaning up".split())


def particle_after(s: Sentence, k: int) -> bool:
    """Whether the "after" at k is the particle of the verb before it ("look after the children")."""
    return 0 < k < s.n - 1 and s.low[k] == "after" and s.low[k - 1] in _AFTER_VERBS and \
        s.w[k + 1].pos in ("DET", "NOUN", "PROPN", "PRON", "ADJ", "NUM")
