"""Build-side scenarios: code generation, and importing the generated module."""

from __future__ import annotations

import gc
import importlib.util
import py_compile
import shutil
import sys
from pathlib import Path

import genparams
from bench.measure import Result, child_environment, run_probe, time_calls, time_process
from bench.workspace import Prepared

GENERATE_PROCESS = "genparams generate (whole process, CPU time)"
GENERATE_PROCESS_WALL = "genparams generate (whole process, wall-clock)"
GENERATE_CALL = "genparams.generate() (in process)"


def codegen(prepared: Prepared, repeats: int) -> list[Result]:
    size, schema = prepared.schema.size, prepared.schema_path
    output = prepared.module_path.with_name(f"codegen_{size}.py")
    command = [sys.executable, "-m", "genparams", "generate", str(schema), "-o", str(output)]
    cpu, wall = zip(*(time_process(command) for _ in range(repeats)), strict=True)
    if output.read_text(encoding="utf-8") != prepared.module_path.read_text(encoding="utf-8"):
        raise RuntimeError("genparams generate and genparams.generate() disagree")
    output.unlink()
    in_process = time_calls(lambda: genparams.generate(schema), repeats)
    return [
        Result("codegen", GENERATE_PROCESS, size, "s", cpu),
        Result("codegen", GENERATE_PROCESS_WALL, size, "s", wall),
        Result("codegen", GENERATE_CALL, size, "s", in_process),
    ]


STAGE_LOAD = "load YAML (loader.load_yaml)"
STAGE_CHECK = "check against the JSON Schema (schema_check)"
STAGE_BUILD = "build the model (builder)"
STAGE_RENDER = "render the module (render)"


def codegen_stages(prepared: Prepared, repeats: int) -> list[Result]:
    """Where in-process generation time goes, one pipeline stage at a time."""
    from genparams.outputs.render import render_module
    from genparams.schema.builder import build_schema
    from genparams.schema.loader import load_yaml
    from genparams.schema.schema_check import check_document

    text = prepared.schema_path.read_text(encoding="utf-8")
    file = str(prepared.schema_path)
    document = load_yaml(text, file)
    schema = build_schema(document)
    stages = {
        STAGE_LOAD: lambda: load_yaml(text, file),
        STAGE_CHECK: lambda: check_document(document),
        STAGE_BUILD: lambda: build_schema(document),
        STAGE_RENDER: lambda: render_module(schema),
    }
    results = []
    for label, stage in stages.items():
        # As in genparams.generate(), which pauses the cycle collector around the pipeline.
        gc.disable()
        try:
            samples = time_calls(stage, repeats)
        finally:
            gc.enable()
        results.append(Result("codegen_stages", label, prepared.schema.size, "s", samples))
    return results


GENPARAMS_COLD = "genparams module, cold (no .pyc)"
PLAIN_COLD = "hand-written module, cold (no .pyc)"
GENPARAMS_WARM = "genparams module, warm (.pyc cached)"
PLAIN_WARM = "hand-written module, warm (.pyc cached)"


def import_time(prepared: Prepared, repeats: int) -> list[Result]:
    directory = prepared.module_path.parent
    cache = directory / "__pycache__"
    results = []
    modules = (
        (prepared.schema.module_name, GENPARAMS_COLD, GENPARAMS_WARM),
        (prepared.schema.plain_module_name, PLAIN_COLD, PLAIN_WARM),
    )
    for module, cold_label, warm_label in modules:
        cold = []
        for _ in range(repeats):
            shutil.rmtree(cache, ignore_errors=True)
            cold.append(_probe(directory, module, write_bytecode=False))
        _probe(directory, module, write_bytecode=True)  # leaves the .pyc behind
        warm = tuple(_probe(directory, module, write_bytecode=True) for _ in range(repeats))
        results.append(Result("import", cold_label, prepared.schema.size, "s", tuple(cold)))
        results.append(Result("import", warm_label, prepared.schema.size, "s", warm))
    return results


def write_bytecode(directory: Path, *modules: str) -> None:
    """Compile modules to their cached .pyc, as installing a package does."""
    for module in modules:
        source = directory / f"{module}.py"
        py_compile.compile(str(source), cfile=importlib.util.cache_from_source(str(source)))


def _probe(directory: Path, module: str, *, write_bytecode: bool) -> float:
    env = child_environment()
    if not write_bytecode:
        env["PYTHONDONTWRITEBYTECODE"] = "1"
    else:
        env.pop("PYTHONDONTWRITEBYTECODE", None)
    seconds: float = run_probe("bench.import_probe", [str(directory), module], env)["seconds"]
    return seconds
