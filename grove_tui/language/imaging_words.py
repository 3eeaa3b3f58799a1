"""Imaging said in everyday words ("where they take pictures of your teeth", "where they photograph the
dog's bones", "to get a picture of his chest"): pictures of a part of the body are x-rays, the plain word
the worlds' names and descriptions use for that room (the x-ray room, radiology)."""

from __future__ import annotations

import re

_PARTS = (r"(?:teeth|tooth|jaws?|bones?|chest|lungs?|skull|spine|back|ribs?|hips?|knees?|legs?|arms?|wrists?|"
          r"ankles?|hands?|feet|foot|insides|mouth|paws?|skeleton|body)")
_OWNER = r"(?:(?:your|their|his|her|its|the|a|an|my|our|\w+'s|\w+s') )?(?:[\w'’]+ )?"
IMAGING: tuple[tuple[str, str], ...] = (
    (r"(?:take|takes|took|taking|get|gets|got|getting|have|has|had|having|do|does|did|doing|make|makes|made) "
     r"(?:a |some |the )?(?:pictures?|photos?|photographs?|images?|snaps?|shots?) of " + _OWNER + _PARTS,
     "take x-rays"),
    (r"(?:photograph|photographs|photographed|photographing|picture|pictures|pictured) " + _OWNER + _PARTS,
     "take x-rays"),
    (r"(?:see|sees|seeing|look|looks|looking) (?:at |inside |through )" + _OWNER + _PARTS, "take x-rays"),
)


def plain_imaging(said: str) -> str:
    """`said` (lower case) with its everyday words of imaging a body as x-rays."""
    for pattern, plain in IMAGING:
        said = re.sub(r"\b" + pattern + r"\b", plain, said)
    return said
