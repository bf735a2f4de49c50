#!/usr/bin/env python3
# SPDX-License-Identifier: BSL-1.0
"""Checks the public names of ParticleSystem and of ParticleSystem::StepView against a list.

Usage: public_names.py CLANG INCLUDE_DIR EXPECTED [--plant NAME]

Reads clang's AST of the class templates (the definitions, so every member counts whatever
configuration would enable it), collects the names each declares public (an overload set is one
name; constructors, destructor and assignment are not counted), and compares them with the
sections of EXPECTED. Fails naming each difference, and when a class has a public base (the
state and the facets are private bases, re-exported by name). --plant NAME adds NAME to the
names found, to prove that a name added to the class is caught.
"""
import re
import subprocess
import sys
import tempfile

CLASSES = {"ParticleSystem": "ParticleSystem", "StepView": "ParticleSystem::StepView"}
NAMED = re.compile(
    r"^(TypeAliasDecl|VarDecl|VarTemplateDecl|CXXMethodDecl|FunctionTemplateDecl|"
    r"UnresolvedUsingValueDecl|UnresolvedUsingTypenameDecl|UsingDecl|CXXRecordDecl|"
    r"TypeAliasTemplateDecl|FieldDecl)\b")


def ast_of(clang, include_dir, qualified):
    with tempfile.NamedTemporaryFile("w", suffix=".cpp") as source:
        source.write("#include <pointmass/particle_system.hpp>\n")
        source.flush()
        command = [clang, "-std=c++20", "-fsyntax-only", "-I", include_dir, "-Xclang",
                   "-ast-dump", "-Xclang", "-ast-dump-filter", "-Xclang", qualified,
                   source.name]
        out = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    out = re.sub(r"\x1b\[[0-9;]*m", "", out)
    # The dump of the class itself: from "Dumping pointmass::<qualified>:" to the next dump.
    # (The longest: a class declared before its definition is dumped once for each.)
    dumps = [dump.splitlines() for dump in re.split(r"^Dumping ", out, flags=re.M)
             if dump.startswith(f"pointmass::{qualified}:")]
    if not dumps:
        sys.exit(f"public_names: no AST for pointmass::{qualified}")
    return max(dumps, key=len)


def public_names(lines):
    """Names declared public directly in the class definition, and the public bases."""
    names, bases = set(), []
    access = None
    members = None  # the prefix width of the class's own members, once its definition is seen
    for line in lines:
        match = re.match(r"^((?:[| `]*)[|`]-)?(.*)$", line)
        prefix = len(match.group(1) or "")
        text = re.sub(r" 0x[0-9a-f]+", "", match.group(2))
        if members is None:
            if re.match(r"CXXRecordDecl .*\b(class|struct) \w+ definition", text):
                members = prefix + 2
                access = "public" if " struct " in f" {text} " else "private"
            continue
        if prefix < members:
            break  # past the class
        if prefix != members:
            continue
        base = re.match(r"(public|protected|private) '", text)
        if base:
            if base.group(1) == "public":
                bases.append(text)
            continue
        spec = re.match(r"AccessSpecDecl .* (public|protected|private)$", text)
        if spec:
            access = spec.group(1)
            continue
        if access != "public" or not NAMED.match(text) or " implicit " in text:
            continue
        text = re.sub(r"<[^<>]*>", "", text)  # the source range
        words = text.split()
        kind = words[0]
        # The name: after the location and flags; for using-declarations the part after ::.
        candidates = [w for w in words[1:] if re.match(r"^[A-Za-z_][\w:]*$", w) and not re.match(r"^(col|line):", w) and w not in (
            "col", "line", "referenced", "used", "class", "struct", "static", "inline",
            "constexpr", "cinit", "definition", "default", "typename")]
        if not candidates:
            continue
        name = candidates[0].split("::")[-1]
        if kind == "CXXMethodDecl" and " operator" in f" {text}":
            continue  # assignment, conversion: not names a user calls by name
        names.add(name)
    return names, bases


def expected_sections(path):
    sections, current = {}, None
    for raw in open(path, encoding="utf-8"):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        if line.startswith("["):
            current = line.strip("[]")
            sections[current] = set()
        else:
            sections[current].add(line)
    return sections


def main():
    clang, include_dir, expected_path = sys.argv[1:4]
    plant = sys.argv[5] if len(sys.argv) > 5 and sys.argv[4] == "--plant" else None
    expected = expected_sections(expected_path)
    failures = []
    for section, qualified in CLASSES.items():
        names, bases = public_names(ast_of(clang, include_dir, qualified))
        if plant and section == "ParticleSystem":
            names.add(plant)
        listed = expected.get(section, set()) | expected.get(f"{section} deprecated", set())
        for name in sorted(names - listed):
            failures.append(f"{qualified}: public name '{name}' is not in {expected_path}")
        for name in sorted(listed - names):
            failures.append(f"{qualified}: '{name}' is listed but not a public name")
        for base in bases:
            failures.append(f"{qualified}: public base {base}")
        current = len(expected.get(section, set()) & names)
        deprecated = len(expected.get(f"{section} deprecated", set()) & names)
        print(f"{qualified}: {current} public names, and {deprecated} deprecated")
    for failure in failures:
        print(failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
