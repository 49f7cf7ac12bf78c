"""The open sea's node groups: `Water Ocean Normal` and `Water Ocean Shade` (a module each, their
shared helpers and inputs in `ocean_parts.py`), `Water Sea Fade`, and the ocean material."""
