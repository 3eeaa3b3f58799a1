"""What a bare person typed as a chat item is doing, by any "-ing" form of a verb of what people do
(round 47): "3 relatives waitin in outpatients + porter hangin about @ imaging", "... and cleaner
loitering by the lifts". Chat drops the article and the final g ("hangin", "queuin", "sittin": the
text pass writes the g back); `bare_items.py` knew only a short list of "-ing" words, so a porter
"hanging about" was lost. Any "-ing" form of a verb the lexicon reads as an intent counts, and the
verbs of hanging about; an "-ing" word that names a room with the noun after it ("meeting room",
"waiting area") is no doing."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import verb_lemma

# Verbs of staying put said with a particle ("hang about", "hover round", "mill around").
_IDLING = frozenset({"hang", "hover", "mill", "pace", "potter", "faff"})
_ROOM_NOUNS = frozenset("room rooms area areas space spaces bay bays lane lanes point points station stations "
                        "desk desks hall halls centre center list lists zone zones lounge".split())


def doing_word(word: str, after: str | None) -> bool:
    """Whether an "-ing" word after a bare person says what they do ("hanging", "loitering")."""
    low = word.lower()
    if not low.endswith("ing") or len(low) < 6 or (after or "").lower() in _ROOM_NOUNS:
        return False
    verb = verb_lemma(low)
    return verb != low and (verb in lx.INTENT_VERBS or verb in _IDLING)
