"""Verbs of leaving in everyday English the lexicon lacks (round 14): "leg it", "bail", "scarper",
"make a run for it", "clear off", "head for the exits". Each is a walk away from where the people
are; said with a hazard (`hazards.py`) or with urgency, the clause's evacuation cues make it an
evacuation, as for "leave" and "get out"."""

from __future__ import annotations

# One-word verbs of leaving (base forms): a walk.
LEAVING_VERBS = frozenset("bail scarper skedaddle scram bolt vamoose decamp depart".split())
# Phrasal verbs of leaving: (base form, words after it).
LEAVING_PHRASES: dict[tuple[str, ...], str] = {
    **{phrase: "walk" for phrase in (
        ("leg", "it"), ("clear", "off"), ("make", "tracks"), ("make", "off"), ("head", "off"), ("take", "off"),
        ("make", "a", "run", "for", "it"), ("make", "a", "break", "for", "it"), ("make", "a", "dash", "for", "it"),
        ("head", "for", "the", "exits"), ("head", "for", "the", "exit"), ("make", "for", "the", "exits"),
        ("make", "for", "the", "exit"), ("run", "for", "it"), ("run", "for", "the", "exits"),
        ("get", "out"), ("clear", "out"), ("pile", "out"), ("bail", "out"), ("file", "out"), ("stream", "out"),
        ("pour", "out"), ("spill", "out"), ("get", "away"))},
}
# Phrasal verbs of leaving that are an evacuation when the prompt names a hazard ("legs it", "bails").
HAZARD_EXIT_PHRASES: tuple[tuple[str, ...], ...] = (
    ("leg", "it"), ("clear", "off"), ("make", "tracks"), ("make", "off"), ("run", "for"), ("make", "a"),
    ("head", "for"), ("make", "for"), ("get", "away"), ("file", "out"), ("stream", "out"), ("spill", "out"))
