#!/usr/bin/env python3
"""The rules of docs/dev/architecture.md ("Rules the sources keep") that a script can see:

  - <meshoptimizer.h> is included only under src/core/meshopt/;
  - no two classes or structs share a name across src/ and ui/ (nested ones count as Outer::Inner,
    ones local to a function by their own name);
  - no comment block in src/ or ui/ runs over 15 lines (figures and diaries go to docs/);
  - the files of src/core include each other without loops (a header and its .cpp count as one);
  - no source file runs over 600 lines;
  - no header outside src/core/meshopt/ includes the folder's door (meshopt/Meshopt.h), and at most
    MAX_DOOR_INCLUDERS source files outside it do; its internal header (meshopt/Reproduction.h)
    is included only inside the folder;
  - README.md has fewer than 250 lines (the rest goes to docs/user/ and docs/dev/);
  - every relative link and image of every .md file names a file that exists, and a #heading in it;
  - each layer includes only the layers below it (LAYER_INCLUDES): the core nothing but itself, the
    readers the core, batch runs the readers, the command line batch runs, the window the scene and
    readers, never the command line;
  - no function in src/ or ui/ runs over 80 lines, from its signature to its closing brace (lambdas count
    with the function around them; a short allowlist names the few left and why).

  scripts/check-sources.py [ROOT]      # prints each breach, exits 1 if there is one

Run by ctest (label `sources`), so CI keeps them true.
"""
import os
import re
import sys

MAX_COMMENT_LINES = 15
MAX_FILE_LINES = 600
# Who may ask meshoptimizer's folder for something: the builders, bounds, records and files that use
# its meshlets, bounds or simplification (9 today); a new one is a decision, not a side effect.
MAX_DOOR_INCLUDERS = 10
MAX_README_LINES = 250
MAX_FUNCTION_LINES = 80
# (file, function) still over MAX_FUNCTION_LINES, each with the reason it is left.
# None today.
LONG_FUNCTIONS_ALLOWED = {}
SOURCE_SUFFIXES = (".h", ".cpp")
# Per folder, the folders its quoted includes ("io/MeshReader.h") may name besides its own; the
# core's own headers are named without a folder or through core/ and meshopt/.
LAYER_INCLUDES = {
    "src/core": {"core", "meshopt", "lod", "optimizer"},
    "src/io": {"core", "io"},
    "src/batch": {"core", "io", "batch"},
    "src/scene": {"core", "scene"},
    "src/cli": {"core", "io", "batch", "cli"},
    "ui": {"core", "io", "scene"},
}


def source_files(root, folders):
    for folder in folders:
        for directory, _, names in sorted(os.walk(os.path.join(root, folder))):
            for name in sorted(names):
                if name.endswith(SOURCE_SUFFIXES):
                    path = os.path.join(directory, name)
                    yield os.path.relpath(path, root), open(path, encoding="utf-8").read().split("\n")


def meshoptimizer_includes(files):
    for path, lines in files:
        if path.startswith("src/") and not path.startswith("src/core/meshopt/"):
            for number, line in enumerate(lines, 1):
                if re.match(r"\s*#\s*include\s*<meshoptimizer\.h>", line):
                    yield f"{path}:{number}: <meshoptimizer.h> outside src/core/meshopt/"


CLASS = re.compile(r"^(\s*)(?:template\s*<[^>]*>\s*)?(?:class|struct)\s+(?:\[\[[^\]]*\]\]\s*)?([A-Za-z_][\w:]*)"
                   r"(?:\s+final)?\s*(?::[^;{]*)?\{")


def class_definitions(path, lines):
    """(qualified name, line) of every class or struct defined in a file. Namespaces are not indented
    here, so a definition at column 0 is at namespace scope; an indented one is nested in the
    enclosing class still open above it, or local to a function."""
    enclosing = []  # (indent, name) of the classes open above
    for number, line in enumerate(lines, 1):
        stripped = line.strip()
        if stripped.startswith("//"):
            continue
        indent = len(line) - len(line.lstrip())
        if enclosing and stripped.startswith("}") and indent == enclosing[-1][0]:
            enclosing.pop()
            continue
        match = CLASS.match(line)
        if not match:
            continue
        name = match.group(2)
        if indent == 0:
            qualified = name
        elif enclosing:
            qualified = enclosing[-1][1] + "::" + name
        else:
            qualified = name  # local to a function: still one class per name
        if not stripped.endswith("};"):
            enclosing.append((indent, qualified))
        yield qualified, number


def shared_class_names(files):
    where = {}
    for path, lines in files:
        for name, number in class_definitions(path, lines):
            where.setdefault(name, []).append(f"{path}:{number}")
    for name, places in sorted(where.items()):
        if len(places) > 1:
            yield f"class {name} is defined {len(places)} times: " + ", ".join(places)


