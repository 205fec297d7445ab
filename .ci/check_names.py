#!/usr/bin/env python3
"""Checks that no public name of bevy_sprung shadows one of Bevy's prelude.

Every type, trait, alias, function, constant and macro that bevy_sprung exports (including
the property markers its `spring_property!` invocations define) is looked up in
`bevy::prelude` by a probe file that imports each one from there: a name that resolves
would collide with `use bevy::prelude::*` in a user's crate. The probe is compiled as a
temporary integration test of the root package (whose Bevy features are already built)
and removed afterwards. Exits 1 on a collision, printing the names.
"""
import glob
import os
import re
import subprocess
import sys

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
names = set()
# Types at any depth (some live in inline modules); functions and constants at the top level
# only (indented ones are methods and associated constants, which no glob import brings in).
item = re.compile(r"^\s*pub (?:struct|enum|trait|type|static) ([A-Za-z_][A-Za-z0-9_]*)", re.M)
free = re.compile(r"^pub (?:const |)(?:fn|const) ([A-Za-z_][A-Za-z0-9_]*)", re.M)
marker = re.compile(r"spring_property!\(\s*(?:///[^\n]*\n\s*)*pub(?:\([a-z]+\))? ([A-Za-z0-9_]+)")
macro = re.compile(r"macro_rules! ([a-z_]+)")
for path in glob.glob(os.path.join(root, "crates/bevy_sprung/src/**/*.rs"), recursive=True):
    text = open(path, encoding="utf-8").read()
    # Doc comments and examples name things that are not exports.
    code = "\n".join(line for line in text.splitlines() if not line.lstrip().startswith("//"))
    names.update(item.findall(code))
    names.update(name for name in free.findall(code) if name != "fn")
    names.update(marker.findall(code))
    names.update(macro.findall(code))
names = sorted(names)
probe = os.path.join(root, "tests", "zz_name_probe.rs")
with open(probe, "w", encoding="utf-8") as out:
    out.write("//! Temporary: written and removed by .ci/check_names.py.\n#![allow(unused_imports)]\n")
    for i, name in enumerate(names):
        out.write(f"use bevy::prelude::{name} as _probe_{i};\n")
try:
    result = subprocess.run(
        ["cargo", "check", "--test", "zz_name_probe", "--message-format", "short"],
        cwd=root, capture_output=True, text=True,
    )
finally:
    os.remove(probe)
unresolved = set(re.findall(r"no `([A-Za-z0-9_]+)` in `prelude`", result.stderr))
if not unresolved:
    print(result.stderr[-2000:])
    print("check_names: the probe did not report unresolved imports; cannot tell", file=sys.stderr)
    sys.exit(1)
shadowing = [name for name in names if name not in unresolved]
if shadowing:
    print("bevy_sprung exports names that Bevy's prelude has:", ", ".join(shadowing), file=sys.stderr)
    sys.exit(1)
print(f"check_names: none of bevy_sprung's {len(names)} public names is in bevy::prelude")
