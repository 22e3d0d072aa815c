"""The version of genparams: the one place it is written (pyproject.toml and the CMake
package read it from here). It imports nothing, so every layer may read it."""

__version__ = "0.2.0"
