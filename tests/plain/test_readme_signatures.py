"""The README's Python API table gives every public function of `api.py` with its whole signature.

`api.py` imports bpy, which this session never loads, so it is not imported: its functions are
read from its source with `ast` and each made an `inspect.Signature`. The README's signatures
(each `` `name(...)` `` naming one of them, in its Python API table and anywhere else outside a
code block) are parsed the same way, as the parameters of a `def`, and the two compared as
`inspect.Signature`s: the parameters' names, order, kinds (`*`, `**`) and defaults must be the
same, so a parameter missing, renamed, moved or given another default fails. Every public
function of `api.py` (defined there, no leading underscore) must be in the table, and the calls
the README's Python examples make must bind to the real signatures.
"""

import ast
import inspect
import re

import pytest
from conftest import ROOT

README = ROOT / "README.md"
API = ROOT / "api.py"
# `name(...)` or `api.name(...)` in a Markdown code span
SPAN = re.compile(r"`(?:\w+\.)?([a-z_]\w*)\(([^`]*)\)`")
FENCE = re.compile(r"^```(\w*)\n(.*?)^```", re.MULTILINE | re.DOTALL)


class _Expression(str):
    """A default that is no literal, compared by its source text."""


def _value(node):
    try:
        return ast.literal_eval(node)
    except ValueError:
        return _Expression(ast.unparse(node))


def _signature(arguments):
    """The `inspect.Signature` of an `ast.arguments` (annotations left out)."""
    kind = inspect.Parameter
    positional = [(a, kind.POSITIONAL_ONLY) for a in arguments.posonlyargs]
    positional += [(a, kind.POSITIONAL_OR_KEYWORD) for a in arguments.args]
    defaults = [inspect.Parameter.empty] * (len(positional) - len(arguments.defaults))
    defaults += [_value(d) for d in arguments.defaults]
    parameters = [kind(a.arg, k, default=d) for (a, k), d in zip(positional, defaults)]
    if arguments.vararg is not None:
        parameters.append(kind(arguments.vararg.arg, kind.VAR_POSITIONAL))
    for a, d in zip(arguments.kwonlyargs, arguments.kw_defaults):
        parameters.append(kind(a.arg, kind.KEYWORD_ONLY, default=kind.empty if d is None else _value(d)))
    if arguments.kwarg is not None:
        parameters.append(kind(arguments.kwarg.arg, kind.VAR_KEYWORD))
    return inspect.Signature(parameters)


def _written(name, parameters):
    """The signature the README writes as `name(parameters)`."""
    try:
        tree = ast.parse(f"def {name}({parameters}): pass")
    except SyntaxError as error:
        raise AssertionError(f"README's `{name}({parameters})` is not a Python signature: {error}") from None
    return _signature(tree.body[0].args)


def _api():
    """{name: signature} of the public functions `api.py` defines."""
    tree = ast.parse(API.read_text(encoding="utf-8"))
    return {
        node.name: _signature(node.args)
        for node in tree.body
        if isinstance(node, ast.FunctionDef) and not node.name.startswith("_")
    }


def _readme():
    return README.read_text(encoding="utf-8")


def _prose(text):
    """The README without its fenced code blocks."""
    return FENCE.sub("", text)


def _api_table():
    """[(name, parameters)] of the signatures in the first column of the Python API table."""
    section = _prose(_readme()).split("\n## Python API\n", 1)[1].split("\n## ", 1)[0]
    rows = [line for line in section.splitlines() if line.startswith("| `")]
    return [span for row in rows for span in SPAN.findall(row.split(" | ")[0])]


def test_the_api_table_lists_every_public_function_of_api_py_once():
    api = _api()
    assert len(api) > 20  # the parse found api.py's functions
    names = [name for name, _parameters in _api_table()]
    assert sorted(set(names)) == sorted(names), (
        f"listed twice: {[n for n in set(names) if names.count(n) > 1]}"
    )
    assert not set(api) - set(names), (
        f"api.py's functions missing from the README: {sorted(set(api) - set(names))}"
    )
    assert not set(names) - set(api), f"the README lists what api.py lacks: {sorted(set(names) - set(api))}"


def test_every_signature_the_readme_writes_is_api_pys():
    api = _api()
    spans = [(n, p) for n, p in SPAN.findall(_prose(_readme())) if n in api]
    assert len(spans) >= len(api)
    wrong = [
        f"README: {name}{_written(name, parameters)}\n api.py: {name}{api[name]}"
        for name, parameters in spans
        if _written(name, parameters) != api[name]
    ]
    assert not wrong, "\n".join(wrong)


def test_the_readmes_examples_call_the_api_with_what_it_takes():
    api = _api()
    calls = []
    for language, code in FENCE.findall(_readme()):
        if language != "python":
            continue
        for node in ast.walk(ast.parse(code)):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr in api:
                calls.append(node)
    assert calls
    for call in calls:
        name = call.func.attr
        try:
            api[name].bind(*[None] * len(call.args), **{k.arg: None for k in call.keywords if k.arg})
        except TypeError as error:
            pytest.fail(f"README calls {ast.unparse(call)}, which {name}{api[name]} refuses: {error}")


@pytest.mark.parametrize(
    "change",
    [
        ("wake=True", ""),  # a parameter left out
        ("scene=None", "scenes=None"),  # renamed
        ("tilt_damping=0.0, scene=None", "scene=None, tilt_damping=0.0"),  # moved
        ("wake=True", "wake=False"),  # another default
        ("water=None", "water"),  # no default
    ],
)
def test_a_changed_signature_would_be_caught(change):
    """The comparison itself: float_on_water's row, changed each way, no longer matches."""
    written = dict(_api_table())["float_on_water"]
    assert _written("float_on_water", written) == _api()["float_on_water"]
    old, new = change
    assert old in written
    changed = written.replace(old, new).replace(", ,", ",").rstrip(", ")
    assert _written("float_on_water", changed) != _api()["float_on_water"]
