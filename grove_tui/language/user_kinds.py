"""Words before a place's head that name the kind of people it is for (round 50): "the staff entrance",
"the visitors' car park", "the members' bar", "the crew room". Though they are person nouns, they say
what kind of place it is, not whose it is ("the nurses' post"), so they stay among the phrase's kind
words (place_meaning.py `noun_modifiers`) and must agree with the place: a mall without a staff entrance
refuses "the staff entrance" rather than read its main entrance hall."""

from __future__ import annotations

USER_KINDS = frozenset("staff visitor guest member public customer crew employee".split())
