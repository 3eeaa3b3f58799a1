"""Mentions the ordinary person phrases miss (round 33): a person moved, said with a pronoun ("Mr Ahmed's
son wheels him ..."), a couple under one name ("Mr and Mrs Obi"), and someone's own person taken along
("pushes the bride's nan in her wheelchair": language/possessed_people.py)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.mention import Mention
from grove_tui.language.model import Count
from grove_tui.language.owned_rides import own_ride, ride_owner_name
from grove_tui.language.possessed_people import possessed_head
from grove_tui.language.moved_pronouns import moved_pronoun, owner_name
from grove_tui.language.sentence import Sentence
from grove_tui.language.titled_couples import couple_end

if TYPE_CHECKING:
    from grove_tui.language.objects import PeopleObjects


def taken_mention(s: Sentence, at: int, objects: PeopleObjects) -> Mention | None:
    """The mention at `at` of a person a pronoun says is taken along, of a couple named together, or of
    someone's own person taken along; None."""
    if moved_pronoun(s, at):
        return Mention(at, at, owner_name(s, at), "person", Count("exact", 1, 1, 1))
    if (ride := own_ride(s, at)) is not None:  # "Grace's son steers her chair from ...": Grace, taken along
        return Mention(at, ride, ride_owner_name(s, at), "person", Count("exact", 1, 1, 1))
    for first in (at, at - 2):  # the couple's name, or its second title after "and" ("meets Mr and Mrs Lee")
        last = couple_end(s, first) if first >= 0 else None
        if last is not None:
            return Mention(first, last, s.span(first, last), "person", Count("exact", 2, 2, 2))
    start = s.skip(at, lx.DETERMINERS | lx.NP_MODIFIERS)
    head = possessed_head(s, objects.people, start) if start < s.n and objects.led_by(at) else None
    if head is None:
        return None
    label = objects.people.label(head)
    plural = s.lemma(head) != s.low[head]
    return Mention(at, head, s.span(at, head), label,
                   Count("vague", s.choose(2, 3, f"{at}:possessed"), 2, 3) if plural else Count("exact", 1, 1, 1))
