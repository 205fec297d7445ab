#!/usr/bin/env python3
"""Checks bevy_sprung's layering: the mechanism stands below its features.

Every `use` of the crate's own items (`crate::…`, `super::…`, `self::…`, also `pub use` and
paths inside braces) is resolved to the file that holds the module it names, the longest module
path that is a file of the crate. Two rules, each failure printed with the import that breaks it:

1. No file under `crates/bevy_sprung/src/spring/` imports a feature module, nor the top-level
   plugin (`plugin.rs`): the mechanism may import only `space/`, `clock`, `property`
   and itself.
2. No two files import each other in a circle (a strongly connected component of more than one
   file, or a file importing itself is not counted).
3. One clock: only `clock.rs` reads Bevy's `Time` (every other file reads time through
   `SpringTime`), so that everything timed follows the spring clock.

`mod` declarations are structure, not imports. Exits 1 on a failure.
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SRC = os.path.join(ROOT, "crates", "bevy_sprung", "src")
# What the mechanism may import besides itself.
BELOW_SPRING = {"space", "clock", "property"}


def module_of(path):
    """The module path of a source file: `spring/component/step.rs` -> ['spring', 'component',
    'step']; `lib.rs` -> []; `spring/mod.rs` -> ['spring']."""
    rel = os.path.relpath(path, SRC)[:-3].split(os.sep)
    if rel[-1] in ("mod", "lib"):
        rel = rel[:-1]
    return rel


def file_of(module):
    """The file that holds `module` (a list of names), or None."""
    base = os.path.join(SRC, *module) if module else os.path.join(SRC, "lib")
    for candidate in (base + ".rs", os.path.join(base, "mod.rs")):
        if os.path.isfile(candidate):
            return candidate
    if not module:
        return os.path.join(SRC, "lib.rs")
    return None


def expand(tree):
    """The paths of one `use` tree: `a::{b, c::{d, e}}` -> ['a::b', 'a::c::d', 'a::c::e']."""
    tree = tree.strip()
    depth, start = 0, None
    for i, ch in enumerate(tree):
        if ch == "{":
            if depth == 0:
                start = i
            depth += 1
        elif ch == "}":
            depth -= 1
    if start is None:
        return [tree]
    prefix, inner = tree[:start], tree[start + 1:tree.rindex("}")]
    parts, depth, current = [], 0, ""
    for ch in inner:
        if ch == "," and depth == 0:
            parts.append(current)
            current = ""
            continue
        depth += ch == "{"
        depth -= ch == "}"
        current += ch
    parts.append(current)
    paths = []
    for part in parts:
        if part.strip():
            paths.extend(prefix + path for path in expand(part))
    return paths


def strip(text):
    """The code of a file: comments (doc examples among them) and the contents of string and
    character literals removed, so that only code is searched for paths."""
    out, i, n = [], 0, len(text)
    while i < n:
        ch, two = text[i], text[i:i + 2]
        if two == "//":
            while i < n and text[i] != "\n":
                i += 1
        elif two == "/*":
            depth = 0
            while i < n:
                if text[i:i + 2] == "/*":
                    depth, i = depth + 1, i + 2
                elif text[i:i + 2] == "*/":
                    depth, i = depth - 1, i + 2
                    if depth == 0:
                        break
                else:
                    i += 1
        elif ch == "r" and re.match(r'r#*"', text[i:]) and not (i and (text[i - 1].isalnum() or text[i - 1] == "_")):
            hashes = re.match(r"r(#*)\"", text[i:]).group(1)
            end = text.find('"' + hashes, i + 2 + len(hashes))
            out.append('""')
            i = n if end < 0 else end + 1 + len(hashes)
        elif ch == '"':
            i += 1
            while i < n and text[i] != '"':
                i += 2 if text[i] == "\\" else 1
            out.append('""')
            i += 1
        elif ch == "'" and (text[i + 1:i + 2] == "\\" or text[i + 2:i + 3] == "'"):
            end = text.find("'", i + 2 if text[i + 1] != "\\" else i + 3)
            out.append("' '")
            i = end + 1
        else:
            out.append(ch)
            i += 1
    return "".join(out)


def imports(path):
    """(module path imported, the text) for each reference to the crate's own items: `use`
    statements, and paths written in the code (`crate::a::b(…)`, `super::c::D`)."""
    code = strip(open(path, encoding="utf-8").read())
    file_module = module_of(path)
    inline = inline_modules(code)

    def module_at(position):
        """The module path at `position`: the file's, inside any inline `mod name { … }`."""
        return file_module + [name for start, end, name in inline if start < position < end]

    statements = [(m.start(), m.group(1)) for m in re.finditer(r"\buse\s+([^;]+);", code)]
    rest = re.sub(r"\buse\s+[^;]+;", lambda m: " " * len(m.group(0)), code)
    # A visibility (`pub(in crate::ui)`) names a module but imports nothing.
    rest = re.sub(r"\bpub\s*\(\s*in\s+[^)]*\)", lambda m: " " * len(m.group(0)), rest)
    # A `#[macro_export]` macro lives at the crate root by the language's rule: the file that
    # defines it calling it as `$crate::name!` names itself, not the root.
    own_macros = set(re.findall(r"\bmacro_rules!\s*(\w+)", code))
    paths = [(m.start(), m.group(0))
             for m in re.finditer(r"\b(?:crate|super|self)(?:\s*::\s*\w+)+\b(?!\s*!)", rest)]
    paths += [(m.start(), m.group(0)[1:])
              for m in re.finditer(r"\$crate\s*::\s*(\w+)(?=\s*!)", rest)
              if m.group(1) not in own_macros]
    found = []
    for position, statement in statements + paths:
        here = module_at(position)
        for item in expand(" ".join(statement.split())):
            item = re.sub(r"\s+as\s+\w+$", "", item.strip())
            names = [name for name in item.split("::") if name]
            if not names:
                continue
            if names[0] == "crate":
                module = names[1:]
            elif names[0] in ("super", "self"):
                module = list(here)
                while names and names[0] in ("super", "self"):
                    if names.pop(0) == "super":
                        module = module[:-1]
                module = module + names
            elif file_of(here + names[:1]):
                # A path from a child module (`use drag::X`, `pub use drag::X` in the file that
                # declares `mod drag`): an edge to that child's file.
                module = here + names
            else:
                continue
            found.append((module, item))
    return found


