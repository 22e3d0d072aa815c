"""The node's source, changed to use the generated class: a unified diff.

- Declarations the schema now holds go: a statement that only declares is
  removed (a loop over literal items, a loop over a parameter's items or an
  ``if`` on a parameter's value that only declares, too); the first one
  becomes ``self.params = XParams.declare(self)``.
- A declaration whose result is used becomes a read: ``.value`` -> the typed
  read ``self.params.a.b``; anything else -> ``self.get_parameter('a.b')``
  (the parameter genparams declared).
- ``self.get_parameter('a.b').value`` (and ``.get_parameter_value().double_value``)
  of an imported parameter becomes ``self.params.a.b``; so does
  ``self.get_parameter_or('a.b', alternative).value`` of one always set (neither
  optional nor conditional), whose alternative rclpy would never give.
- The class is imported beside the other imports; names whose last use went
  with a declaration (``ParameterDescriptor``, a descriptor variable) go too.

Declarations left out of the schema stay as they are. Only ``self.``
declarations inside the node class are rewritten.
"""

from __future__ import annotations

import ast
import difflib
from collections.abc import Iterable
from pathlib import Path

from genparams.importing import LEFT_OUT
from genparams.rclpy_import.features import AUTOMATIC
from genparams.rclpy_import.found import Found
from genparams.rclpy_import.node_file import ImportedNode
from genparams.rclpy_import.patch_shapes import (
    always_set,
    body_of,
    declaring_branches,
    free_attribute,
    only_declares,
    only_read_in,
    read_of,
    self_calls,
)
from genparams.rclpy_import.placing import item_place
from genparams.rclpy_import.reads import DECLARE_ONE
from genparams.rclpy_import.source_edits import (
    Edit,
    Source,
    apply_edits,
    drop_unused_descriptors,
    drop_unused_imports,
)
from genparams.rclpy_import.values import Evaluator, Scope, UntranslatableError
from genparams.runtime.core.naming import attribute_parts, class_name, module_name

LINE_LENGTH = 100  # the longest line a rewritten call is written on (ruff's E501 at 100)


def patch_diff(node: ImportedNode, file: str) -> str:
    patched = patched_source(node, file)
    before = node.source.splitlines(keepends=True)
    after = patched.splitlines(keepends=True)
    lines = difflib.unified_diff(before, after, file, file)
    # a last line without a newline is marked as diff and patch expect it
    return "".join(line if line.endswith("\n") else f"{line}\n\\ No newline at end of file\n"
                   for line in lines)  # fmt: skip


def unchanged_reason(node: ImportedNode) -> str:
    """Why the patch of ``node`` changes nothing, for the message."""
    if not isinstance(node.unit.node, ast.ClassDef):
        return (
            "the module's functions declare the parameters: only declarations on self in "
            "a class are rewritten"
        )
    elsewhere = _declared_elsewhere(node)
    if elsewhere is not None:
        return (
            f"{elsewhere} declares imported parameters, which the generated class would "
            "declare again: the node is left as written (move those declarations to the "
            "schema by hand)"
        )
    declared = [o.found for o in node.imported.declared if o.found and o.found.read is None]
    if declared and not any(f.receiver_is_self for f in declared):
        return "only declarations on self in a class are rewritten"
    if not declared:
        return "no statement of the node declares a parameter the schema holds"
    return (
        "every declaring statement also declares a parameter left out (see warnings), so "
        "it stays as written"
    )


def _declared_elsewhere(node: ImportedNode) -> str | None:
    """A helper, base class or object of the package declaring an imported parameter."""
    for each in node.imported.declared:
        if each.found is not None and each.found.via is not None and each.fate != LEFT_OUT:
            return each.found.via
    return None


def patched_source(node: ImportedNode, file: str) -> str:
    if not isinstance(node.unit.node, ast.ClassDef) or _declared_elsewhere(node) is not None:
        return node.source  # declarations on other receivers: left to the author
    return _Patcher(node, node.unit.node, file).run()


