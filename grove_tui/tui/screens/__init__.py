"""The Textual app's screens: a thin shell over grove_tui."""
