"""The one "did you mean" of genparams: schema keys, validator names, rule expressions,
remote sets and params-file entries all suggest a name the same way; and the one measure of
a slip between two names (node names of params-file sections)."""

from __future__ import annotations

from collections.abc import Iterable

# difflib's similarity ratio a word must reach to be offered; 0.6 is difflib's default.
CUTOFF = 0.6
# A leaf name alone is short, so a near miss of it must be closer to be offered.
LEAF_CUTOFF = 0.75


def closest(word: str, options: Iterable[str], *, cutoff: float = CUTOFF) -> str | None:
    """The option most like ``word``, or None when none is alike enough."""
    import difflib  # only an error message needs it: not loaded by a node that declares fine

    close = difflib.get_close_matches(word, sorted(options), n=1, cutoff=cutoff)
    return close[0] if close else None


def hint(suggestion: str | None) -> str:
    """`` (did you mean 'x'?)``, to append to a message, or ""."""
    return f" (did you mean {suggestion!r}?)" if suggestion is not None else ""


def did_you_mean(word: str, options: Iterable[str]) -> str:
    return hint(closest(word, options))


def did_you_mean_name(name: str, candidates: Iterable[str]) -> str:
    """The hint for a misspelt or misplaced dotted name (:func:`closest_name`)."""
    return hint(closest_name(name, candidates))


def closest_name(
    name: str, candidates: Iterable[str], *, separator: str = ".", by_leaf: bool = True
) -> str | None:
    """The candidate a misspelt or misplaced name (segments joined by ``separator``) meant:
    the one with the same last segment (moved to another namespace), else the closest
    whole name, else, ``by_leaf``, the one whose last segment is closest (misspelt deep in
    a namespace)."""
    candidates = sorted(candidates)
    last = name.rsplit(separator, 1)[-1]
    same_leaf = [c for c in candidates if c.rsplit(separator, 1)[-1] == last]
    if len(same_leaf) == 1:
        return same_leaf[0]
    found = closest(name, candidates)
    if found is None and by_leaf:
        leaves = {c.rsplit(separator, 1)[-1]: c for c in candidates}
        near = closest(last, leaves, cutoff=LEAF_CUTOFF)
        found = leaves[near] if near is not None else None
    return found


def numbered_copies(one: str, other: str) -> bool:
    """Names that differ only in digits (robot_1 and robot_2, joint1 and joint2): both real."""
    return len(one) == len(other) and all(
        a == b or (a.isdigit() and b.isdigit()) for a, b in zip(one, other, strict=True)
    )


def close_names(one: str, other: str) -> bool:
    """Names one slip apart (two for long names): a typo, a swap of two letters."""
    allowed = 1 if max(len(one), len(other)) < 8 else 2
    return edit_distance(one, other) <= allowed


def edit_distance(one: str, other: str) -> int:
    """Edits (insert, delete, replace, swap of neighbours) that turn ``one`` into ``other``."""
    rows = [list(range(len(other) + 1))]
    for i, a in enumerate(one, start=1):
        row = [i]
        for j, b in enumerate(other, start=1):
            cost = min(rows[-1][j] + 1, row[j - 1] + 1, rows[-1][j - 1] + (a != b))
            if i > 1 and j > 1 and a == other[j - 2] and one[i - 2] == b:
                cost = min(cost, rows[-2][j - 2] + 1)
            row.append(cost)
        rows.append(row)
    return rows[-1][-1]
