"""Sphinx configuration of the genparams documentation site (`make docs`)."""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from genparams import __version__  # noqa: E402  (after the path is set up)

project = "genparams"
author = "genparams contributors"
copyright = "genparams contributors"  # noqa: A001  (Sphinx reads this name)
version = release = __version__

extensions = ["myst_parser"]
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build"]

# Anchors for headings down to ###, so pages link to each other's sections
# (`schema.md#validators`) the same way on GitHub and in the built site.
myst_heading_anchors = 3

html_theme = "alabaster"
html_title = f"genparams {release}"
