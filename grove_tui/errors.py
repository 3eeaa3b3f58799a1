"""The root of every error the core raises on bad input; the UI and CLI show its message as is."""


class GroveError(Exception):
    """A problem with the user's input or environment, described well enough to act on."""
