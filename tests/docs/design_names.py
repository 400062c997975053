#!/usr/bin/env python3
"""ctest docs.design_names: every code name docs/design.md cites exists in the sources.

A design page that names code goes stale silently when the code is renamed; this keeps it honest.
What counts as a code name, taken from the page's text:
  - a file path, backticked or not (`cut/removal_loop.cpp`, engine/src/core/mesh_journal.cpp,
    tetcut/detail/local_tables.hpp): some file of the tree must end with it;
  - a backticked identifier, qualified or not, called or not (`Pipeline::attempt`,
    `CutRefusal::kQualityFloor`, `removability()`, `StampedSet`): each part must occur as a word
    in the sources, and for `A::b`, `b` in a source file that names `A`;
  - an unbackticked qualified name (Remover::remove): the same.
Backticked text that is not a name (a command line, an expression, a scenario line) is skipped.

usage: design_names.py SOURCE_DIR [DOC]     (DOC defaults to SOURCE_DIR/docs/design.md)
       design_names.py --self-test SOURCE_DIR   (a page citing missing names must fail)
"""
import os
import re
import sys

SOURCE_DIRS = ["engine", "geometry", "io", "mechanics", "invariants", "python", "tools", "bench",
               "fuzz", "tests", "ci", "cmake", "examples"]
SOURCE_EXT = (".cpp", ".hpp", ".h", ".py", ".pyi", ".cmake", ".txt", ".sh", ".json")
SKIP_DIRS = {".git", "build", "__pycache__"}
# What the page cites as a pattern to follow or as what the code does not use, not as code:
# "a reader `read_x(text, name)` in io/src/x.cpp", "no `random_device`".
NOT_CODE = {"read_x", "format_x", "io/src/x.cpp", "random_device"}

PATH_EXT = r"(?:cpp|hpp|h|py|pyi|md|txt|json|cmake|sh|dict)"
PATH_RE = re.compile(r"(?<![\w/.<>*-])((?:[A-Za-z_][\w.-]*/)*[A-Za-z_][\w-]*\." + PATH_EXT + r")(?![\w/])")
BACKTICK_RE = re.compile(r"`([^`\n]+)`")
# `A::b::c`, `name`, `name()`, `name(args)`, `ws.check`-style member uses are not names.
IDENT_RE = re.compile(r"^(?:[A-Za-z_]\w*::)*[A-Za-z_]\w*(?:\(.*\))?$")
QUALIFIED_RE = re.compile(r"(?<![\w:`])([A-Z]\w*(?:::[A-Za-z_]\w*)+)")


def source_files(root):
    files = []
    for top in [root] + [os.path.join(root, d) for d in SOURCE_DIRS]:
        if top == root:
            files += [os.path.join(root, f) for f in os.listdir(root) if os.path.isfile(os.path.join(root, f))]
            continue
        for d, subdirs, names in os.walk(top):
            subdirs[:] = [s for s in subdirs if s not in SKIP_DIRS]
            files += [os.path.join(d, n) for n in names]
    return files


def tree_paths(root):
    paths = []
    for d, subdirs, names in os.walk(root):
        subdirs[:] = [s for s in subdirs if s not in SKIP_DIRS and not (d == root and s.startswith("build"))]
        rel = os.path.relpath(d, root)
        paths += [n if rel == "." else rel.replace(os.sep, "/") + "/" + n for n in names]
    return paths


class Sources:
    def __init__(self, root):
        self.texts = {}
        this = os.path.realpath(__file__)  # its self-test's names are not the sources'
        for f in source_files(root):
            if os.path.realpath(f) == this:
                continue
            if f.endswith(SOURCE_EXT) or os.path.basename(os.path.dirname(f)) == "ci":
                try:
                    with open(f, encoding="utf-8", errors="replace") as fh:
                        self.texts[f] = fh.read()
                except OSError:
                    pass
        self.words = set()
        for text in self.texts.values():
            self.words.update(re.findall(r"[A-Za-z_]\w*", text))
        self.paths = tree_paths(root)
        self._files_naming = {}

    def has_path(self, path):
        return any(p == path or p.endswith("/" + path) for p in self.paths)

    def files_naming(self, word):
        if word not in self._files_naming:
            pat = re.compile(r"\b" + re.escape(word) + r"\b")
            self._files_naming[word] = [t for t in self.texts.values() if pat.search(t)]
        return self._files_naming[word]

    def has_name(self, name):
        name = re.sub(r"\(.*\)$", "", name)
        parts = name.split("::")
        if any(p not in self.words for p in parts):
            return False
        # A::b: b must occur where A is named (a member declared in A's file, or defined as A::b).
        for outer, inner in zip(parts, parts[1:]):
            pat = re.compile(r"\b" + re.escape(inner) + r"\b")
            if not any(pat.search(t) for t in self.files_naming(outer)):
                return False
        return True


def cited_names(doc_text):
    """(kind, name, line number) for every code name the page cites."""
    out = []
    for number, line in enumerate(doc_text.splitlines(), 1):
        # Markdown links' targets are pages, not code: [text](target.md#anchor).
        line = re.sub(r"\]\([^)]*\)", "]", line)
        for m in PATH_RE.finditer(line):
            path = m.group(1)
            if "/" in path or path.endswith((".cpp", ".hpp", ".h", ".py", ".pyi")):
                out.append(("path", path, number))
        for m in BACKTICK_RE.finditer(line):
            span = m.group(1).strip()
            if PATH_RE.fullmatch(span):
                continue  # a path, taken above
            if IDENT_RE.match(span) and len(span) > 1:
                out.append(("name", span, number))
        for m in QUALIFIED_RE.finditer(BACKTICK_RE.sub("", line)):
            out.append(("name", m.group(1), number))
    return out


def check(root, doc):
    with open(doc, encoding="utf-8") as fh:
        text = fh.read()
    sources = Sources(root)
    missing = []
    names = cited_names(text)
    for kind, name, number in names:
        if re.sub(r"\(.*\)$", "", name) in NOT_CODE:
            continue
        ok = sources.has_path(name) if kind == "path" else sources.has_name(name)
        if not ok:
            missing.append(f"{os.path.relpath(doc, root)}:{number}: {kind} `{name}` is not in the sources")
    return names, missing


def main(argv):
    if len(argv) >= 2 and argv[1] == "--self-test":
        import tempfile
        root = argv[2]
        page = ("`Cutter::Pipeline::attempt`, engine/src/cut/removal_loop.cpp and `TissueAudit::run` exist;\n"
                "`Pipeline::plan_and_apply`, cut/no_such_stage.cpp and `NoSuchType` do not.\n")
        with tempfile.NamedTemporaryFile("w", suffix=".md", delete=False) as fh:
            fh.write(page)
        try:
            names, missing = check(root, fh.name)
        finally:
            os.unlink(fh.name)
        found = {m.split("`")[1] for m in missing}
        expected = {"Pipeline::plan_and_apply", "cut/no_such_stage.cpp", "NoSuchType"}
        if found != expected:
            print(f"self-test: reported {sorted(found)}, expected {sorted(expected)}")
            return 1
        print(f"self-test: the {len(expected)} missing names of {len(names)} reported, no other")
        return 0
    root = argv[1]
    doc = argv[2] if len(argv) > 2 else os.path.join(root, "docs", "design.md")
    names, missing = check(root, doc)
    for m in missing:
        print(m)
    print(f"{len(names)} code names cited, {len(missing)} missing")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
