"""Rules, several classes on one node, threads, remote access and lifecycle nodes, on real nodes.

Run from the repository root, one part or all of them:
ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST .venv/bin/python examples/motion/tour.py [PART...]
PART is rules, several, threads, remote, lifecycle (default: all).
"""

from __future__ import annotations

import importlib.util
import itertools
import random
import sys
import tempfile
import threading
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

import rclpy
from rcl_interfaces.msg import SetParametersResult
from rclpy.context import Context
from rclpy.executors import MultiThreadedExecutor, SingleThreadedExecutor
from rclpy.lifecycle import Node as LifecycleNode
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.task import Future

import genparams
from genparams.runtime import Changes, ParameterDeclarationError, RemoteSetError

HERE = Path(__file__).resolve().parent


def generated(name: str, directory: Path) -> ModuleType:
    """Generate ``<name>.yaml`` into ``directory`` and import it (a package would commit it)."""
    path = directory / f"{name}_params.py"
    path.write_text(genparams.generate(HERE / f"{name}.yaml"), encoding="utf-8")
    spec = importlib.util.spec_from_file_location(f"{name}_params", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def verdict(result: SetParametersResult) -> str:
    return "accepted" if result.successful else f"rejected: {result.reason}"


def changed(changes: Changes[Any]) -> str:
    return ", ".join(f"{c.name} {c.old!r} -> {c.new!r}" for c in changes)


# The modules are generated at run time, so values are typed Any here.
def rules(m: ModuleType, context: Context) -> None:
    node = Node("base", context=context)
    cfg = m.MotionParams.declare(node)
    (result,) = node.set_parameters([Parameter("min_speed", value=2.0)])
    print(f"set min_speed := 2.0 -> {verdict(result)}")
    (result,) = node.set_parameters([Parameter("image.width", value=1920)])
    print(f"set image.width := 1920 -> {verdict(result)}")
    size = [("image.width", 1920), ("image.height", 1080), ("image.aspect_ratio", 1.7778)]
    result = node.set_parameters_atomically([Parameter(n, value=v) for n, v in size])
    print(f"set 1920x1080, aspect_ratio 1.7778 atomically -> {verdict(result)}")
    print(f"cfg.image = {cfg.image}")
    args = ["--ros-args", "-p", "min_speed:=3.0", "-p", "weights:=[1.0]"]
    try:
        m.MotionParams.declare(Node("base_bad", context=context, cli_args=args))
    except ParameterDeclarationError as exc:
        print(exc)


def several(m: ModuleType, s: ModuleType, context: Context) -> None:
    node = Node("robot", context=context)
    motion = m.MotionParams.declare(node, prefix="base")
    safety = s.SafetyParams.declare(node, prefix="safety")
    motion.on_change(lambda changes: print(f"  motion heard: {changed(changes)}"))
    safety.on_change(lambda changes: print(f"  safety heard: {changed(changes)}"))
    for name, value in (
        ("base.max_speed", 2.0),
        ("safety.stop_distance", 1.5),
        ("use_sim_time", True),
    ):
        print(f"set {name} := {value!r}")
        node.set_parameters([Parameter(name, value=value)])
    print("set base.min_speed := 0.5 and safety.enabled := false atomically")
    node.set_parameters_atomically(
        [Parameter("base.min_speed", value=0.5), Parameter("safety.enabled", value=False)]
    )


def threads(m: ModuleType, context: Context) -> None:
    node = Node("busy_base", context=context)
    cfg = m.MotionParams.declare(node)
    executor = MultiThreadedExecutor(num_threads=4, context=context)
    executor.add_node(node)
    spinner = threading.Thread(target=executor.spin, daemon=True)
    spinner.start()
    deliveries: list[Changes[Any]] = []
    cfg.on_change(deliveries.append)
    outcomes = {"accepted": 0, "rejected": 0}
    lock = threading.Lock()

    def client(seed: int) -> None:
        rng = random.Random(seed)
        for _ in range(250):
            name = rng.choice(("min_speed", "max_speed"))
            (result,) = node.set_parameters([Parameter(name, value=rng.uniform(0.0, 5.0))])
            with lock:
                outcomes["accepted" if result.successful else "rejected"] += 1

    clients = [threading.Thread(target=client, args=(seed,)) for seed in range(4)]
    for thread in clients:
        thread.start()
    for thread in clients:
        thread.join()
    executor.shutdown()
    kept = all(d.after.min_speed <= d.after.max_speed for d in deliveries)
    in_order = all(a.after is b.before for a, b in itertools.pairwise(deliveries))
    agree = (node.get_parameter("min_speed").value, node.get_parameter("max_speed").value) == (
        cfg.min_speed,
        cfg.max_speed,
    )
    print(f"4 threads x 250 sets: {outcomes['accepted']} accepted, {outcomes['rejected']} rejected")
    print(f"every committed snapshot keeps min_speed <= max_speed: {kept}")
    print(f"on_change calls chain in commit order: {in_order}; node and cfg agree: {agree}")


def remote(m: ModuleType, context: Context) -> None:
    base = Node("remote_base", context=context)
    m.MotionParams.declare(base)
    teleop = Node("teleop", context=context)
    executor = SingleThreadedExecutor(context=context)
    executor.add_node(base)
    executor.add_node(teleop)

    def wait(future: Future) -> Any:
        executor.spin_until_future_complete(future, timeout_sec=10.0)
        return future.result()

    base_remote = m.MotionParams.remote(teleop, "/remote_base")
    if not base_remote.wait_for_services(timeout_sec=10.0):
        raise TimeoutError("no parameter services")
    snapshot = wait(base_remote.get())
    print(f"get -> max_speed={snapshot.max_speed}, topics={snapshot.topics}")
    wait(base_remote.set({"max_speed": 3, "min_speed": 0.5}))
    print(f"set max_speed=3, min_speed=0.5 -> accepted; now {wait(base_remote.get()).max_speed}")
    try:
        base_remote.set({"max_speed": 9.0}).result()  # fails at once: nothing is sent
    except RemoteSetError as exc:
        print(f"set max_speed=9.0 -> {exc}")
    seen: list[Changes[Any]] = []
    watch = base_remote.watch(seen.append)
    wait(watch.ready)
    base.set_parameters([Parameter("min_speed", value=1.25)])
    spin_until(executor, lambda: bool(seen))
    print(f"watch heard: {changed(seen[0])}")
    watch.cancel()
    executor.shutdown()


def spin_until(executor: SingleThreadedExecutor, done: Callable[[], bool]) -> None:
    for _ in range(200):
        if done():
            return
        executor.spin_once(timeout_sec=0.05)
    raise TimeoutError("nothing heard")


def lifecycle(m: ModuleType, context: Context) -> None:
    class Base(LifecycleNode):
        def __init__(self) -> None:
            super().__init__("lifecycle_base", context=context)
            self.params = m.MotionParams.declare(self)  # declared once, before configure

        def on_configure(self, state: State) -> TransitionCallbackReturn:
            print(f"configured with max_speed={self.params.snapshot().max_speed}")
            return TransitionCallbackReturn.SUCCESS

    node = Base()
    (result,) = node.set_parameters([Parameter("max_speed", value=4.0)])
    print(f"set max_speed := 4.0 -> {verdict(result)}")
    node.trigger_configure()
    (result,) = node.set_parameters([Parameter("min_speed", value=4.5)])
    print(f"set min_speed := 4.5 -> {verdict(result)}")


def main(parts: list[str]) -> int:
    known = ("rules", "several", "threads", "remote", "lifecycle")
    parts = parts or list(known)
    unknown = [p for p in parts if p not in known]
    if unknown:
        print(f"unknown part {unknown[0]!r}: choose from {', '.join(known)}", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as directory:
        motion = generated("motion", Path(directory))
        safety = generated("safety", Path(directory))
        for part in parts:
            print(f"== {part}")
            context = Context()  # each part in its own context: nodes go with it
            rclpy.init(context=context)
            try:
                if part == "several":
                    several(motion, safety, context)
                else:
                    {"rules": rules, "threads": threads, "remote": remote, "lifecycle": lifecycle}[
                        part
                    ](motion, context)
            finally:
                rclpy.shutdown(context=context)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
