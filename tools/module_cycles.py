#!/usr/bin/env python3
"""Import cycles between the modules of each crate (issue 17: "no import cycle").

One node per source file (lib.rs is the crate root, x/mod.rs is module x). An edge A -> B when A's
code (comments excluded) names a path that resolves to module B: `crate::…`, `super::…`, `self::…`,
the groups of `use crate::{a, b::c}`, and in lib.rs / mod.rs a `use child::…` of its own child. A
path resolves to the longest module prefix it names; `mod x;` declarations are containment, not
edges. An item named through a module that only re-exports it (`pub use`, a facade such as lib.rs or a
mod.rs) resolves to the module that defines it, so a facade does not make a cycle by itself.

Usage: tools/module_cycles.py [CRATE_SRC_DIR ...] (default: every crates/*/src). Prints each cycle
(a strongly connected component of more than one module) and exits 1 if there is any.

`--folders CRATE_SRC_DIR ...` checks coarser nodes: each top-level module of the crate with all its
children (a folder such as `compare/`, or a single file), so two folders that import each other
through any of their files are a cycle (issue 44 item 6: the app's features each in one folder,
none importing another both ways). Method calls on a type another folder extends (`impl Lab` in
`api/`) are not paths and are not seen.
"""
import os
import re
import sys


def modules(src):
    mods = {}
    for dirpath, _, files in os.walk(src):
        for f in files:
            if not f.endswith(".rs"):
                continue
            rel = os.path.relpath(os.path.join(dirpath, f), src)[:-3].split(os.sep)
            if rel in (["lib"], ["main"]):
                key = ()
            elif rel[-1] == "mod":
                key = tuple(rel[:-1])
            else:
                key = tuple(rel)
            mods[key] = os.path.join(dirpath, f)
    return mods


def strip(text):
    text = re.sub(r'"(?:[^"\\\n]|\\.)*"', '""', text)
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return "\n".join(line.split("//")[0] for line in text.split("\n"))


def expand_groups(code):
    """`crate::a::{b, c::d}` -> `crate::a::b crate::a::c::d` (one level of nesting at a time)."""
    group = re.compile(r"((?:\$?\bcrate|\b\w+)(?:::\w+)*)::\{([^{}]*)\}")
    while True:
        new = group.sub(lambda m: " ".join(f"{m.group(1)}::{p.strip()}" for p in m.group(2).split(",") if p.strip()), code)
        if new == code:
            return code
        code = new


def reexports(mods):
    """What each module re-exports: `pub use a::b::Item;` in module M -> {(M, Item): path}, the
    path made absolute (a facade's child, `crate::…`, `super::…`)."""
    out = {}
    for m, path in mods.items():
        is_dir = path.endswith(("mod.rs", "lib.rs", "main.rs"))
        code = strip(open(path).read())
        paths = []
        for statement in re.findall(r"pub(?:\([^)]*\))?\s+use\s+([^;]+);", code):
            for item in expand_groups(statement).split():
                item = re.sub(r"\s+as\s+\w+$", "", item)
                m_ = re.match(r"((?:\$?crate|super|self)?)((?:::)?[\w:]+)$", item)
                if m_:
                    paths.append((m_.group(1), m_.group(2)))
        for prefix, body in paths:
            segs = [x for x in body.split("::") if x]
            if not segs:
                continue
            if prefix.endswith("crate"):
                full = segs
            elif prefix == "super":
                # The parent of a directory module and of a file module alike.
                full = list(m[:-1]) + segs
            elif prefix == "self":
                full = list(m) + segs
            elif is_dir:
                full = list(m) + segs
            else:
                continue
            out[(m, segs[-1])] = full
    return out


def macro_homes(mods):
    """`#[macro_export]` macros are named at the crate root but live where they are defined."""
    homes = {}
    for m, path in mods.items():
        text = open(path).read()
        for name in re.findall(r"#\[macro_export\][^\n]*\n(?:\s*#\[[^\n]*\n)*\s*macro_rules!\s*(\w+)", text):
            homes[name] = m
    return homes


def graph(mods):
    roots = reexports(mods)
    macros = macro_homes(mods)

    def resolve(segs, depth=0):
        best, k_best = None, 0
        for k in range(len(segs) + 1):
            if tuple(segs[:k]) in mods:
                best, k_best = tuple(segs[:k]), k
        # An item the module only re-exports is used from where it is defined.
        if best is not None and k_best < len(segs) and depth < 8:
            full = roots.get((best, segs[k_best]))
            if full is not None:
                return resolve(full + segs[k_best + 1:], depth + 1)
        return best

    edges = {m: set() for m in mods}
    path_re = re.compile(r"(\$?\bcrate|\bsuper|\bself)((?:::\w+)+)")
    for m, path in mods.items():
        code = expand_groups(strip(open(path).read()))
        is_dir = path.endswith(("mod.rs", "lib.rs", "main.rs"))
        here = list(m) if is_dir else list(m[:-1])
        for line in code.split("\n"):
            own = re.match(r"\s*(?:pub(?:\([^)]*\))?\s+)?use\s+(\w+)((?:::\w+)*)", line)
            if own and is_dir and (m + (own.group(1),)) in mods:
                target = resolve(list(m) + [own.group(1)] + own.group(2).split("::")[1:])
                if target is not None and target != m:
                    edges[m].add(target)
            for root, rest in path_re.findall(line):
                segs = rest.split("::")[1:]
                if root.endswith("crate") and segs and segs[0] in macros:
                    if macros[segs[0]] != m:
                        edges[m].add(macros[segs[0]])
                    continue
                if root.endswith("crate"):
                    full = segs
                elif root == "self":
                    full = list(m) + segs if is_dir else list(m) + segs
                else:
                    base = list(m[:-1]) if is_dir else list(m[:-1])
                    full = (here[:-1] if is_dir else base) + segs
                target = resolve(full)
                if target is not None and target != m:
                    edges[m].add(target)
    return edges


def sccs(g):
    index, low, on, stack, out, counter = {}, {}, set(), [], [], [0]
    sys.setrecursionlimit(10000)

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in g[v]:
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
                out.append(comp)

    for v in sorted(g):
        if v not in index:
            visit(v)
    return out


def folder_graph(edges):
    """The module graph with each module folded into its top-level module (`()` is the root)."""
    top = lambda m: m[:1]
    out = {}
    for a, targets in edges.items():
        out.setdefault(top(a), set())
        for b in targets:
            out.setdefault(top(b), set())
            if top(a) != top(b):
                out[top(a)].add(top(b))
    return out


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    folders = bool(argv) and argv[0] == "--folders"
    if folders:
        argv = argv[1:]
    dirs = argv or sorted(
        os.path.join(here, "..", "crates", c, "src")
        for c in os.listdir(os.path.join(here, "..", "crates"))
        if os.path.isdir(os.path.join(here, "..", "crates", c, "src"))
    )
    found = 0
    for src in dirs:
        mods = modules(src)
        crate = os.path.basename(os.path.dirname(os.path.normpath(src)))
        g = graph(mods)
        for comp in sccs(folder_graph(g) if folders else g):
            found += 1
            names = sorted("crate" if not m else "::".join(m) for m in comp)
            print(f"cycle in {crate}: {' <-> '.join(names)}")
    what = "folder" if folders else "module"
    print(f"module_cycles: {found} {what} cycle(s) in {len(dirs)} crate(s)")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
