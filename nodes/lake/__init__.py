"""The lake's shading: `Water Surface` (`water_surface.py`, its helpers in `lake_parts.py`); the
foam coverage and the groups the sea shares with it stay at the top of `nodes/`."""
