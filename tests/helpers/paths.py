"""Where the repository and the test data are, whatever folder a test sits in."""

from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
TEST_DATA = REPO / "tests" / "data"
