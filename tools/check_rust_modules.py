"""Fails (exit 1) on any module cycle inside a Rust crate (the core; also the bindings): the layout
rule of ARCHITECTURE.md is that modules depend downward only (``error`` ← ``limits`` ← ``state`` ←
``model/`` ← ``integrate/`` …).

The graph is read from the source, comments and strings stripped: every path that starts with
``crate::``, ``super::`` or ``self::`` — in ``use`` declarations (groups ``{a, b::c}`` expanded) and
inline in code, outside ``#[cfg(test)]`` modules — is an edge from the file to the module the path
names (the longest prefix that is a module file). A name a ``mod.rs`` re-exports
(``pub use child::Name``) is followed to the child that defines it, and re-exports themselves are not
edges (a parent listing its children is not a dependency of the design). Two levels are checked:
files (``model::registry`` → ``state``) and top-level modules (``model`` → ``state``, every file of
a directory taken together); a cycle at either level fails.

Usage: ``python tools/check_rust_modules.py [SRC_DIR]`` (default ``crates/pendulab-core/src``).
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

# comments, string and char literals in one pass (a `//` inside a string is not a comment)
TOKENS = re.compile(r'//[^\n]*|/\*.*?\*/|\bb?r#*".*?"#*|"(?:\\.|[^"\\])*"|\'(?:\\.|[^\'\\])\'', re.S)
USE = re.compile(r"\b(pub(?:\([^)]*\))?\s+)?use\s+([^;]+);")
TESTS = re.compile(r"#\[cfg\(test\)\]\s*mod\s+\w+\s*\{")
INLINE = re.compile(r"\b((?:crate|super|self)(?:::[A-Za-z_][A-Za-z0-9_]*)+)")


def strip_tests(text: str) -> str:
    """The text without its ``#[cfg(test)] mod … { … }`` blocks (a unit test that compares with a
    sibling is not a dependency of the design)."""
    while m := TESTS.search(text):
        depth, i = 0, m.end() - 1
        while i < len(text):
            depth += {"{": 1, "}": -1}.get(text[i], 0)
            i += 1
            if depth == 0:
                break
        text = text[: m.start()] + text[i:]
    return text


def module_files(src: Path) -> dict[str, Path]:
    """Module path (``model::registry``; the crate root is ``""``) → file."""
    out: dict[str, Path] = {}
    for path in sorted(src.rglob("*.rs")):
        parts = list(path.relative_to(src).with_suffix("").parts)
        if parts[-1] in ("mod", "lib", "main"):
            parts = parts[:-1]
        out["::".join(parts)] = path
    return out


def expand(tree: str) -> list[str]:
    """``a::{b, c::{d, e}}`` → ``a::b``, ``a::c::d``, ``a::c::e`` (``self`` in a group is the prefix)."""
    tree = re.sub(r"\s+", "", tree)
    m = re.match(r"^(.*?)\{(.*)\}$", tree)
    if not m:
        return [re.sub(r"as\w+$", "", tree) if "as" not in tree else tree.split("as")[0]]
    prefix, body = m.group(1), m.group(2)
    parts, depth, cur = [], 0, ""
    for ch in body:
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
            continue
        depth += ch == "{"
        depth -= ch == "}"
        cur += ch
    parts.append(cur)
    out: list[str] = []
    for p in filter(None, parts):
        for e in expand(p):
            out.append(prefix.rstrip(":") if e == "self" else prefix + e)
    return out


def absolute(module: str, path: str) -> list[str] | None:
    """The segments of ``path`` from the crate root, or None for an external crate. ``self`` is the
    module itself and ``super`` its parent, for ``a/b.rs`` and ``a/mod.rs`` alike."""
    segs = path.split("::")
    here = module.split("::") if module else []
    if segs[0] == "crate":
        return segs[1:]
    if segs[0] == "self":
        return here + segs[1:]
    if segs[0] == "super":
        cur, segs = here[:-1], segs[1:]
        while segs and segs[0] == "super":
            cur, segs = cur[:-1], segs[1:]
        return cur + segs
    return None


def parse(src: Path) -> tuple[dict[str, Path], dict[str, set[str]]]:
    files = module_files(src)
    texts = {m: strip_tests(TOKENS.sub(" ", p.read_text(encoding="utf-8"))) for m, p in files.items()}
    # re-exports of each module: name → the module it comes from
    reexports: dict[str, dict[str, list[str]]] = {m: {} for m in files}
    for m, text in texts.items():
        for pub, tree in USE.findall(text):
            if not pub:
                continue
            for item in expand(tree):
                segs = item.split("::")
                if segs[0] not in ("crate", "super", "self"):
                    segs = ["self", *segs]  # `pub use child::Name` is relative in edition 2018+
                full = absolute(m, "::".join(segs))
                if full:
                    reexports[m][full[-1]] = full

    def resolve(segs: list[str], depth: int = 0) -> str | None:
        for k in range(len(segs), -1, -1):
            mod = "::".join(segs[:k])
            if mod in files:
                rest = segs[k:]
                if rest and depth < 8 and rest[0] in reexports[mod]:
                    target = reexports[mod][rest[0]]
                    if target != segs:
                        return resolve(target + rest[1:], depth + 1)
                return mod
        return None

    edges: dict[str, set[str]] = {m: set() for m in files}
    for m, text in texts.items():
        paths: list[str] = []
        for pub, tree in USE.findall(text):
            if pub:
                continue
            paths += [p for p in expand(tree) if p.split("::")[0] in ("crate", "super", "self")]
        code = USE.sub("", text)
        paths += INLINE.findall(code)
        for p in paths:
            full = absolute(m, p)
            target = resolve(full) if full is not None else None
            if target is not None and target != m and target != "":
                edges[m].add(target)
    return files, edges


def cycles(edges: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one node (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    out: list[list[str]] = []
    counter = [0]

    def visit(v: str) -> None:
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(edges):
        if v not in index:
            visit(v)
    return out


def main(argv: list[str]) -> int:
    src = Path(argv[1]) if len(argv) > 1 else Path("crates/pendulab-core/src")
    files, edges = parse(src)
    top: dict[str, set[str]] = {}
    for m, targets in edges.items():
        a = m.split("::")[0]
        top.setdefault(a, set()).update(t.split("::")[0] for t in targets if t.split("::")[0] != a)
    # inside a directory, a child's use of its parent's items (super::Model) is not a cycle with the
    # parent's own code only when the parent uses no child: checked like any other pair
    bad = [("file", c) for c in cycles(edges)] + [("top-level module", c) for c in cycles(top)]
    for level, comp in bad:
        graph = edges if level == "file" else top
        inner = [f"{a} -> {b}" for a in comp for b in sorted(graph.get(a, set())) if b in comp]
        print(f"{src}: module cycle ({level}): {', '.join(comp)}\n    edges: {'; '.join(inner)}")
    if bad:
        return 1
    n_edges = sum(len(t) for t in edges.values())
    print(f"{src}: no module cycle ({len(files)} files, {n_edges} edges, {len(top)} top-level modules)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
