"""No import circle among the runtime's modules, imports for type checking included.

import-linter keeps the layers (core, node, remote, Params; pyproject's
[tool.importlinter]) but leaves out imports under ``TYPE_CHECKING``; a circle of
those still ties modules together, so this test reads every import, type-only
and function-level ones included, from grimp's graph of the package.
"""

from __future__ import annotations

import copy
from collections.abc import Mapping, Sequence
from functools import cache

import grimp

RUNTIME = "genparams.runtime"


@cache
def package_graph() -> grimp.ImportGraph:
    # cache_dir=None: nothing is written beside the sources.
    return grimp.build_graph("genparams", exclude_type_checking_imports=False, cache_dir=None)


def runtime_imports(graph: grimp.ImportGraph) -> dict[str, list[str]]:
    """Each runtime module -> the runtime modules it imports directly."""
    inside = {m for m in graph.modules if m == RUNTIME or m.startswith(RUNTIME + ".")}
    return {m: sorted(graph.find_modules_directly_imported_by(m) & inside) for m in sorted(inside)}


def first_cycle(imports: Mapping[str, Sequence[str]]) -> list[str]:
    """One circle of ``imports`` as the modules around it, first one last again; [] if none."""
    done: set[str] = set()
    path: list[str] = []

    def visit(module: str) -> list[str]:
        path.append(module)
        for imported in imports.get(module, ()):
            if imported in path:
                return [*path[path.index(imported) :], imported]
            if imported not in done:
                found = visit(imported)
                if found:
                    return found
        path.pop()
        done.add(module)
        return []

    for module in imports:
        if module not in done:
            found = visit(module)
            if found:
                return found
    return []


def test_no_runtime_module_imports_itself_round_a_circle() -> None:
    graph = package_graph()
    # rule_check imports ParamsView under TYPE_CHECKING only: such imports are read.
    type_only = (f"{RUNTIME}.core.rule_check", f"{RUNTIME}.core.params_view")
    assert graph.direct_import_exists(importer=type_only[0], imported=type_only[1])
    imports = runtime_imports(graph)
    assert len(imports) > 30  # the graph holds the runtime
    cycle = first_cycle(imports)
    assert not cycle, "an import circle: " + " -> ".join(cycle)


def test_one_import_against_the_layers_shows_as_a_circle() -> None:
    """The check fails as it should: spec imports naming, so naming importing spec closes one."""
    graph = copy.deepcopy(package_graph())
    naming, spec = f"{RUNTIME}.core.naming", f"{RUNTIME}.core.spec"
    assert graph.direct_import_exists(importer=spec, imported=naming)
    graph.add_import(importer=naming, imported=spec)
    cycle = first_cycle(runtime_imports(graph))
    assert cycle[0] == cycle[-1]
    assert {naming, spec} <= set(cycle)


def test_a_circle_is_reported_as_the_modules_around_it() -> None:
    imports = {
        "a.binding": ["a.mapped", "a.spec"],
        "a.mapped": ["a.spec"],
        "a.spec": [],
    }
    assert first_cycle(imports) == []
    assert first_cycle({**imports, "a.mapped": ["a.spec", "a.binding"]}) == [
        "a.binding",
        "a.mapped",
        "a.binding",
    ]
