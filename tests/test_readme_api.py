"""The README's Python API table says what `api.py` takes: each function it names exists, its
parameters are the real ones in their order, and each default it writes is the real default
(a signature written with defaults lists every parameter)."""

import ast
import inspect
import re

import harness

ROW = re.compile(r"`(\w+)\(([^`]*)\)`")


def _api_rows():
    text = (harness.ROOT / "README.md").read_text(encoding="utf-8")
    table = text.split("## Python API", 1)[1].split("\n## ", 1)[0]
    return [
        (name, args)
        for line in table.splitlines()
        if line.startswith("| `")
        for name, args in ROW.findall(line)
    ]


def test_the_readmes_api_signatures_are_api_pys(addon):
    api = harness.addon("api")
    rows = _api_rows()
    assert len(rows) > 20
    for name, written in rows:
        function = getattr(api, name, None)
        assert callable(function), f"README names api.{name}, which does not exist"
        real = inspect.signature(function).parameters
        parts = [p.strip() for p in written.split(",") if p.strip() and p.strip() not in ("...", "id")]
        names = [p.split("=")[0].lstrip("*") for p in parts]
        assert [n for n in real if n in names] == names, (name, names, list(real))
        for part in parts:
            if "=" in part:
                key, value = part.split("=", 1)
                assert real[key].default == ast.literal_eval(value), (name, key, value, real[key].default)
        if any("=" in part for part in parts):
            required = [n for n, p in real.items() if p.kind is not p.VAR_KEYWORD]
            assert names == required, f"README's {name}() leaves out {set(required) - set(names)}"
