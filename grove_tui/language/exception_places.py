"""Where the people excepted from everybody are said to be stays theirs: "Everybody except the two people
in the server room goes to the kitchen" sends everybody else to the kitchen from wherever they are; the
server room is where the two stay, not where everybody starts. The verb after the exception is the
everybody's (groups.py); the places said before that verb belong to the exception's own words."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.clauses import Clause


def split_at_the_verb(whole: Clause, excepted: Clause) -> tuple[Clause, Clause]:
    """The whole's clause (the verb after the exception, with the whole's places and those after the verb)
    and the exception's (no verb: only the places said inside its words, before the verb)."""
    verb = excepted.verb_index
    own = [p for p in excepted.places if verb is not None and p.index < verb]
    return replace(excepted, places=whole.places + [p for p in excepted.places if p not in own]), Clause(places=own)
