"""An evacuation cue word that is part of a place's name here (round 44): "jog from the kit room out to
the smoke house in the drill yard" names the training yard by its alias "drill yard", and no drill is
on; "the alarm panel", "the escape room" of a world that has them are places too. A cue read as a cue
made every group in the prompt evacuate."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import phrase_lemmas


def in_a_place_name(s: Sentence, i: int) -> bool:
    """Whether word i starts a whole name or alias of a place of the world with the words after it."""
    for n in (3, 2):
        said = phrase_lemmas(s.low[i:i + n])
        match = s.index.match(said) if len(said) == n else None
        entry = s.index.entry(match.name) if match is not None and match.exact else None
        if entry is not None and tuple(said) in entry.phrases:
            return True
    return False
