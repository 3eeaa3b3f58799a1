"""Places picked among several that fit ("leads them to the exit" in a building with four exits, "the
meeting room" among three): the report marks each such pick unsure and says which others fit.

The reader weighs the places a phrase fits and keeps the others as a field's alternatives; a pick it is
fairly sure of (a score of 0.6 up: "main_entrance is in entrance_lobby, named before") asked nothing, and
one the roi model settled (rois.refine_with_model) was made sure (1.0) with its alternatives dropped, so
"the robot leads them to the exit" read main_entrance with confidence 1.0 and the report said nothing. The
model's pick now keeps the places it chose among (`model_pick`), and the report lists every pick with
alternatives the reader's own question did not already ask about (`picked_questions`).
"""

from __future__ import annotations

from grove_tui.language.model import FieldConfidence, GroupReading, RobotReading

PLACE_FIELDS = ("start", "destination", "location", "via")
MODEL_PICK = 0.9  # a place the roi model chose among several: what it chose, though not what the words said


def model_pick(confidence: FieldConfidence, chosen: str, old: str) -> FieldConfidence:
    """The field's confidence once the roi model chose `chosen`: the others it chose among kept."""
    others = tuple(dict.fromkeys(a for a in (old, *confidence.alternatives) if a and a != chosen))
    return FieldConfidence(confidence.field, max(confidence.score, MODEL_PICK),
                           f"{confidence.reason}; the roi model chose {chosen}", others)


def _value(subject: GroupReading | RobotReading, field: str) -> str:
    value = getattr(subject, field, None)
    if isinstance(value, tuple):
        return ", ".join(str(v) for v in value)
    return str(value) if value else ""


def picked_questions(who: str, subject: GroupReading | RobotReading) -> tuple[str, ...]:
    """One line per place field picked among several that fit and not already asked as unsure."""
    out = []
    for c in subject.confidence:
        if c.field not in PLACE_FIELDS or c.unsure or not c.alternatives or c.score >= 1.0:
            continue
        value = _value(subject, c.field)
        if not value:
            continue
        out.append(f"'{who}' {c.field}: {value} was picked, but {', '.join(c.alternatives)} fit too "
                   f"(unsure, {c.score:.1f}: {c.reason})")
    return tuple(out)