def long_comments(files):
    for path, lines in files:
        run, start = 0, 0
        for number, line in enumerate(lines + [""], 1):
            if line.strip().startswith("//"):
                if run == 0:
                    start = number
                run += 1
                continue
            if run > MAX_COMMENT_LINES:
                yield f"{path}:{start}: a comment block of {run} lines (at most {MAX_COMMENT_LINES}; figures go to docs/)"
            run = 0
        for match in re.finditer(r"/\*.*?\*/", "\n".join(lines), re.S):
            if match.group(0).count("\n") + 1 > MAX_COMMENT_LINES:
                number = "\n".join(lines)[: match.start()].count("\n") + 1
                yield f"{path}:{number}: a /* */ comment of more than {MAX_COMMENT_LINES} lines"


def meshopt_door_includes(files):
    includers = []
    for path, lines in files:
        if path.startswith("src/core/meshopt/"):
            continue
        for number, line in enumerate(lines, 1):
            match = re.match(r'\s*#\s*include\s*"(?:core/)?meshopt/(\w+)\.h"', line)
            if not match:
                continue
            if match.group(1) != "Meshopt":
                yield f"{path}:{number}: meshopt/{match.group(1)}.h is the folder's own; ask meshopt/Meshopt.h"
            elif path.endswith(".h"):
                yield f"{path}:{number}: a header includes meshopt/Meshopt.h (declare what it needs instead)"
            else:
                includers.append(path)
    if len(includers) > MAX_DOOR_INCLUDERS:
        yield (f"{len(includers)} files include meshopt/Meshopt.h (at most {MAX_DOOR_INCLUDERS}): " + ", ".join(includers))


def long_files(files):
    for path, lines in files:
        if len(lines) - 1 > MAX_FILE_LINES:
            yield f"{path}: {len(lines) - 1} lines (at most about {MAX_FILE_LINES})"


def blank_comments_and_strings(text):
    """The text with comments, string and character literals replaced by spaces (newlines kept), so
    braces inside them do not count."""
    def blank(match):
        return re.sub(r"[^\n]", " ", match.group(0))
    pattern = re.compile(r'R"([^(\s]*)\(.*?\)\1"|//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', re.S)
    return pattern.sub(blank, text)


CONTAINER = re.compile(r"^(?:template\s*<.*>\s*)?(?:namespace|class|struct|union|enum|extern)\b", re.S)
FUNCTION_BODY = re.compile(r"\)\s*(?:const|override|final|noexcept|mutable|&&?|\s)*(?:->\s*[\w:<>,\s*&]+)?$")
LABEL_OR_MACRO = re.compile(r"^\s*(?:(?:public|private|protected)(?:\s+(?:slots|Q_SLOTS))?\s*:|signals\s*:|Q_\w+|#.*)\s*$")


def function_spans(lines):
    """(name, first line, last line) of every function body in a file: a `{` that follows a signature
    (text ending in `)`, perhaps with const/override/noexcept or a trailing return type) outside any
    function; namespace, class, enum and initialiser braces are walked through. The first line is the
    signature's first line; braces inside a function (blocks, lambdas) belong to it."""
    text = blank_comments_and_strings("\n".join(lines))
    scopes = []  # "container", "function" or "init" for each open brace
    statement_start = 0  # offset where the text before the next brace begins
    opened = []  # (name, start line) of the function open, if any
    line_of = lambda offset: text.count("\n", 0, offset) + 1
    for offset, char in enumerate(text):
        inside_function = "function" in scopes
        if char == ";" and not inside_function and (not scopes or scopes[-1] != "init"):
            statement_start = offset + 1
        elif char == "{":
            if inside_function:
                scopes.append("block")
                continue
            statement = text[statement_start:offset]
            kept = [line for line in statement.split("\n") if line.strip() and not LABEL_OR_MACRO.match(line)]
            signature = "\n".join(kept).strip()
            if CONTAINER.match(signature):
                scopes.append("container")
                statement_start = offset + 1
            elif FUNCTION_BODY.search(signature) and "(" in signature:
                scopes.append("function")
                first = statement_start + statement.index(kept[0]) + len(kept[0]) - len(kept[0].lstrip())
                operator = re.search(r"[\w:]*operator\s*(?:\(\)|[^\s(]+)", signature)
                name = [operator.group(0)] if operator else re.findall(r"([~\w:]+)\s*\(", signature.split("(")[0] + "(")
                lambdas = list(re.finditer(r"\[[^\[\]]*\]\s*\(", statement))
                if scopes[:-1] and scopes[-2] == "init" and lambdas:
                    first = statement_start + lambdas[-1].start()  # a lambda in a table: from its own line
                    name = ["lambda"]
                opened.append((name[-1] if name else "lambda", line_of(first)))
            else:
                scopes.append("init")  # `= {`, `member{value}`: part of the statement around it
        elif char == "}" and scopes:
            kind = scopes.pop()
            if kind == "function":
                name, start = opened.pop()
                yield name, start, line_of(offset)
            if kind in ("function", "container"):
                statement_start = offset + 1


