"""A word for the robot inside a place's name (twenty-third session): "a student walks from the lobby to
the robot lab" names the university's robotics lab by its alias, and says nothing of the robot; read
word by word, "to the robot" made the student approach the robot. Before the sentence is read, such a
name is said by another of the place's names that has no robot word in it ("the robotics lab"), so the
place is still found and the robot is not heard."""

from __future__ import annotations

import re
from functools import lru_cache

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceIndex


def _has_robot_word(words: tuple[str, ...]) -> bool:
    return any(w in lx.ROBOT_WORDS for w in words)


@lru_cache(maxsize=64)  # one index per world, built once: its renamings too, not on every reading
def _renamings(index: PlaceIndex) -> tuple[tuple[re.Pattern[str], str], ...]:
    """(the robot-worded name as typed, another name of the same place) for each place that has both,
    longest names first so that "robot lab annex" is renamed before "robot lab"."""
    out: list[tuple[int, re.Pattern[str], str]] = []
    for entry in index.entries:
        said = [tuple(phrase.lower().split()) for phrase in entry.said if phrase.strip()]
        plain = sorted((words for words in said if not _has_robot_word(words)), key=lambda words: len(words) < 2)
        robotic = [words for words in said if _has_robot_word(words) and len(words) > 1]
        if not plain or not robotic:
            continue
        other = " ".join(plain[0])
        for words in robotic:
            pattern = r"(?<![\w-])" + r"[\s-]+".join(re.escape(w) for w in words) + r"(?=s?\b)(?!['’]s)"
            out.append((len(words), re.compile(pattern, re.IGNORECASE), other))
    out.sort(key=lambda item: -item[0])
    return tuple((pattern, other) for _, pattern, other in out)


def without_robot_words_in_place_names(text: str, index: PlaceIndex) -> str:
    """The text with each place name that has a robot word in it said by another name of that place."""
    if not any(w in lx.ROBOT_WORDS for w in re.findall(r"[a-z]+", text.lower())):
        return text
    for pattern, other in _renamings(index):
        text = pattern.sub(other, text)
    return text
