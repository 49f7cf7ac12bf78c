"""Writes every node group the add-on defines as canonical JSON, so two versions of the
descriptions can be compared group by group: a refactoring of them must build the same trees.

Run: `~/.cache/water_surface/venv-bpy-5.2.3/bin/python tools/group_dump.py OUT.json [--root DIR]`.
`--root` (default: this repository) is the add-on's source folder: a copy of another commit
(`git archive HEAD | tar -x -C DIR`) dumps that commit. The add-on is built and installed as the
tests do (`harness`), then each group of `nodes.SPECS` is built, every variant of its parts too,
and each tree in the file written: its interface, its nodes (type, label, properties, unlinked
input values, location) and its links, sorted.
"""

import argparse
import itertools
import json
import sys
import tempfile
from pathlib import Path

import harness

# What every node has: left out of a node's own properties (location and the like are written apart).
_BASE_NODE = None


def _plain(value):
    """A JSON-able form of an RNA value: IDs by name, arrays as lists, floats as they are."""
    if value is None or isinstance(value, bool | int | float | str):
        return value
    if hasattr(value, "bl_rna") and hasattr(value, "name") and hasattr(value, "users"):
        return {"id": type(value).__name__, "name": value.name}
    if isinstance(value, set | frozenset):
        return sorted(value)
    try:
        return [_plain(v) for v in value]
    except TypeError:
        return repr(value)


def _properties(node):
    """The node's own RNA properties (operation, data_type, domain, ...), not those of every node."""
    found = {}
    for prop in node.bl_rna.properties:
        key = prop.identifier
        if key in _BASE_NODE or prop.type == "COLLECTION":
            continue
        found[key] = _plain(getattr(node, key))
    for collection in ("state_items", "capture_items", "repeat_items", "bake_items"):
        items = getattr(node, collection, None)
        if items is not None:
            found[collection] = [[item.name, item.socket_type] for item in items]
    return found


def _socket(socket, linked):
    entry = {"name": socket.name, "type": socket.bl_idname, "enabled": socket.enabled}
    if not linked and hasattr(socket, "default_value"):
        entry["default"] = _plain(socket.default_value)
    return entry


def _interface(tree):
    items = []
    for item in tree.interface.items_tree:
        entry = {"item_type": item.item_type, "name": item.name, "index": item.index}
        if item.item_type == "SOCKET":
            entry |= {"in_out": item.in_out, "socket_type": item.socket_type, "description": item.description}
            for key in ("default_value", "min_value", "max_value", "subtype", "hide_value"):
                if hasattr(item, key):
                    entry[key] = _plain(getattr(item, key))
        items.append(entry)
    return items


def dump_tree(tree):
    linked = {(link.to_node.name, link.to_socket.identifier) for link in tree.links}
    nodes = {}
    for node in tree.nodes:
        nodes[node.name] = {
            "bl_idname": node.bl_idname,
            "label": node.label,
            "location": [round(node.location.x, 3), round(node.location.y, 3)],
            "properties": _properties(node),
            "inputs": {s.identifier: _socket(s, (node.name, s.identifier) in linked) for s in node.inputs},
            "outputs": [s.identifier for s in node.outputs if s.enabled],
        }
    links = sorted(
        [
            f"{link.from_node.name}:{link.from_socket.identifier}",
            f"{link.to_node.name}:{link.to_socket.identifier}",
            link.multi_input_sort_id if link.to_socket.is_multi_input else None,
            link.is_muted,
        ]
        for link in tree.links
    )
    return {
        "bl_idname": tree.bl_idname,
        "description": tree.description,
        "properties": {key: _plain(tree[key]) for key in sorted(tree.keys())},
        "is_modifier": getattr(tree, "is_modifier", None),
        "interface": _interface(tree),
        "nodes": dict(sorted(nodes.items())),
        "links": links,
    }


def _variants(spec):
    """The spec and each variant of its parts (every subset of them)."""
    names = [part.name for part in spec.parts]
    return [spec.variant(on) for size in range(len(names) + 1) for on in itertools.combinations(names, size)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", help="the JSON file written")
    parser.add_argument("--root", default=str(harness.ROOT), help="the add-on's source folder")
    args = parser.parse_args()
    bpy = harness.start()
    global _BASE_NODE
    _BASE_NODE = {prop.identifier for prop in bpy.types.Node.bl_rna.properties}
    with tempfile.TemporaryDirectory() as folder:
        zip_path = Path(folder) / f"{harness.ADDON_ID}.zip"
        proc = harness.run_blender_ext("build", "--source-dir", args.root, "--output-filepath", str(zip_path))
        if proc.returncode != 0:
            sys.exit(f"building the add-on from {args.root} failed:\n{proc.stdout}\n{proc.stderr}")
        harness.install(zip_path)
    nodes = harness.addon("nodes")
    builder = harness.addon("nodes.builder")
    for spec in nodes.SPECS.values():
        for variant in _variants(spec):
            builder.ensure_group(variant, nodes.SPECS)
    groups = {tree.name: dump_tree(tree) for tree in bpy.data.node_groups}
    Path(args.out).write_text(json.dumps(dict(sorted(groups.items())), indent=1, ensure_ascii=False) + "\n")
    print(f"{len(groups)} node groups written to {args.out}")


if __name__ == "__main__":
    main()