def long_functions(files, allowed=None):
    allowed = LONG_FUNCTIONS_ALLOWED if allowed is None else allowed
    for path, lines in files:
        if not (path.startswith("src/") or path.startswith("ui/")):
            continue
        for name, first, last in function_spans(lines):
            length = last - first + 1
            if length > MAX_FUNCTION_LINES and (path, name) not in allowed:
                yield f"{path}:{first}: {name} runs {length} lines (at most {MAX_FUNCTION_LINES}; split it)"


def include_loops(root, files):
    """Loops among src/core's modules (a header and its .cpp together), following quoted includes."""
    def module(path):
        return os.path.splitext(path)[0]

    edges = {}
    for path, lines in files:
        if not path.startswith("src/core/"):
            continue
        for line in lines:
            match = re.match(r'\s*#\s*include\s*"([^"]+)"', line)
            if not match:
                continue
            for candidate in (os.path.join(os.path.dirname(path), match.group(1)), os.path.join("src", match.group(1))):
                candidate = os.path.normpath(candidate)
                if os.path.isfile(os.path.join(root, candidate)):
                    if module(candidate) != module(path):
                        edges.setdefault(module(path), set()).add(module(candidate))
                    break
    state, stack, loops = {}, [], []

    def visit(node):
        state[node] = "open"
        stack.append(node)
        for target in sorted(edges.get(node, ())):
            if state.get(target) == "open":
                loops.append(stack[stack.index(target):] + [target])
            elif target not in state:
                visit(target)
        stack.pop()
        state[node] = "done"

    for node in sorted(edges):
        if node not in state:
            visit(node)
    for loop in loops:
        yield "include loop: " + " -> ".join(loop)


def layer_includes(files):
    """Quoted includes that reach a layer above (src/batch naming cli/, src/core naming io/, ...)."""
    for path, lines in files:
        layer = next((folder for folder in LAYER_INCLUDES if path.startswith(folder + "/")), None)
        if layer is None:
            continue
        for number, line in enumerate(lines, 1):
            match = re.match(r'\s*#\s*include\s*"(\w+)/', line)
            if match and match.group(1) not in LAYER_INCLUDES[layer]:
                yield f"{path}:{number}: {layer} includes {match.group(1)}/ (a layer above it)"


def long_readme(root):
    lines = open(os.path.join(root, "README.md"), encoding="utf-8").read().count("\n")
    if lines >= MAX_README_LINES:
        yield f"README.md: {lines} lines (fewer than {MAX_README_LINES}; details go to docs/user/ and docs/dev/)"


LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)[^)]*\)|<img [^>]*src=\"([^\"]+)\"")


def heading_anchors(path):
    """GitHub's anchors of a markdown file's headings: lower case, punctuation dropped, spaces to dashes."""
    text = re.sub(r"^```.*?^```", "", open(path, encoding="utf-8").read(), flags=re.S | re.M)
    return {re.sub(r"[^\w\- ]", "", title.strip().lower()).replace(" ", "-")
            for title in re.findall(r"^#+\s+(.*)$", text, re.M)}


def broken_doc_links(root):
    """Relative links and images in the repository's .md files (not the fetched meshes or builds)."""
    for directory, folders, names in os.walk(root):
        folders[:] = sorted(f for f in folders if not f.startswith((".", "build")) and f not in ("cgal", "cgal-all", "props-debian"))
        for name in sorted(n for n in names if n.endswith(".md")):
            path = os.path.join(directory, name)
            text = re.sub(r"^```.*?^```", "", open(path, encoding="utf-8").read(), flags=re.S | re.M)
            for match in LINK.finditer(text):
                target = match.group(1) or match.group(2)
                if re.match(r"[a-z]+:", target):
                    continue
                file, _, anchor = target.partition("#")
                where = os.path.normpath(os.path.join(directory, file)) if file else path
                shown = os.path.relpath(path, root)
                if not os.path.exists(where):
                    yield f"{shown}: link to {target}: no such file"
                elif anchor and where.endswith(".md") and anchor not in heading_anchors(where):
                    yield f"{shown}: link to {target}: no such heading"


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    files = list(source_files(root, ["src", "ui"]))
    breaches = [*meshoptimizer_includes(files), *shared_class_names(files), *long_comments(files), *long_files(files),
                *include_loops(root, files), *meshopt_door_includes(files), *layer_includes(files), *long_readme(root), *broken_doc_links(root)]
    breaches += long_functions(files)
    for breach in breaches:
        print(breach)
    print(f"check-sources: {len(files)} files, {len(breaches)} breaches", file=sys.stderr)
    return 1 if breaches else 0


if __name__ == "__main__":
    sys.exit(main())
