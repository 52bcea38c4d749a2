#!/usr/bin/env python3
"""Each registry is the only list of its names (docs/extending.md).

vahf has three registries of things a file may name: the steppers
(simulation/integrator), the contact models (contact/model) and the
experiment kinds. Their names are read here from the generated indices that
tests keep current with the registries (docs/parameters.md, docs/kinds.md),
and the code under src/, tools/, tests/ and bench/ is searched for two ways
a second list creeps in:

  selection  code under src/ or tools/ that compares a stepper, model or kind
             selector with a name ("c.model != \"shell\"", "kind == \"paper\""):
             the registry entry should carry the fact instead;
  list       one statement whose string literals name three or more of one
             registry's names ({"table1", "fatigue", "precision"}, or an error
             message listing them) under src/, tools/ or bench/, or nearly every
             name (all but one at most) under tests/: it should ask the registry.
             A test may pick a few names to exercise; a list of every name goes
             stale, unnoticed, when a name is added.

A registry's own file (the one list) is exempt from its own names. Prints one
line per finding, FILE:LINE: what and why; exit status 1 if there is any.

Usage: registry_names.py REPO_ROOT
"""

import os
import re
import sys

# A registry: where the check reads its names (a generated index and how to
# find them there) and the file that is its one list.
REGISTRIES = {
    "stepper": ("docs/parameters.md", r"^\| `simulation/integrator` \| - \| ([^|]+) \|",
                "src/vahf/scene/steppers.def"),
    "contact model": ("docs/parameters.md", r"^\| `contact/model` \| - \| ([^|]+) \|",
                      "src/vahf/contact/contact_registry.cc"),
    "kind": ("docs/kinds.md", r"^\| `([a-z0-9_]+)` \|", "src/vahf/kinds/kinds.def"),
}
# The field of an entry that selects it by name.
SELECTORS = r"(?:(?:\.|->)(?:model|integrator|kind)|\[\"(?:model|integrator|kind)\"\])"
SCANNED = ("src", "tools", "tests", "bench")
CPP = (".h", ".cc", ".def", ".cpp")
SCRIPT = (".py", ".sh")


def registry_names(root):
    out = {}
    for registry, (index, pattern, own) in REGISTRIES.items():
        path = os.path.join(root, index)
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            sys.exit("registry_names.py: cannot read %s: %s" % (index, e))
        found = re.findall(pattern, text, re.M)
        names = set()
        for cell in found:
            names.update(n.strip() for n in cell.split(","))
        if len(names) < 2:
            sys.exit("registry_names.py: %s lists fewer than 2 %s names (pattern %s)" %
                     (index, registry, pattern))
        out[registry] = (names, own)
    return out


def strip_comments(text, ext):
    """The text with comments blanked (line numbers kept); strings kept."""
    out, i, n = [], 0, len(text)
    quote = None
    while i < n:
        c = text[i]
        if quote:
            out.append(c)
            if c == "\\" and i + 1 < n:
                out.append(text[i + 1])
                i += 2
                continue
            if c == quote or c == "\n":
                quote = None
            i += 1
            continue
        if c in "\"'":
            # A C++ digit separator or char literal is harmless either way.
            quote = c
            out.append(c)
            i += 1
            continue
        if ext in CPP and text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        if ext in CPP and text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
            continue
        if ext in SCRIPT and c == "#" and (i == 0 or text[i - 1] in " \t\n;(") \
                and not text.startswith("#!", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        out.append(c)
        i += 1
    return "".join(out)


def statements(text, ext):
    """(first line, text) of each statement: for C++ cut at ';' and at a
    brace that opens or closes a block (one ending or starting a line); for
    scripts a logical line (joined while a bracket is open)."""
    lines = text.split("\n")
    out, start, buf, depth = [], 1, [], 0
    for number, line in enumerate(lines, 1):
        if not buf:
            start = number
        if ext in CPP:
            pieces = re.split(r";|\{\s*$|^\s*\}", line)
            for k, piece in enumerate(pieces):
                buf.append(piece)
                if k + 1 < len(pieces):
                    out.append((start, "\n".join(buf)))
                    buf, start = [], number
        else:
            buf.append(line)
            depth += len(re.findall(r"[\[({]", line)) - len(re.findall(r"[\])}]", line))
            if depth <= 0 or len(buf) > 60:
                out.append((start, "\n".join(buf)))
                buf, depth = [], 0
    if buf:
        out.append((start, "\n".join(buf)))
    return out


LITERAL = re.compile(r'"((?:[^"\\\n]|\\.)*)"|\'((?:[^\'\\\n]|\\.)*)\'')


def findings(root):
    registries = registry_names(root)
    found = []
    for top in SCANNED:
        for folder, dirs, files in os.walk(os.path.join(root, top)):
            dirs[:] = sorted(d for d in dirs if d not in ("corpus", "__pycache__"))
            for name in sorted(files):
                ext = os.path.splitext(name)[1]
                if ext not in CPP + SCRIPT:
                    continue
                path = os.path.join(folder, name)
                rel = os.path.relpath(path, root)
                if rel == "tests/tools/registry_names.py":
                    continue
                with open(path, encoding="utf-8", errors="replace") as f:
                    text = strip_comments(f.read(), ext)
                found += file_findings(rel, text, ext, registries)
    return found


def file_findings(rel, text, ext, registries):
    out = []
    if ext in CPP and rel.split("/")[0] in ("src", "tools"):
        for registry, (names, own) in registries.items():
            if rel == own:
                continue
            alternatives = "|".join(re.escape(n) for n in sorted(names))
            pattern = re.compile(
                r'%s\s*[!=]=\s*(?:std::string\()?"(%s)"|"(%s)"\s*[!=]=\s*[\w.>\[\]"-]*%s' %
                (SELECTORS, alternatives, alternatives, SELECTORS))
            for number, line in enumerate(text.split("\n"), 1):
                for m in pattern.finditer(line):
                    out.append("%s:%d: selects the %s %s by name: let its registry entry "
                               "carry what differs" % (rel, number, registry,
                                                       m.group(1) or m.group(2)))
    for start, statement in statements(text, ext):
        literals = [a or b for a, b in LITERAL.findall(statement)]
        if not literals:
            continue
        words = set(re.findall(r"[A-Za-z0-9_]+", " ".join(literals)))
        for registry, (names, own) in registries.items():
            if rel == own:
                continue
            hits = sorted(names & words)
            least = 3 if not rel.startswith("tests/") else max(3, len(names) - 1)
            if len(hits) >= least:
                out.append("%s:%d: a second list of %s names (%s): ask the registry" %
                           (rel, start, registry, ", ".join(hits)))
    return out


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    found = findings(sys.argv[1])
    for line in found:
        print(line)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
