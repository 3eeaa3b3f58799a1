"""Whether the verb a "by" hangs on is a participle, so what follows "by" is a passive's doer ("the
kitchen is occupied by a cleaner", "the lobby is crossed by two porters"). The small parser tags some
plain verbs a participle and calls their "by" an agent ("newlyweds hover by the concierge"): there
"by" says where they are, and the person-shaped place after it is no second group."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma


def participle(s: Sentence, i: int) -> bool:
    """Whether word i is written as a participle ("crossed", "seen", "led", "held") or a passive's
    auxiliary hangs on it ("is being set up by two assistants")."""
    low = s.low[i]
    return verb_lemma(low) != low or s.w[i].lemma != low or low.endswith(("ed", "en", "wn", "ld")) or \
        any(w.dep == "auxpass" and w.head == i for w in s.w)
