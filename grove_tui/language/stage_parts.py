"""Parts of a stage said by the theatre's own words (round 48): "smoke drifts from the wings", "a
stagehand up in the flies", "the cast waits stage left". The wings, the flies and the apron are part of
the stage, not rooms a world must list: a world with a stage (a room or a fixture) and no such alias reads them as its stage
rather than refusing them. A world with no stage is left alone ("the east wing" of a hospital is no
stage part and stays whatever the world makes of it)."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceIndex, PlaceMatch

# Heads (as lemmas) that name a part of a stage, and two-word names of one.
_PARTS = frozenset("wing wings fly flies apron downstage upstage onstage offstage".split())
_PAIRS = frozenset({("stage", "left"), ("stage", "right"), ("fly", "tower"), ("fly", "gallery"),
                    ("fly", "floor"), ("prompt", "side"), ("prompt", "corner")})
# Words that make "wing" a wing of a building, never of a stage.
_COMPASS = frozenset("north south east west northern southern eastern western new old main left right "
                     "children's maternity surgical medical private".split())


def stage_part(index: PlaceIndex, lemmas: Sequence[str]) -> PlaceMatch | None:
    """The world's stage for a phrase naming a part of one, or None (module doc)."""
    if not lemmas:
        return None
    said = tuple(lemmas[-2:])
    if said not in _PAIRS:
        if lemmas[-1] not in _PARTS or any(w in _COMPASS for w in lemmas[:-1]):
            return None
    stage = index.match(("stage",))
    if stage is None or not stage.exact or "stage" not in stage.name.split("_"):
        return None
    return stage
