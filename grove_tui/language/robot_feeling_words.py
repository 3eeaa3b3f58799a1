"""Words of people's reactions to the robot that the lexicon's own tables lack (round 25), kept here so
the lexicon stays short; the lexicon merges them into its tables.

- Feelings said as a state ("terrified of the robot", "intrigued by it", "spooked by the robot",
  "mesmerised by it", "furious with the robot"): the reaction the feeling leads to.
- A place right behind the robot ("tiptoe in the robot's wake", "pad along at its heels", "on the
  robot's tail"): whatever verb of moving goes there, it follows the robot.
- Keeping watch on the robot ("keeps an eye on the robot", "keeps tabs on it"): looking at it.
- Lengths ("within a few metres", "two yards from it", "a couple of paces"): never people.
"""

from __future__ import annotations

MORE_FEELINGS: dict[str, str] = {
    **dict.fromkeys("terrified petrified spooked alarmed unnerved uneasy anxious apprehensive jumpy intimidated "
                    "leery mistrustful distrustful panicked panicky timid".split(), "avoid"),
    **dict.fromkeys("intrigued enchanted captivated mesmerised mesmerized enthralled smitten agog inquisitive "
                    "nosy nosey beguiled charmed delighted thrilled excited".split(), "approach"),
    **dict.fromkeys("stunned dumbfounded gobsmacked flabbergasted bemused puzzled baffled perplexed bewildered "
                    "awestruck transfixed".split(), "look"),
    **dict.fromkeys("furious irate livid enraged incensed belligerent annoyed irritated".split(), "block"),
}
WAKE_PHRASES: dict[tuple[str, ...], str] = {
    (apostrophe, noun): "follow" for apostrophe in ("'s", "’s") for noun in ("wake", "heels", "tail")}
WATCHING_PHRASES: dict[tuple[str, ...], str] = {
    ("keep", "an", "eye", "on"): "look", ("keep", "a", "close", "eye", "on"): "look", ("keep", "tabs", "on"): "look", ("keep", "tab", "on"): "look",
    ("keep", "watch", "on"): "look", ("keep", "a", "wary", "eye", "on"): "look"}
DISTANCE_NOUNS = frozenset("metre meter yard foot feet inch mile pace centimetre centimeter kilometre kilometer "
                           "m cm km ft".split())
