"""Settings the add-on changed and may put back, noted on the data-block they belong to.

One rule for every switch (mirror set-up, ray tracing, Physical Caustics, light linking):

* a setting is put back only when it still holds the value the add-on set: a change the
  user made since is theirs and stays;
* it is put back only when no other holder (another water whose switch is still on) needs
  it: each entry lists its holders, and the last one to let go puts the value back.

The ledger is JSON in an ID property (`LEDGER_KEY`) of the scene, object, light or material
whose setting changed, keyed by the setting's RNA path from that data-block, so it is saved
with the file, survives undo, and needs no Python at render time (nothing reads it then).
"""

import json

import bpy

LEDGER_KEY = "water_surface_ledger"
# On a water: the name its ledger holders carry ("mirror:<it>"), the name it had at its first
# claim, so a water renamed since still finds what it holds.
HOLDER_KEY = "water_surface_holder"
_COLLECTIONS = {"WORLD": "worlds", "OBJECT": "objects", "COLLECTION": "collections"}


def holder(kind, water, stamp=True):
    """The holder `water` claims settings as for `kind` ("mirror", "caustics"): "kind:<name>",
    the name the water had at its first claim (`stamp` notes it on the water then)."""
    key = water.get(HOLDER_KEY)
    if not isinstance(key, str):
        key = water.name
        if stamp and water.library is None:
            water[HOLDER_KEY] = key
    return f"{kind}:{key}"


def holder_object(holder_name):
    """The water a holder names (found by the name it noted, or, for holders written before the
    note existed, by its name), or None."""
    key = holder_name.partition(":")[2]
    noted = next((o for o in bpy.data.objects if o.get(HOLDER_KEY) == key), None)
    if noted is not None:
        return noted
    named = bpy.data.objects.get(key)
    return named if named is not None and named.get(HOLDER_KEY, key) == key else None


def _load(block):
    try:
        ledger = json.loads(block.get(LEDGER_KEY, "{}"))
    except (TypeError, ValueError):
        return {}
    return ledger if isinstance(ledger, dict) else {}


def _save(block, ledger):
    if ledger:
        block[LEDGER_KEY] = json.dumps(ledger)
    elif LEDGER_KEY in block:
        del block[LEDGER_KEY]


def _plain(value):
    """A JSON-able form of an RNA value (an ID by its type and name)."""
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, bpy.types.ID):
        return {"id": value.id_type, "name": value.name}
    try:
        return [_plain(v) for v in value]
    except TypeError:
        return str(value)


def _live(value):
    """The RNA value a plain one stands for (an ID looked up by name; None when it is gone)."""
    if isinstance(value, dict) and "id" in value:
        return getattr(bpy.data, _COLLECTIONS[value["id"]]).get(value["name"])
    return value


def _same(a, b):
    if isinstance(a, float) or isinstance(b, float):
        return isinstance(a, (int, float)) and isinstance(b, (int, float)) and abs(a - b) <= 1e-6
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    return a == b


def read(block, path):
    """The plain value of `block`'s setting at RNA `path`."""
    return _plain(block.path_resolve(path))


def _write(block, path, value):
    owner_path, _, attribute = path.rpartition(".")
    owner = block.path_resolve(owner_path) if owner_path else block
    setattr(owner, attribute, _live(value))


def _shown(value):
    if isinstance(value, dict) and "name" in value:
        return f"'{value['name']}'"
    return "none" if value is None else str(value)


def claim(block, path, value, holder, label, changes, at_least=False):
    """Sets `block`'s `path` to `value` for `holder` (with `at_least`, raises it to `value`), noting
    what it was; a setting that already holds the value is only noted as needed by `holder` when the
    add-on set it before. Appends what changed, in words, to `changes`."""
    ledger = _load(block)
    entry = ledger.get(path)
    current = read(block, path)
    wanted = max(current, value) if at_least else value
    if entry is not None and not _same(current, entry["set"]):
        entry = None  # changed by the user since the add-on set it: theirs now
    if entry is None:
        ledger.pop(path, None)
        if _same(current, wanted):
            _save(block, ledger)
            return
        entry = {"before": current, "set": wanted, "holders": []}
        _write(block, path, wanted)
        changes.append(f"{label}: {_shown(current)} -> {_shown(wanted)}")
    if holder not in entry["holders"]:
        entry["holders"].append(holder)
    ledger[path] = entry
    _save(block, ledger)


def release(block, path, holder, label, changes, alive=None):
    """`holder` no longer needs `block`'s `path`: when no other holder does (`alive(name)` says
    whether one still holds; default: all do), the value the add-on found is put back, unless
    the setting was changed since. Appends what changed, in words, to `changes`."""
    if block is None:
        return
    ledger = _load(block)
    entry = ledger.get(path)
    if entry is None:
        return
    others = [h for h in entry["holders"] if h != holder and (alive is None or alive(h))]
    if others:
        entry["holders"] = others
        _save(block, ledger)
        return
    del ledger[path]
    _save(block, ledger)
    current = read(block, path)
    if not _same(current, entry["set"]):
        changes.append(f"{label} left at {_shown(current)} (changed since)")
        return
    _write(block, path, entry["before"])
    changes.append(f"{label}: {_shown(current)} -> {_shown(entry['before'])}")


def held_paths(block, holder):
    """The paths of `block`'s ledger that `holder` holds."""
    return [path for path, entry in _load(block).items() if holder in entry.get("holders", ())]


def holders(block, path):
    entry = _load(block).get(path)
    return list(entry["holders"]) if entry else []


def prune(block, alive):
    """Forgets the holders `alive(name)` says are gone, and the entries no one holds any more;
    the settings keep their values (nothing is put back). Returns the paths forgotten."""
    ledger = _load(block)
    forgotten = []
    for path, entry in list(ledger.items()):
        entry["holders"] = [h for h in entry.get("holders", ()) if alive(h)]
        if not entry["holders"]:
            del ledger[path]
            forgotten.append(path)
    if forgotten or LEDGER_KEY in block:
        _save(block, ledger)
    return forgotten
