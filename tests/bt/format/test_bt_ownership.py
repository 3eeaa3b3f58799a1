"""bt/format/ is the only owner of behavior-tree XML: no other module parses XML or writes tree markup.

Everything else (the runtime included) goes through bt/format/xml.py (hardened reader, one writer) and bt/format/document.py, so the
hardening (no DTDs, entities, XInclude; size, depth and SubTree limits) is on every path.
"""

from __future__ import annotations

from helpers.paths import REPO
import ast

ROOT = REPO
PACKAGE = ROOT / "grove_tui"
OWNER = PACKAGE / "bt" / "format"
XML_MODULES = ("xml", "lxml", "defusedxml")
TREE_MARKUP = ("<BehaviorTree", "<root", "<SubTree", "<TreeNodesModel")


def _is_xml_module(name: str) -> bool:
    return any(name == module or name.startswith(module + ".") for module in XML_MODULES)


def xml_ownership_offences(source: str, filename: str) -> list[str]:
    """Imports of an XML library, and string literals holding tree markup, in one module's source."""
    offences = []
    for node in ast.walk(ast.parse(source, filename=filename)):
        if isinstance(node, ast.Import):
            offences += [f"{filename}:{node.lineno} imports {a.name}" for a in node.names if _is_xml_module(a.name)]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0 and _is_xml_module(node.module):
            offences.append(f"{filename}:{node.lineno} imports from {node.module}")
        elif isinstance(node, ast.Constant) and isinstance(node.value, str):
            # importlib.import_module("lxml.etree") and the like; a bare "xml" is a word, not an import
            if _is_xml_module(node.value.strip()) and node.value.strip() != "xml":
                offences.append(f"{filename}:{node.lineno} names the module {node.value.strip()!r}")
            offences += [f"{filename}:{node.lineno} writes {markup!r}" for markup in TREE_MARKUP
                         if markup in node.value]
    return sorted(offences, key=lambda offence: int(offence.split(":")[1].split(" ")[0]))


def test_no_module_outside_bt_format_parses_xml_or_writes_tree_markup():
    offences = []
    for path in sorted(PACKAGE.rglob("*.py")):
        if OWNER in path.parents:
            continue
        offences += xml_ownership_offences(path.read_text(encoding="utf-8"), str(path.relative_to(ROOT)))
    assert not offences, "behavior-tree XML belongs to grove_tui/bt/format/:\n" + "\n".join(offences)


def test_the_search_finds_each_kind_of_offence():
    # the search itself must be able to fail: each line below is one offence
    source = '''
import xml.etree.ElementTree as ET
from lxml import etree
import defusedxml
from xml.sax.saxutils import quoteattr
engine = __import__("lxml.etree")
text = f'<root BTCPP_format="4" main_tree_to_execute="{tree_id}">'
other = "<BehaviorTree ID='a'>"
'''
    offences = xml_ownership_offences(source, "sample.py")
    assert [o.split(" ", 1)[0] for o in offences] == [f"sample.py:{n}" for n in (2, 3, 4, 5, 6, 7, 8)]
    assert xml_ownership_offences("print('a tree is written by bt/format/xml.py')\n", "ok.py") == []


def test_bt_is_where_the_xml_library_is_used():
    # the other half of ownership: the reader and writer live in bt/format/xml.py
    offences = xml_ownership_offences((OWNER / "xml.py").read_text(encoding="utf-8"), "bt/format/xml.py")
    assert any("imports from lxml" in o for o in offences)
