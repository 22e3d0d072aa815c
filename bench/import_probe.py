"""Time one import of a module in this fresh process: ``python -m bench.import_probe DIR MODULE``.

What any node imports anyway (rclpy, its messages, the genparams runtime) is
imported first, so the time is the module's own: reading or compiling its
code and running its class bodies.
"""

from __future__ import annotations

import importlib
import json
import sys
import time


def main(directory: str, module_name: str) -> None:
    import rcl_interfaces.msg  # noqa: F401
    import rclpy.node  # noqa: F401

    import genparams.runtime  # noqa: F401

    sys.path.insert(0, directory)
    start = time.thread_time()  # CPU time, as for every in-process measurement
    importlib.import_module(module_name)
    print(json.dumps({"seconds": time.thread_time() - start}))


if __name__ == "__main__":
    main(*sys.argv[1:3])
