#!/usr/bin/env python3
"""Structure rules the code keeps, checked on every test run.

    check_structure.py SOURCE_DIR

- layering: machine/ includes nothing of parix/ or apps/; parix/ nothing of apps/ (apps -> parix -> machine);
- the runtime's API: a header directly in parix/ (processor.hpp, backend.hpp, ...) includes nothing of the simulated
  backend (parix/sim/), which implements the API and is one backend among others;
- size: no source file of machine/, parix/ or apps/ over 450 lines (generated-looking data tables, *_data.hpp, aside);
- functions: no function body over 80 lines.

Function bodies are found by reading the code as text: comments, strings and preprocessor lines are blanked, then
every brace block opened right after a parameter list `)` (with qualifiers such as const, noexcept, override or a
trailing return type) outside any other function body is a function; its length is the lines from its `{` to its `}`.
"""
import pathlib
import re
import sys

MAX_FILE_LINES = 450
MAX_FUNCTION_LINES = 80
SOURCES = ("machine", "parix", "apps")
LAYERS = {"machine": ("parix/", "apps/"), "parix": ("apps/",)}
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)
# What may stand between a parameter list's ')' and the body's '{'.
# A header of the runtime's API (directly in parix/) and the backend folder it must not include.
API_HEADER = re.compile(r"^parix/[^/]+\.(?:hpp|h)$")
API_MUST_NOT_INCLUDE = "parix/sim/"
QUALIFIERS = re.compile(r"^\s*(?:const|noexcept(?:\([^)]*\))?|override|final|mutable|&&?|->\s*[\w:<>,\s*&]+|\s)*$")


def blank_comments_and_strings(text):
    """The text with comments, string and character literals and preprocessor lines replaced by spaces
    (newlines kept, so line numbers hold)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i) or (c == "#" and (i == 0 or text[i - 1] == "\n")):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(" " * (j - i))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def long_functions(text):
    """(first line, lines) of each function body longer than MAX_FUNCTION_LINES."""
    code = blank_comments_and_strings(text)
    found, stack = [], []  # stack: for each open brace, whether it opened a function body
    for i, c in enumerate(code):
        if c == "{":
            inside_function = any(stack)
            close = code.rfind(")", 0, i)
            is_function = (not inside_function and close >= 0 and QUALIFIERS.match(code[close + 1:i]) is not None)
            stack.append(i if is_function else None)
        elif c == "}" and stack:
            start = stack.pop()
            if start is not None:
                first = code.count("\n", 0, start) + 1
                lines = code.count("\n", start, i) + 1
                if lines > MAX_FUNCTION_LINES:
                    found.append((first, lines))
    return found


def include_problems(rel, text):
    """The includes of the file at rel (relative to the source root) that break the layering or the API rule."""
    top = rel.split("/")[0]
    problems = []
    for inc in INCLUDE.findall(text):
        if any(inc.startswith(bad) for bad in LAYERS.get(top, ())):
            problems.append(f"{rel}: includes {inc}: {top}/ must not depend on {inc.split('/')[0]}/")
        elif API_HEADER.match(rel) and inc.startswith(API_MUST_NOT_INCLUDE):
            problems.append(f"{rel}: includes {inc}: the runtime's API headers must not depend on the simulated "
                            f"backend ({API_MUST_NOT_INCLUDE})")
    return problems


def main(root):
    problems = []
    for top in SOURCES:
        for path in sorted((root / top).rglob("*")):
            if path.suffix not in (".cpp", ".hpp", ".h", ".c") or path.name.endswith("_data.hpp"):
                continue
            rel = path.relative_to(root).as_posix()
            text = path.read_text(encoding="utf-8", errors="replace")
            problems += include_problems(rel, text)
            lines = text.count("\n")
            if lines > MAX_FILE_LINES:
                problems.append(f"{rel}: {lines} lines (at most {MAX_FILE_LINES}: split it by concept)")
            for first, length in long_functions(text):
                problems.append(f"{rel}:{first}: a function of {length} lines (at most {MAX_FUNCTION_LINES})")
    for p in problems:
        print(p)
    print(f"structure: {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(pathlib.Path(sys.argv[1]).resolve()))
