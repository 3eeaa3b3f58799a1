"""A fronted stay said with how the people were before where (issue 29): "After five minutes alone on
the bench, ...", "After an hour together in the lounge, ...", "After ten minutes alone sat by the
window, ...". A word of being on one's own or in company between the length and the place does not
change what the length is: a stay at that place. `stay_first` reads past it as if it were not said."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Words of how the people were during the stay, said between the length and the place.
_MANNER = frozenset({"alone", "together", "unattended", "unaccompanied", "undisturbed"})


def past_manner(s: Sentence, k: int) -> int:
    """The index after a word of manner at k ("alone", "together"); k itself when none is there."""
    return k + 1 if k + 1 < s.n and s.low[k] in _MANNER else k
