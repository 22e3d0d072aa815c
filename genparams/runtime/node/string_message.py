"""std_msgs/String, the schema message's type, loaded without the rest of ``std_msgs.msg``.

``from std_msgs.msg import String`` runs that package's ``__init__``, which imports
all thirty std_msgs types: about 10 ms of CPU in every process that declares a
class. Only the module defining String is loaded here, under its own name, so a
later ``import std_msgs.msg`` finds it in ``sys.modules`` and the whole process
shares one String class. Anything unusual (the package already imported, no
source file) falls back to the ordinary import.
"""

from __future__ import annotations

import importlib.util
import sys
import threading
from pathlib import Path
from types import ModuleType
from typing import Any

_MODULE = "std_msgs.msg._string"
_LOADING = threading.Lock()


def string_type() -> Any:
    """The std_msgs/String message class."""
    with _LOADING:
        module = sys.modules.get(_MODULE)
        if module is None and "std_msgs.msg" not in sys.modules:
            module = _load_alone()
    if module is None:
        from std_msgs.msg import String

        return String
    return module.String


def _load_alone() -> ModuleType | None:
    package = importlib.util.find_spec("std_msgs")
    folders = package.submodule_search_locations if package is not None else None
    sources = [Path(folder, "msg", "_string.py") for folder in folders or ()]
    source = next((path for path in sources if path.is_file()), None)
    spec = importlib.util.spec_from_file_location(_MODULE, source) if source else None
    if spec is None or spec.loader is None:
        return None
    module = importlib.util.module_from_spec(spec)
    sys.modules[_MODULE] = module
    try:
        spec.loader.exec_module(module)
    except BaseException:
        del sys.modules[_MODULE]
        raise
    return module
