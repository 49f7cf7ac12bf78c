"""The view from below the surface (docs/MODEL.md section 16), made for each water by
`water/underwater.py`: `Water Underwater Fog` in `Water Underwater Shell`'s body, with `Water
Meniscus` along the waterline, and `Water Caustic Light` on `Water Caustic Sheet`'s copy of the
surface; one module a group, the camera's gates they share in `camera_gate.py`."""
