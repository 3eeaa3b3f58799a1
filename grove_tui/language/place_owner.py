"""Whose own room a possessive names, when the person is only a first name: "Little Tom runs to his
bedroom", "baby Ella naps in her room" are a child's, so the child's room is theirs (language/places.py
knows the rooms of each kind of person: "kids room", "child's bedroom")."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Words before a first name that make its bearer a child.
CHILD_WORDS = frozenset({"little", "baby", "wee", "kid", "toddler", "tiny", "young"})


def owner_at(s: Sentence, owner: str | None, at: int) -> str | None:
    """The kind of person who owns "his/her/their <room>" said at word `at`: a child when the nearest
    first name before it in its sentence follows "little", "baby", "kid"; else `owner` as read."""
    for x in range(at - 1, 0, -1):
        if s.w[x].sentence != s.w[at].sentence:
            break
        if s.w[x].text[:1].isupper() and s.w[x].pos == "PROPN":
            return "child" if s.low[x - 1] in CHILD_WORDS else owner
    return owner
