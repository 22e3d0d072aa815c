"""Sphinx configuration of the genparams documentation site (`make docs`)."""

from genparams import __version__

project = "genparams"
author = "genparams contributors"
copyright = "genparams contributors"
version = release = __version__

extensions = ["myst_parser"]
source_suffix = {".md": "markdown"}
root_doc = "index"

# Anchors for headings down to ###, so pages link to each other's sections
# (`schema.md#validators`) the same way on GitHub and in the built site.
myst_heading_anchors = 3

html_theme = "alabaster"
html_title = f"genparams {release}"
