"""Plain functions behind the operators, the panel and the command line.

Everything here works from any `bpy` script: the operators only add undo,
reports and the 3D cursor on top.
"""
