"""Build integration: writing outputs atomically, the ``[tool.genparams]`` table of
pyproject.toml. ``genparams.setuptools`` and ``genparams.cmake`` are the public entry
points built on it.
"""