def inline_modules(code):
    """(start, end, name) of each inline module `mod name { … }` of a file's code, outermost
    first."""
    spans = []
    for match in re.finditer(r"\bmod\s+(\w+)\s*\{", code):
        depth, i = 0, match.end() - 1
        while i < len(code):
            depth += code[i] == "{"
            depth -= code[i] == "}"
            if depth == 0:
                break
            i += 1
        spans.append((match.start(), i, match.group(1)))
    return spans


def resolve(module):
    """The file of the longest prefix of `module` that is a file of the crate."""
    for length in range(len(module), -1, -1):
        target = file_of(module[:length])
        if target:
            return target
    return None


def main():
    if sys.argv[1:] == ["--self-test"]:
        self_test()
        return
    failures, count, files = check(SRC)
    if failures:
        print("check_layers:\n" + "\n".join(failures), file=sys.stderr)
        sys.exit(1)
    print(f"check_layers: {len(files)} files, {count} imports between them, no circle; "
          "spring/ imports no feature; only clock.rs reads Bevy's Time")


def self_test():
    """Proves the check on crates written for it: each forms a circle through one kind of
    import (a child's re-export, `crate::`, `super::`), and a crate without a circle passes."""
    import tempfile
    global SRC
    cases = {
        "a child re-exported by its parent, the child using the parent": {
            "lib.rs": "mod a;\npub use a::Thing;\npub struct Root;\n",
            "a.rs": "use crate::Root;\npub struct Thing(Root);\n",
        },
        "two features through crate:: paths": {
            "lib.rs": "mod a;\nmod b;\n",
            "a.rs": "use crate::b::B;\npub struct A;\n",
            "b.rs": "pub(crate) fn f() -> crate::a::A { crate::a::A }\npub struct B;\n",
        },
        "a macro that calls another file's macro at the root": {
            "lib.rs": "mod a;\nmod b;\npub use a::A;\n",
            "a.rs": "#[macro_export]\nmacro_rules! m { () => { $crate::n!(); } }\npub struct A;\n",
            "b.rs": "#[macro_export]\nmacro_rules! n { () => {} }\nuse crate::A;\n",
        },
        "a module and its child through super::": {
            "lib.rs": "mod m;\n",
            "m/mod.rs": "mod c;\npub use c::C;\npub struct M;\n",
            "m/c.rs": "use super::M;\npub struct C(M);\n",
        },
    }
    clean = {
        "lib.rs": "mod a;\nmod b;\npub use b::B;\n",
        "a.rs": "pub struct A;\n",
        "b.rs": "use crate::a::A;\npub struct B(A);\n"
        "#[macro_export]\nmacro_rules! m { () => {}; (x) => { $crate::m!(); } }\n",
    }
    saved = SRC
    try:
        for name, files in list(cases.items()) + [("no circle", clean)]:
            with tempfile.TemporaryDirectory() as root:
                for path, text in files.items():
                    os.makedirs(os.path.dirname(os.path.join(root, path)), exist_ok=True)
                    with open(os.path.join(root, path), "w", encoding="utf-8") as out:
                        out.write(text)
                SRC = root
                failures, _, _ = check(root)
                found = any("circle" in failure for failure in failures)
                if found != (files is not clean):
                    print(f"check_layers self-test failed: {name}: {failures}", file=sys.stderr)
                    sys.exit(1)
    finally:
        SRC = saved
    print(f"check_layers self-test: {len(cases)} circles found, a clean crate passes")


