"""Trades whose word is also their shop or practice (round 26): "drift towards the dentist", "pop into
the optician", "walk to the butcher": after a place preposition the word names the place the trade is
done in, so a world with no such place refuses it (language/place_kinds.py), though the same word
names a person elsewhere ("the dentist walks to the staff room")."""

from __future__ import annotations

TRADE_PLACES = frozenset("dentist optician optometrist butcher florist jeweller jeweler greengrocer fishmonger "
                         "bookie bookmaker cobbler tailor undertaker ironmonger chiropodist podiatrist "
                         "physiotherapist osteopath".split())
