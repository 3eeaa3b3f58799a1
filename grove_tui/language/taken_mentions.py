"""Mentions the ordinary person phrases miss (round 33): a person moved, said with a pronoun ("Mr Ahmed's
son wheels him ..."), and a couple under one name ("Mr and Mrs Obi")."""

from __future__ import annotations

from grove_tui.language.mention import Mention
from grove_tui.language.model import Count
from grove_tui.language.owned_rides import own_ride, ride_owner_name
from grove_tui.language.moved_pronouns import moved_pronoun, owner_name
from grove_tui.language.sentence import Sentence
from grove_tui.language.titled_couples import couple_end


def taken_mention(s: Sentence, at: int) -> Mention | None:
    """The mention at `at` of a person a pronoun says is taken along, or of a couple named together; None."""
    if moved_pronoun(s, at):
        return Mention(at, at, owner_name(s, at), "person", Count("exact", 1, 1, 1))
    if (ride := own_ride(s, at)) is not None:  # "Grace's son steers her chair from ...": Grace, taken along
        return Mention(at, ride, ride_owner_name(s, at), "person", Count("exact", 1, 1, 1))
    for first in (at, at - 2):  # the couple's name, or its second title after "and" ("meets Mr and Mrs Lee")
        last = couple_end(s, first) if first >= 0 else None
        if last is not None:
            return Mention(first, last, s.span(first, last), "person", Count("exact", 2, 2, 2))
    return None
