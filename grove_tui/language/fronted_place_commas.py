"""A place phrase fronted before its people with no comma (round 34): "By the check-in kiosks a toddler
gapes at the robot", "Near the vending machines a little girl stares at the robot". Without the comma
the parser runs the place into the person ("desks a toddler gapes": a crowd of gapes) and the one
person is lost. The comma a writer may leave out is put back between the place phrase and the people,
so the person is the subject of their verb as in "By the check-in kiosks, a toddler gapes ...". A
phrase of time ("By the time the robot ...") or one that already has its comma reads as before."""

from __future__ import annotations

import re

_PREPOSITIONS = (r"(?:(?:over|down|up|right|just|out|back)\s+)?(?:by|near|beside|next\s+to|close\s+to|outside|"
                 r"inside|behind|at|in|on|opposite|in\s+front\s+of|across\s+from|under|beneath|alongside|among|"
                 r"amongst|around|round|past|beyond|through)")
_PEOPLE_STARTS = (r"(?:a|an|one|the|some|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|"
                  r"a\s+couple\s+of|a\s+pair\s+of|a\s+few|several|[2-9]|[1-9]\d)")
_FRONTED = re.compile(rf"(?P<lead>(?:^|[.!?;]\s+))(?P<pp>{_PREPOSITIONS}\s+(?:the|a|an|their|his|her|our|its)\s+)"
                      rf"(?P<rest>[^,.;:!?()]+)", re.IGNORECASE)
_STARTS = re.compile(rf"\s(?={_PEOPLE_STARTS}\s+[a-z])", re.IGNORECASE)
_LINKS = frozenset("of to from with and or in on at by for into onto as than near".split())
_NOT_PLACES = frozenset("time moment end meantime meanwhile way morning afternoon evening night day week "
                        "minute minutes hour hours rush chaos confusion panic".split())
_NOT_PEOPLE = frozenset("robot robots bot droid machine".split())


def with_fronted_place_commas(text: str) -> str:
    """The text with a comma after a place phrase fronted before its people (module doc)."""
    def comma(m: re.Match[str]) -> str:
        rest = m.group("rest")
        for start in _STARTS.finditer(rest):
            place, people = rest[:start.start()], rest[start.end():]
            words = (m.group("pp") + place).lower().split()
            people_words = people.lower().split()
            if not place.strip() or words[-1] in _LINKS or len(words) > 12:
                continue
            if set(words) & _NOT_PLACES or set(people_words[:4]) & _NOT_PEOPLE or len(people_words) < 3:
                return m.group(0)
            return f"{m.group('lead')}{m.group('pp')}{place}, {people}"
        return m.group(0)
    return _FRONTED.sub(comma, text)
