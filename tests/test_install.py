"""Install in three steps, as the README gives them: build the zip (`tools/build`), Install from Disk
into a clean user folder, Add > Mesh > Water Surface; and the README's API import.

The session's Blender already has the add-on (tests/conftest.py), so the clean install runs in a
Blender of its own, started with an empty `BLENDER_USER_RESOURCES`, while this one waits.
"""

import json
import os
import subprocess
import sys
import zipfile

import harness

# Runs in a fresh Python with an empty user folder; prints one JSON line of what it found.
INSTALL_AND_ADD = r"""
import importlib
import json
import os
import sys

import bpy  # first: it puts addon_utils on the path

import addon_utils

zip_path, user = sys.argv[1], os.environ["BLENDER_USER_RESOURCES"]
found = {"before": sorted(m.__name__ for m in addon_utils.modules() if "water_surface" in m.__name__)}

# Step 2: Edit > Preferences > Get Extensions > Install from Disk (its operator and defaults).
found["install"] = sorted(
    bpy.ops.extensions.package_install_files(filepath=zip_path, repo="user_default", enable_on_install=True)
)
module = "bl_ext.user_default.water_surface"
found["enabled"] = module in bpy.context.preferences.addons
found["installed_in"] = os.path.relpath(os.path.dirname(importlib.import_module(module).__file__), user)

# Step 3: Add > Mesh > Water Surface (the menu entry, then its operator in an empty scene).
entries = [f.__module__ for f in bpy.types.VIEW3D_MT_mesh_add._dyn_ui_initialize()]
found["menu"] = [m for m in entries if m.startswith(module)]
bpy.ops.wm.read_homefile(use_empty=True)
found["add"] = sorted(bpy.ops.object.water_add())
water = bpy.context.active_object
values = importlib.import_module(module + ".water.values")
found["is_water"] = values.is_water(water)
found["material"] = values.water_material(water).name

# The pipeline engineer's import, as the README writes it.
package = next(m.__name__ for m in addon_utils.modules() if m.__name__.rpartition(".")[2] == "water_surface")
water_api = importlib.import_module(package + ".api")
added = water_api.add_water(bpy.context.scene, preset="calm_mirror", size=64, location=(0, 0, 0))
waters = [o.name for o in bpy.context.scene.objects if water_api.is_water(o)]
found["api"] = [package, water_api.kind_of(added.object), len(waters)]
print("RESULT " + json.dumps(found))
"""


def test_tools_build_zip_installs_from_disk_into_a_clean_user_folder_and_adds_water(tmp_path):
    # Step 1: what tools/build makes, a validated dist/water_surface-<version>.zip (here in tmp_path).
    zip_path = harness.build_release(tmp_path / "dist")
    assert zip_path.name == f"water_surface-{harness.manifest_version()}.zip"
    assert zip_path.parent == (tmp_path / "dist").resolve()
    assert "blender_manifest.toml" in zipfile.ZipFile(zip_path).namelist()

    user = tmp_path / "user"
    user.mkdir()
    env = dict(os.environ, BLENDER_USER_RESOURCES=str(user))
    proc = subprocess.run(
        [sys.executable, "-c", INSTALL_AND_ADD, str(zip_path)],
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )
    lines = [line for line in proc.stdout.splitlines() if line.startswith("RESULT ")]
    assert proc.returncode == 0 and lines, proc.stdout[-4000:] + proc.stderr[-4000:]
    found = json.loads(lines[-1][len("RESULT ") :])

    assert found["before"] == []  # a clean user folder: no Water Surface yet
    assert found["install"] == ["FINISHED"]
    assert found["enabled"]
    assert found["installed_in"].replace("\\", "/").endswith("extensions/user_default/water_surface")
    assert found["menu"] == ["bl_ext.user_default.water_surface.ui.menus"]
    assert found["add"] == ["FINISHED"]
    assert found["is_water"]
    assert found["material"]
    assert found["api"] == ["bl_ext.user_default.water_surface", "lake", 2]
