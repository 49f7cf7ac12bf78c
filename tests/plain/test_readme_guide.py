"""The README stays a guide: at most `MAX_LINES` lines, its links and the docs' links land.

How each part works belongs in docs/MODEL.md and the figures in docs/BENCHMARKS.md; the README
links to them. Every relative link in the README and in the docs it links to must name a file
that exists and, with a `#fragment`, a heading of that file (GitHub's anchor for it: lower case,
punctuation dropped, spaces to hyphens, `-1`, `-2`, ... for repeats). MODEL.md's contents list
links every one of its numbered sections.

MODEL.md and BENCHMARKS.md are references, not diaries (issue 59 point 4): each section says what
it is and gives the current figure with its command; how a figure got there is the git log's. So
they hold no "Version N of the group" history, and their prose reads in sentences of under
`MAX_MEAN_SENTENCE` words on average (tables, headings and code left out).
"""

import re

import pytest
from conftest import ROOT

README = ROOT / "README.md"
MODEL = ROOT / "docs" / "MODEL.md"
BENCHMARKS = ROOT / "docs" / "BENCHMARKS.md"
MAX_LINES = 330
DOCS = (README, MODEL, BENCHMARKS, ROOT / "docs" / "GLOSSARY.md")
REFERENCES = (MODEL, BENCHMARKS)
MAX_MEAN_SENTENCE = 30  # words

FENCE = re.compile(r"^```.*?^```", re.MULTILINE | re.DOTALL)
CODE = re.compile(r"`[^`\n]*`")
# [text](target) and ![alt](target); the target up to the first space or closing parenthesis
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
HEADING = re.compile(r"^#{1,6}\s+(.*?)\s*#*\s*$", re.MULTILINE)
# A version-by-version account: "Version 2 of the group", "until version 11", "History of this figure"
HISTORY = re.compile(r"\bversion\s+\d+\s+of\b|\buntil\s+version\s+\d+|\bhistory\s+of\s+this\b", re.IGNORECASE)
INDENTED_FENCE = re.compile(r"^ *```.*?^ *```[^\n]*$", re.MULTILINE | re.DOTALL)
LIST_ITEM = re.compile(r"\s*(?:[*-]|\d+\.)\s")
SENTENCE_END = re.compile(r"(?<=[.!?])[\"')\]]*\s+")


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


def _prose_blocks(text):
    """The paragraphs and list items of `text` (lists of lines), less code, tables and headings."""
    blocks, block = [], []
    for line in INDENTED_FENCE.sub("\n", text).split("\n") + [""]:
        stripped = line.strip()
        if not stripped or stripped.startswith(("|", "#")) or (LIST_ITEM.match(line) and block):
            if block:
                blocks.append(block)
            block = []
        if stripped and not stripped.startswith(("|", "#")):
            block.append(line)
    # an indented code block: every line indented four spaces (a nested list's lines are not all)
    return [b for b in blocks if not all(line.startswith("    ") for line in b)]


def _sentence_lengths(text):
    """Words per sentence in the prose of markdown `text`: a code span counts as one word, a link
    as its text, and a paragraph or list item ends a sentence."""
    lengths = []
    for block in _prose_blocks(text):
        joined = CODE.sub("X", " ".join(line.strip() for line in block))
        joined = LIST_ITEM.sub("", re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", joined), count=1)
        lengths += [len(s.split()) for s in SENTENCE_END.split(joined) if s.split()]
    return lengths


def test_sentences_are_counted_in_prose_only():
    text = (
        "# A heading of many words\n\n| a | table of | words |\n\n```\nsome code here\n```\n\n"
        "One two three. Four `a b c` [five](x.md)! (Six seven.) Eight\n\n* nine\n"
        "* ten eleven\n  twelve\n\n    an indented code line\n"
    )
    assert _sentence_lengths(text) == [3, 3, 2, 1, 1, 3]


@pytest.mark.parametrize("doc", REFERENCES, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_the_references_hold_no_version_history(doc):
    found = [m.group(0) for m in HISTORY.finditer(doc.read_text(encoding="utf-8"))]
    assert not found, (
        f"{doc.relative_to(ROOT)} tells its history ({found}): keep the current state and figure "
        "with its command; the versions before belong in the git log"
    )


@pytest.mark.parametrize("doc", REFERENCES, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_the_references_read_in_short_sentences(doc):
    lengths = _sentence_lengths(doc.read_text(encoding="utf-8"))
    assert len(lengths) > 100  # the parse found the prose
    mean = sum(lengths) / len(lengths)
    assert mean < MAX_MEAN_SENTENCE, (
        f"{doc.relative_to(ROOT)}'s sentences average {mean:.1f} words, over {MAX_MEAN_SENTENCE}: "
        "split them (the history they tell goes to the git log)"
    )
