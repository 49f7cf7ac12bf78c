"""The README stays a guide: at most `MAX_LINES` lines, its links and the docs' links land.

How each part works belongs in docs/MODEL.md and the figures in docs/BENCHMARKS.md; the README
links to them. Every relative link in the README and in the docs it links to must name a file
that exists and, with a `#fragment`, a heading of that file (GitHub's anchor for it: lower case,
punctuation dropped, spaces to hyphens, `-1`, `-2`, ... for repeats). MODEL.md's contents list
links every one of its numbered sections.
"""

import re

import pytest
from conftest import ROOT

README = ROOT / "README.md"
MODEL = ROOT / "docs" / "MODEL.md"
MAX_LINES = 330
DOCS = (README, MODEL, ROOT / "docs" / "BENCHMARKS.md", ROOT / "docs" / "GLOSSARY.md")

FENCE = re.compile(r"^```.*?^```", re.MULTILINE | re.DOTALL)
CODE = re.compile(r"`[^`\n]*`")
# [text](target) and ![alt](target); the target up to the first space or closing parenthesis
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
HEADING = re.compile(r"^#{1,6}\s+(.*?)\s*#*\s*$", re.MULTILINE)


def _slug(heading):
    """GitHub's anchor for a heading's text."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link: its text
    text = text.replace("`", "").replace("*", "")
    text = re.sub(r"[^\w\- ]", "", text.strip().lower())
    return text.replace(" ", "-")


def _anchors(path):
    anchors, seen = set(), {}
    for heading in HEADING.findall(FENCE.sub("", path.read_text(encoding="utf-8"))):
        slug = _slug(heading)
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        anchors.add(slug if count == 0 else f"{slug}-{count}")
    return anchors


def _links(path):
    """The relative link targets in `path`, outside code blocks and code spans."""
    text = CODE.sub("", FENCE.sub("", path.read_text(encoding="utf-8")))
    return [t for t in LINK.findall(text) if not re.match(r"[a-z][a-z0-9+.-]*:", t)]


def test_the_readme_is_at_most_max_lines_long():
    lines = README.read_text(encoding="utf-8").count("\n")
    assert lines <= MAX_LINES, (
        f"README.md has {lines} lines, over {MAX_LINES}: move how it works to docs/MODEL.md and "
        "figures to docs/BENCHMARKS.md, and link to them"
    )


def test_the_slug_is_githubs():
    assert _slug("16. Under the surface: the water between the eye and what it sees") == (
        "16-under-the-surface-the-water-between-the-eye-and-what-it-sees"
    )
    assert _slug("7. The `Water Surface` group at a glance") == "7-the-water-surface-group-at-a-glance"
    assert _slug("The sun's own highlight") == "the-suns-own-highlight"
    assert _slug("The shore scene (issue 41 point 5)") == "the-shore-scene-issue-41-point-5"


@pytest.mark.parametrize("doc", DOCS, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_every_relative_link_lands(doc):
    links = _links(doc)
    if doc == README:
        assert len(links) > 20  # the parse found the README's links
    broken = []
    for target in links:
        name, _, fragment = target.partition("#")
        path = (doc.parent / name).resolve() if name else doc
        if not path.exists():
            shown = path.relative_to(ROOT) if path.is_relative_to(ROOT) else path
            broken.append(f"{target}: no file {shown}")
        elif fragment and path.suffix == ".md" and fragment not in _anchors(path):
            broken.append(f"{target}: no heading with that anchor in {path.relative_to(ROOT)}")
    assert not broken, f"{doc.relative_to(ROOT)}:\n" + "\n".join(broken)


def test_models_contents_list_every_section():
    text = MODEL.read_text(encoding="utf-8")
    sections = [_slug(h) for h in re.findall(r"^## (\d+\..*)$", text, re.MULTILINE)]
    assert len(sections) >= 16
    contents = text.split("\n## ", 1)[0]
    listed = {target.lstrip("#") for target in _links_in(contents)}
    missing = [s for s in sections if s not in listed]
    assert not missing, f"MODEL.md's contents list leaves out: {missing}"


def _links_in(text):
    return LINK.findall(CODE.sub("", text))
