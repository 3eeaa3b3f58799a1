"""Talk said by an idiom the small parser does not know as a verb (round 29): "a couple of orderlies
chinwag by the lifts", "two porters are chewing the fat in the cafe", "a pair of cleaners jaw by the
lockers". Read as nouns ("orderlies chinwag"), the people are lost; written as "chat" before the
prompt is parsed, they converse where they are. "Have a chinwag" is left to the lexicon's "have a
chat"."""

from __future__ import annotations

import re

_FORMS = {"": "chat", "s": "chats", "ging": "chatting", "ged": "chatted", "ing": "chatting", "ed": "chatted"}
# "chinwag", "chin-wag"; "chew the fat", "chew the rag"; "gab", "gabbing".
_IDIOM = re.compile(r"\b(?:chin-?wag(?P<a>s|ging|ged)?|chew(?P<b>s|ing|ed)? the (?:fat|rag)"
                    r"|gab(?P<c>s|bing|bed)?)\b", re.IGNORECASE)
_HAVE_A = re.compile(r"\b(a|the) chin-?wag\b", re.IGNORECASE)


def _form(m: re.Match[str]) -> str:
    tail = m.group("a") or m.group("b") or m.group("c") or ""
    tail = {"bing": "ing", "bed": "ed"}.get(tail, tail)
    return _FORMS[tail]


def with_talk_idioms(text: str) -> str:
    """The text with an idiom of talk written as "chat" in the same form (module doc)."""
    text = _HAVE_A.sub(lambda m: f"{m.group(1)} chat", text)
    return _IDIOM.sub(_form, text)