def check(src):
    """The failures, the number of imports between files, and the files of the crate at
    `src`."""
    files = []
    for directory, _, names in os.walk(src):
        files.extend(os.path.join(directory, name) for name in names if name.endswith(".rs"))
    edges = {path: {} for path in files}
    failures = []
    for path in sorted(files):
        here = module_of(path)
        for module, text in imports(path):
            target = resolve(module)
            if target is None or target == path:
                continue
            edges[path].setdefault(target, text)
            if here[:1] == ["spring"]:
                top = module_of(target)[:1]
                if top and top[0] not in BELOW_SPRING | {"spring"}:
                    failures.append(
                        f"{os.path.relpath(path, SRC)} imports the feature `{top[0]}`: use {text}"
                    )
                elif target == os.path.join(SRC, "plugin.rs"):
                    failures.append(
                        f"{os.path.relpath(path, SRC)} imports the top-level plugin: use {text}"
                    )
    for path in sorted(files):
        if os.path.relpath(path, src) != "clock.rs":
            code = strip(open(path, encoding="utf-8").read())
            if re.search(r"\bTime\b", code):
                failures.append(
                    f"{os.path.relpath(path, src)} reads Bevy's `Time`: read `SpringTime` instead"
                )
    # Tarjan's strongly connected components.
    index, low, stack, on_stack, components = {}, {}, [], set(), []
    counter = [0]

    def connect(node):
        index[node] = low[node] = counter[0]
        counter[0] += 1
        stack.append(node)
        on_stack.add(node)
        for target in edges[node]:
            if target not in index:
                connect(target)
                low[node] = min(low[node], low[target])
            elif target in on_stack:
                low[node] = min(low[node], index[target])
        if low[node] == index[node]:
            component = []
            while True:
                top = stack.pop()
                on_stack.discard(top)
                component.append(top)
                if top == node:
                    break
            components.append(component)

    sys.setrecursionlimit(10000)
    for node in sorted(edges):
        if node not in index:
            connect(node)
    for component in components:
        if len(component) > 1:
            members = set(component)
            lines = [
                f"  {os.path.relpath(a, SRC)} -> {os.path.relpath(b, SRC)}: use {text}"
                for a in sorted(component)
                for b, text in edges[a].items()
                if b in members
            ]
            failures.append("files that import each other in a circle:\n" + "\n".join(lines))
    count = sum(len(targets) for targets in edges.values())
    return failures, count, files


if __name__ == "__main__":
    main()
