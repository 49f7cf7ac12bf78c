# SPDX-License-Identifier: GPL-3.0-or-later
"""Water Surface: animated water with mirror reflections and refraction for EEVEE.

Each sub-package registers its own classes; this module only chains them, in
order on register and in reverse on unregister, so that disabling the add-on
leaves nothing behind.
"""

from . import cli, handlers, nodes, operators, presets, ui

_packages = (nodes, presets, handlers, operators, ui, cli)


def register():
    for package in _packages:
        package.register()


def unregister():
    for package in reversed(_packages):
        package.unregister()