class _Patcher:
    def __init__(self, node: ImportedNode, cls: ast.ClassDef, file: str) -> None:
        self.node = node
        self.file = file
        self.source = Source(node.source)
        self.cls = cls
        self.parents = {
            child: parent for parent in ast.walk(cls) for child in ast.iter_child_nodes(parent)
        }
        self.schema = node.imported.name
        self.class_name = class_name(self.schema)
        self.attribute = free_attribute(cls)
        self.names = node.imported.imported_names
        self.edits: list[Edit] = []
        self.removed: list[ast.stmt] = []
        self.removals: dict[ast.stmt, Edit] = {}
        self.kept: list[ast.stmt] = []  # declare_parameters statements keeping part of a list

    def run(self) -> str:
        patchable = self.patchable()
        automatic = self.automatic_option()
        declare = f"self.{self.attribute} = {self.class_name}.declare(self)"
        if automatic is not None:
            self.drop_keyword(automatic)
            if not patchable:  # the node only reads: declare once the node is built
                statement = self.statement_of(automatic)
                at = self.source.starts[statement.end_lineno or statement.lineno]
                self.edits.append(Edit(at, at, f"{self.source.indent(statement)}{declare}\n"))
        elif not patchable and not self.kept:
            return self.node.source
        elif not patchable:  # a list imported in part: genparams declares before it
            first = min(self.kept, key=lambda s: (s.lineno, s.col_offset))
            start = self.source.starts[first.lineno - 1]
            self.edits.append(Edit(start, start, f"{self.source.indent(first)}{declare}\n"))
        if patchable:
            first = min(patchable, key=lambda s: (s.lineno, s.col_offset))
            removed_first = False
            for statement, founds in patchable.items():
                removed = self.rewrite(statement, founds)
                if statement is first:
                    removed_first = removed
            self.drop_condition_variables(patchable)
            removed_first = first in self.removed
            self.place_declare(first, declare, removed_first)
            self.drop_name_variables()
            self.fill_emptied(first if removed_first else None)
        self.rewrite_reads()
        self.add_import()
        text = apply_edits(self.node.source, self.edits)
        for _ in range(3):  # a descriptor may use a range variable
            text = drop_unused_descriptors(text)
        return drop_unused_imports(self.node.source, text)

    def automatic_option(self) -> ast.keyword | None:
        """``automatically_declare_parameters_from_overrides=True`` in the class, when the
        schema declares every parameter the node reads (it goes: genparams declares)."""
        if not self.node.imported.replaces_automatic:
            return None
        for option in self.node.unit.options:
            if option.option == AUTOMATIC and isinstance(option.at, ast.keyword):
                if option.at in self.parents:
                    return option.at
        return None

    def statement_of(self, node: ast.AST) -> ast.stmt:
        while not isinstance(node, ast.stmt):
            node = self.parents[node]
        return node

    def drop_keyword(self, keyword: ast.keyword) -> None:
        """Take ``keyword`` out of its call, with the comma before it (or after it)."""
        call = self.parents[keyword]
        if not isinstance(call, ast.Call):
            return
        arguments: list[ast.AST] = sorted(
            [*call.args, *call.keywords],
            key=lambda n: (n.lineno, n.col_offset),  # type: ignore[attr-defined]
        )
        index = arguments.index(keyword)
        start, end = self.source.span(keyword)
        if index > 0:
            start = self.source.span(arguments[index - 1])[1]
        elif index + 1 < len(arguments):
            end = self.source.span(arguments[index + 1])[0]
        self.edits.append(Edit(start, end, ""))

    def patchable(self) -> dict[ast.stmt, list[Found]]:
        """Statements to rewrite (declaring statements, or loops over literal items), each
        with its declarations; only when every declaration they make was imported."""
        outcomes: dict[ast.stmt, list[str]] = {}
        for each in self.node.imported.declared:
            if each.found is not None:
                outcomes.setdefault(each.found.statement, []).append(each.fate)
        groups: dict[ast.stmt, list[tuple[Found, str]]] = {}
        for each in self.node.imported.declared:
            found, outcome = each.found, each.fate
            if found is None or found.via is not None:
                continue  # declared outside the node's own statements: left as written
            if found.read is not None:
                continue  # a read stays: genparams declared the parameter it reads
            statement: ast.stmt = (
                found.literal_loop or self.enclosing(found, outcomes) or found.statement
            )
            groups.setdefault(statement, []).append((found, outcome))
        out = {}
        for statement, items in groups.items():
            if any(not f.receiver_is_self for f, _ in items):
                continue
            if any(o == LEFT_OUT for _, o in items):
                self.keep_left_out(statement, items)
                continue
            if isinstance(statement, ast.For) and not only_declares(statement):
                continue
            out[statement] = [f for f, _ in items]
        return out

    def enclosing(self, found: Found, outcomes: dict[ast.stmt, list[str]]) -> ast.stmt | None:
        """The loop over a parameter's value, or the ``if`` on one (with its ``elif`` and
        ``else`` branches), around a declaration, when it only declares parameters the
        schema now holds (per-item, conditional): it goes whole."""
        parent = self.parents.get(found.statement)
        if not isinstance(parent, (ast.For, ast.If)) or found.statement not in (
            parent.body + parent.orelse
        ):
            return None
        above = self.parents.get(parent)
        while isinstance(above, ast.If) and above.orelse == [parent]:  # parent is an elif
            parent, above = above, self.parents.get(above)
        statements = declaring_branches(parent)
        if statements is None or any(LEFT_OUT in outcomes.get(s, [LEFT_OUT]) for s in statements):
            return None
        return parent

    def keep_left_out(self, statement: ast.stmt, items: list[tuple[Found, str]]) -> None:
        """A declare_parameters statement whose list is imported in part keeps the rest."""
        call = items[0][0].call
        if not (isinstance(statement, ast.Expr) and statement.value is call):
            return
        if not all(f.in_list and f.call is call for f, _ in items):
            return
        parent = self.parents.get(items[0][0].at)
        if not isinstance(parent, (ast.List, ast.Tuple)):
            return
        if any(self.parents.get(f.at) is not parent for f, _ in items):
            return
        kept = [f.at for f, o in items if o == LEFT_OUT]
        texts = [self.node.source[slice(*self.source.span(n))] for n in kept]
        start, end = self.source.span(parent)
        open_, close = ("[", "]") if isinstance(parent, ast.List) else ("(", ")")
        if parent.lineno == parent.end_lineno:
            text = open_ + ", ".join(texts) + ("," if len(texts) == 1 and close == ")" else "")
        else:
            inner = " " * getattr(kept[0], "col_offset", 4)
            last = self.source.lines[(parent.end_lineno or parent.lineno) - 1]
            outer = last[: len(last) - len(last.lstrip())]
            if not last.lstrip().startswith(close):
                outer = self.source.indent(statement)
            text = open_ + "\n" + "".join(f"{inner}{t},\n" for t in texts) + outer
        self.edits.append(Edit(start, end, text + close))
        self.kept.append(statement)

    def rewrite(self, statement: ast.stmt, founds: list[Found]) -> bool:
        """Rewrite one statement; True when it is removed."""
        if isinstance(statement, (ast.For, ast.If)) or (
            isinstance(statement, ast.Expr) and statement.value is founds[0].call
        ):
            self.remove(statement)
            return True
        for call in dict.fromkeys(f.call for f in founds):
            self.replace_use(call, [f for f in founds if f.call is call])
        return False

    def remove(self, statement: ast.stmt) -> None:
        span = self.source.line_span(statement)
        if span is None:
            start, end = self.source.span(statement)
            edit = Edit(start, end, "pass")
        else:
            edit = Edit(span[0], span[1], "")
        self.edits.append(edit)
        self.removals[statement] = edit
        self.removed.append(statement)

    def replace_use(self, call: ast.Call, founds: list[Found]) -> None:
        if isinstance(call.func, ast.Attribute) and call.func.attr == DECLARE_ONE:
            name = founds[0].name.value
            if isinstance(name, str) and self.typed_read_span(call, name) is not None:
                return
            start, end = self.source.span(call)
            quoted = self.name_text(call, founds[0])
            text = self.fitted(call, "self.get_parameter", [quoted], listed=False)
            self.edits.append(Edit(start, end, text))
            return
        start, end = self.source.span(call)
        names = [self.name_text(call, found) for found in founds]
        self.edits.append(Edit(start, end, self.fitted(call, "self.get_parameters", names)))

    def fitted(self, call: ast.Call, function: str, names: list[str], listed: bool = True) -> str:
        """``function(names)`` in place of ``call``, written as ruff format would, so that
        no line runs past LINE_LENGTH: on one line if the line fits, else the argument on
        a line of its own, else one name a line."""
        lines = self.source.lines
        end_line = call.end_lineno or call.lineno
        end_column = call.end_col_offset or call.col_offset
        first, last = lines[call.lineno - 1], lines[end_line - 1].rstrip("\r\n")
        before = first[: self.source.column(call.lineno, call.col_offset)]
        after = last[self.source.column(end_line, end_column) :]
        argument = f"[{', '.join(names)}]" if listed else names[0]
        text = f"{function}({argument})"
        if len(before) + len(text) + len(after) <= LINE_LENGTH:
            return text
        indent = first[: len(first) - len(first.lstrip())]
        inner = indent + "    "
        if len(inner) + len(argument) <= LINE_LENGTH or not listed:
            return f"{function}(\n{inner}{argument}\n{indent})"
        items = "".join(f"{inner}    {name},\n" for name in names)
        return f"{function}(\n{inner}[\n{items}{inner}]\n{indent})"

    def name_text(self, call: ast.Call, found: Found) -> str:
        """The declared name as source: a string literal, or for a name built from a
        loop's item an f-string of the same name (``f"wheels.{wheel}.radius"``)."""
        if found.name.problem is None:
            return self.quoted(call, found.name.value)
        place = item_place(found)
        if place is None or found.loop_variable is None:  # only such names are imported
            return self.quoted(call, str(found.name.value))
        parts = [place.head, "{" + found.loop_variable + "}", place.tail]
        if parts == ["", parts[1], ""]:
            return found.loop_variable
        return "f" + self.quoted(call, ".".join(p for p in parts if p))

    def quoted(self, call: ast.Call, text: str) -> str:
        """``text`` as a string literal in the quotes the call's source uses."""
        written = self.node.source[slice(*self.source.span(call))]
        double = written.find('"') != -1 and (
            written.find("'") == -1 or written.find('"') < written.find("'")
        )
        literal = repr(text)
        if double and '"' not in text and literal.startswith("'"):
            literal = '"' + literal[1:-1] + '"'
        return literal

    def typed_read_span(self, call: ast.Call, name: str) -> Edit | None:
        """``<call>.value`` or ``<call>.get_parameter_value().x_value`` -> a typed read."""
        outer = read_of(call, self.parents)
        if outer is None:
            return None
        start, end = self.source.span(outer)
        read = ".".join((f"self.{self.attribute}", *attribute_parts(name)))
        edit = Edit(start, end, read)
        self.edits.append(edit)
        return edit

    def place_declare(self, first: ast.stmt, declare: str, removed_first: bool) -> None:
        indent = self.source.indent(first)
        if removed_first:
            old = self.removals[first]
            self.edits.remove(old)
            text = f"{indent}{declare}\n" if old.text == "" else declare
            self.edits.append(Edit(old.start, old.end, text))
        else:
            start = self.source.starts[first.lineno - 1]
            self.edits.append(Edit(start, start, f"{indent}{declare}\n"))

    def drop_name_variables(self) -> None:
        """``key = 'tolerance.' + axis`` just before a declaration of ``key`` that went,
        when nothing else reads ``key``: it goes too."""
        for statement in list(self.removed):
            body = body_of(statement, self.parents)
            value = statement.value if isinstance(statement, ast.Expr) else None
            if body is None or not isinstance(value, ast.Call) or not value.args:
                continue
            name = value.args[0]
            index = body.index(statement)
            assigned = body[index - 1] if index > 0 else None
            if (
                not isinstance(name, ast.Name)
                or not isinstance(assigned, ast.Assign)
                or [ast.unparse(t) for t in assigned.targets] != [name.id]
            ):
                continue
            loads = [
                n for n in ast.walk(self.cls)
                if isinstance(n, ast.Name) and n.id == name.id and isinstance(n.ctx, ast.Load)
            ]  # fmt: skip
            if loads == [name] and assigned not in self.removed:
                self.remove(assigned)

    def drop_condition_variables(self, statements: Iterable[ast.stmt]) -> None:
        """``mode = self.declare_parameter('mode', 'a').value`` read only by the ``if``
        statements that went (the schema declares what they declared): it goes too."""
        for statement in statements:
            if statement in self.removed or not isinstance(statement, ast.Assign):
                continue
            target = statement.targets[0] if len(statement.targets) == 1 else None
            function = self.parents.get(statement)
            while function is not None and not isinstance(function, ast.FunctionDef):
                function = self.parents.get(function)
            if not isinstance(target, ast.Name) or function is None:
                continue
            if only_read_in(target.id, function, self.removed):
                start, end = self.source.span(statement)
                self.edits = [e for e in self.edits if not (start <= e.start and e.end <= end)]
                self.remove(statement)

    def fill_emptied(self, keep: ast.stmt | None) -> None:
        """A block whose every statement was removed gets ``pass``."""
        for statement in self.removed:
            body = body_of(statement, self.parents)
            if body is None or statement is not body[0] or keep in body:
                continue
            if not all(s in self.removed for s in body):
                continue
            old = self.removals[statement]
            self.edits.remove(old)
            text = f"{self.source.indent(statement)}pass\n" if old.text == "" else "pass"
            self.edits.append(Edit(old.start, old.end, text))

    def rewrite_reads(self) -> None:
        scope = Scope(class_name=self.cls.name)
        taken = [(e.start, e.end) for e in self.edits]
        reads = [(c, False) for c in self_calls(self.cls, "get_parameter")]
        reads += [(c, True) for c in self_calls(self.cls, "get_parameter_or")]
        for call, has_alternative in reads:
            arguments = len(call.args) + len(call.keywords)
            if not call.args or arguments > (2 if has_alternative else 1):
                continue
            try:
                name = Evaluator(scope).value(call.args[0])
            except UntranslatableError:
                continue
            if name not in self.names:
                continue
            # get_parameter_or gives its alternative for a parameter not set (or not
            # declared): the typed read says None there, so only one always set is read.
            if has_alternative and not always_set(self.node.imported.data, name):
                continue
            outer = read_of(call, self.parents)
            if outer is None:
                continue
            start, end = self.source.span(outer)
            if any(s < end and start < e for s, e in taken):
                continue
            read = ".".join((f"self.{self.attribute}", *attribute_parts(name)))
            self.edits.append(Edit(start, end, read))

    def add_import(self) -> None:
        package = (Path(self.file).parent / "__init__.py").is_file()
        module = ("." if package else "") + module_name(self.schema)
        line = f"from {module} import {self.class_name}\n"
        imports = [s for s in self.node.tree.body if isinstance(s, (ast.Import, ast.ImportFrom))]
        last = max((s.end_lineno or s.lineno for s in imports), default=0)
        at = self.source.starts[last]
        self.edits.append(Edit(at, at, line))
