"""`tools/demo` leaves the checkout clean: the render scripts write their pictures to out/ and only
`demo_output.publish` copies them into docs/, and only when `tools/demo --docs` asked for it; the
demo's noise filter drops Blender's lines and keeps the scripts' own."""

import ast
import re
import shutil
import subprocess

import demo_output
import pytest
from conftest import ROOT

SCRIPTS = sorted((ROOT / "tools").glob("render_*.py"))


def _code_names(path):
    """The names, attributes and strings a script's code uses (its docstrings left out)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    docstrings = {
        id(node.body[0].value)
        for node in ast.walk(tree)
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.ClassDef))
        and node.body
        and isinstance(node.body[0], ast.Expr)
        and isinstance(node.body[0].value, ast.Constant)
    }
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            names.add(node.id)
        elif isinstance(node, ast.Attribute):
            names.add(node.attr)
        elif isinstance(node, ast.alias):
            names.add(node.name)
        elif isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in docstrings:
            names.add(node.value)
    return names


def test_the_render_scripts_write_docs_only_through_publish():
    assert {path.name for path in SCRIPTS} >= {
        "render_demo.py",
        "render_sea.py",
        "render_boat.py",
        "render_under.py",
        "render_ocean.py",
    }
    for path in SCRIPTS:
        names = _code_names(path)
        assert "shutil" not in names, f"{path.name} copies files itself (shutil)"
        # Any other way into docs/ would name it: DOCS, "docs", harness.ROOT / "docs".
        assert not {"DOCS", "docs", "docs/"} & names, f"{path.name} names docs/ itself"
        assert "publish" in names, f"{path.name} does not publish its pictures"


def test_publish_copies_to_docs_only_when_asked(tmp_path, monkeypatch, capsys):
    out, docs = tmp_path / "out", tmp_path / "docs"
    out.mkdir()
    picture = out / "demo.png"
    picture.write_bytes(b"\x89PNG not really")

    monkeypatch.delenv(demo_output.DOCS_ENV, raising=False)
    assert demo_output.publish(picture, docs_dir=docs) == [picture]
    monkeypatch.setenv(demo_output.DOCS_ENV, "0")
    assert demo_output.publish(picture, docs_dir=docs) == [picture]
    assert not docs.exists()
    assert capsys.readouterr().out == f"wrote {picture}\n" * 2

    monkeypatch.setenv(demo_output.DOCS_ENV, "1")
    assert demo_output.publish(picture, docs=False, docs_dir=docs) == [picture]  # the preview
    assert not docs.exists()
    assert demo_output.publish(picture, docs_dir=docs, note="in 3 s") == [picture, docs / "demo.png"]
    assert (docs / "demo.png").read_bytes() == picture.read_bytes()
    assert capsys.readouterr().out == f"wrote {picture}\nwrote {picture} and {docs / 'demo.png'} in 3 s\n"


def test_demo_asks_for_docs_only_with_its_option():
    demo = (ROOT / "tools" / "demo").read_text(encoding="utf-8")
    assert f"export {demo_output.DOCS_ENV}=0" in demo
    assert re.search(rf'"\$arg" = "--docs" \]; then\s+{demo_output.DOCS_ENV}=1', demo)


@pytest.mark.skipif(shutil.which("grep") is None, reason="needs grep")
def test_the_demo_filter_drops_blenders_lines_and_keeps_the_scripts():
    noise = re.search(r"^noise='(.*)'$", (ROOT / "tools" / "demo").read_text(encoding="utf-8"), re.M)
    blender = [  # as bpy 5.2.3 and 4.5.15 print them
        'STATUS Installed "water_surface"',
        "00:00.699  cycles           | WARNING CUEW initialization failed: Error opening the library",
        "Warning: CUEW initialization failed",
        "Info: Added 'Water' (Tropical Shallows, 128 m) with material 'Water'; set-up: ...",
        "EGL Error (0x3009): EGL_BAD_MATCH: Arguments are inconsistent (for example, ...).",
        "ALSA lib confmisc.c:855:(parse_card) cannot find card '0'",
        "Fra:1 Mem:236.05M (Peak 324.76M) | Time:00:14.42 | Rendering 1 / 4 samples",
        "Saved: '/tmp/water_surface_demo_6py3mpv6/main.png'",
        "00:12.442  render           | Saved: '/tmp/water_surface_demo_w8kmc0uq/main.png'",
        "Time: 00:17.26 (Saving: 00:00.00)",
        " Time: 00:03.41 (Saving: 00:00.01)",
        "",
        "   ",
    ]
    ours = [
        "rendering the demo with Blender 5.2.3 LTS (software EEVEE: a few minutes)",
        "Warning: Resolution raised to 513 so the waterline of what stands in the water is found",
        "[1/1] main view, 320 x 180 ... (3 s so far)",
        "[open_sea_15_3m] 15 m/s from 3 m up ...",
        "the shore took 12 s",
        "wrote /repo/out/demo_shore_preview.png (a preview: never copied to docs/)",
        "wrote /repo/out/ocean.png and /repo/docs/ocean.png in 95 s",
        "Traceback (most recent call last):",
        "done in 13 s",
    ]
    kept = subprocess.run(
        ["grep", "-v", "-E", noise.group(1)],
        input="\n".join(blender + ours) + "\n",
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    assert kept.splitlines() == ours
