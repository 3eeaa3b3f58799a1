"""Who does what a place is described by: "the room where they decide on their verdict" is read as
"where the jury decide on their verdict" when the jury are the sentence's subject, and taken when it
reads a room of theirs (language/place_meaning.py keeps the pronoun's reading otherwise). A pronoun says
nothing of what the place is; the people it stands for often do (a jury's room, a class's classroom),
and the world's names and descriptions say them ("jury room", "Room where the jury deliberates").
Read for language/place_meaning.py."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Subject pronouns a relative clause may open with for the people of its sentence.
_PRONOUNS = frozenset("they he she".split())


def named_doers(s: Sentence, first: int, said: str) -> tuple[str, str]:
    """The clause `said` (its words from `first`) with its opening pronoun replaced by the subject noun
    of its sentence said before it ("they decide" -> "the jury decide"), and that noun's lemma; as it
    was, and "", when there is none."""
    words = said.split()
    if not words or words[0] not in _PRONOUNS:
        return said, ""
    at = first if s.low[first] in _PRONOUNS else first + 1 if first + 1 < s.n and s.low[first + 1] in _PRONOUNS else -1
    if at < 0:
        return said, ""
    sentence = s.w[at].sentence
    own = [x for x in range(at) if s.w[x].sentence == sentence]
    subject = next((x for x in own if s.w[x].dep in ("nsubj", "nsubjpass") and s.w[x].pos in ("NOUN", "PROPN")), None)
    if subject is None:
        # "The jury retire ...": the small model reads the verb as a noun and the subject as its compound;
        # the sentence's first noun, before any preposition, is still who does it
        first_noun = next((x for x in own if s.w[x].pos in ("NOUN", "PROPN") or s.w[x].pos == "ADP"), None)
        subject = first_noun if first_noun is not None and s.w[first_noun].dep == "compound" else None
    if subject is not None and s.low[subject] in ("robot", "bot"):
        return said, ""
    if subject is None:
        return said, ""
    return " ".join(["the", s.low[subject], *words[1:]]), s.lemma(subject)
