"""Where the demo's pictures go: `out/` always, `docs/` only when asked (`tools/demo --docs`, which
sets WATER_SURFACE_DEMO_DOCS=1). The render scripts publish every finished picture through
`publish`, the one place that writes into docs/, so a plain `tools/demo` leaves the checkout clean.
"""

import os
import shutil
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "out"
DOCS = ROOT / "docs"
DOCS_ENV = "WATER_SURFACE_DEMO_DOCS"


def docs_asked():
    """Whether this run refreshes the pictures in docs/ (`tools/demo --docs`)."""
    return os.environ.get(DOCS_ENV, "") == "1"


def publish(path, docs=None, docs_dir=DOCS, note=""):
    """Publishes the finished picture `path` (written under out/): copies it to `docs_dir` when
    `docs` (default: `docs_asked()`), prints "wrote <path>[ and <copy>]" (and `note`) and returns
    the paths written."""
    path = Path(path)
    written = [path]
    if docs_asked() if docs is None else docs:
        copy = Path(docs_dir) / path.name
        copy.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(path, copy)
        written.append(copy)
    print(f"wrote {' and '.join(str(p) for p in written)}{f' {note}' if note else ''}", flush=True)
    return written
