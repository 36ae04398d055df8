#!/usr/bin/env python3
"""Layout rules of the repository, checked from its files (README.md, "Contributing").

  structure_check.py REPO CHECK      CHECK: includes | mains | length | format | report

includes  no file under services/X includes a header of services/Y, except
          robot_sim -> lms100_emulator (robot_sim runs the emulated device) and anyone
          -> world_renderer (a library folder); common/ is for everyone. Prints the
          include graph (service -> services it includes).
mains     every services/*/main.cpp has at most 100 lines and no function over 40.
          Prints each main's size and longest function, the largest first.
length    a C++ file over 300 lines states why within its first 5 lines, in a comment
          containing "longer than 300 lines because".
format    clang-format --dry-run -Werror (the repo's .clang-format) accepts every C++ file.
report    includes, mains and length together, never failing: the numbers to quote.
Exit 0 when the check holds, 1 with one line per offence.
"""

import os
import re
import subprocess
import sys

MAIN_MAX_LINES = 100
MAIN_MAX_FUNCTION_LINES = 40
FILE_MAX_LINES = 300
REASON_MARKER = re.compile(r"longer than 300 lines because", re.IGNORECASE)
REASON_WITHIN_LINES = 5
# (from, to) service folders allowed to include each other; "*" = any folder.
ALLOWED_INCLUDES = {("robot_sim", "lms100_emulator"), ("*", "world_renderer")}
CPP_SUFFIXES = (".cpp", ".hpp", ".h", ".cc")


def cpp_files(repo):
    """Tracked and new (not ignored) C++ files that exist, relative to repo."""
    out = subprocess.run(["git", "-C", repo, "ls-files", "--cached", "--others", "--exclude-standard"],
                         check=True, capture_output=True, text=True).stdout.split()
    return sorted(f for f in set(out) if f.endswith(CPP_SUFFIXES) and os.path.isfile(os.path.join(repo, f)))


def read(repo, path):
    with open(os.path.join(repo, path), encoding="utf-8", errors="replace") as f:
        return f.read()


# ---- includes -------------------------------------------------------------------------

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.MULTILINE)


def service_of(path):
    parts = path.split("/")
    return parts[1] if len(parts) > 2 and parts[0] == "services" else None


def resolve(repo, source, header):
    """The repo-relative file an #include "header" of source means (the build's include
    path: the including folder, the repo root, services/), or None."""
    for base in (os.path.dirname(source), "", "services"):
        candidate = os.path.normpath(os.path.join(base, header))
        if os.path.isfile(os.path.join(repo, candidate)):
            return candidate
    return None


def include_graph(repo):
    """{(from_service, to_service): [(file, header), ...]} over services/*."""
    edges = {}
    for path in cpp_files(repo):
        src = service_of(path)
        if not src:
            continue
        for header in INCLUDE.findall(read(repo, path)):
            target = resolve(repo, path, header)
            dst = service_of(target) if target else None
            if dst and dst != src:
                edges.setdefault((src, dst), []).append((path, header))
    return edges


def allowed(src, dst):
    return (src, dst) in ALLOWED_INCLUDES or ("*", dst) in ALLOWED_INCLUDES


def check_includes(repo, report_only=False):
    edges = include_graph(repo)
    services = sorted(d for d in os.listdir(os.path.join(repo, "services"))
                      if os.path.isdir(os.path.join(repo, "services", d)))
    print("include graph (service -> services whose headers it includes; * = not allowed):")
    for s in services:
        targets = sorted(dst for (src, dst) in edges if src == s)
        shown = [f"{t}{'' if allowed(s, t) else '*'} ({len(edges[(s, t)])})" for t in targets]
        print(f"  {s} -> {', '.join(shown) if shown else '(none)'}")
    bad = [(k, v) for k, v in sorted(edges.items()) if not allowed(*k)]
    for (src, dst), uses in bad:
        for path, header in uses:
            print(f"FORBIDDEN: {path} includes \"{header}\" (services/{src} -> services/{dst})")
    print(f"{len(bad)} forbidden service -> service edge(s)")
    return 0 if report_only or not bad else 1


# ---- functions in main.cpp ------------------------------------------------------------

def strip_comments_and_strings(text):
    """Same line structure, comments and string/char literals blanked."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
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
            end = text.find(")" + (m.group(1) if m else "") + '"', i)
            j = n if end < 0 else end + len(m.group(1) if m else "") + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + (c if j < n else ""))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(text):
    """[(name, first_line, last_line)] of the function bodies outside other functions:
    a '{' at namespace or class scope whose head (text since the last ';', '{' or '}')
    has a '(' and is not a namespace/class/struct/enum. Lines are 1-based, from the
    head's first line to the closing brace."""
    code = strip_comments_and_strings(text)
    result, stack, head_start = [], [], 0
    line_of = lambda pos: code.count("\n", 0, pos) + 1
    for pos, c in enumerate(code):
        if c in ";{}":
            head = code[head_start:pos]
            if c == "{":
                in_function = any(kind == "function" for kind, _, _ in stack)
                words = head.strip()
                is_type = re.match(r"^(template\s*<.*>\s*)?(namespace|class|struct|union|enum|extern)\b", words, re.S)
                kind = "function" if not in_function and "(" in words and not is_type else "block"
                first = pos - len(head) + (len(head) - len(head.lstrip()))
                name_match = re.search(r"(operator\s*\S+?|[\w:~]+)\s*\(", words)
                stack.append((kind, line_of(first), name_match.group(1) if name_match else words[:30]))
            elif c == "}" and stack:
                kind, first_line, name = stack.pop()
                if kind == "function":
                    result.append((name, first_line, line_of(pos)))
            head_start = pos + 1
    return result


def main_stats(repo):
    """[(path, lines, (name, length) of the longest function)] for services/*/main.cpp."""
    stats = []
    for path in cpp_files(repo):
        if service_of(path) and path.endswith("/main.cpp") and path.count("/") == 2:
            text = read(repo, path)
            funcs = [(name, last - first + 1) for name, first, last in functions(text)]
            longest = max(funcs, key=lambda f: f[1]) if funcs else ("-", 0)
            stats.append((path, text.count("\n"), longest, funcs))
    return sorted(stats, key=lambda s: -s[1])


def check_mains(repo, report_only=False):
    stats = main_stats(repo)
    offences = []
    print(f"services/*/main.cpp (limit {MAIN_MAX_LINES} lines, functions {MAIN_MAX_FUNCTION_LINES} lines):")
    for path, lines, (name, length), funcs in stats:
        print(f"  {path}: {lines} lines, longest function {name}() {length} lines")
        if lines > MAIN_MAX_LINES:
            offences.append(f"TOO LONG: {path} has {lines} lines (at most {MAIN_MAX_LINES})")
        for fname, flen in funcs:
            if flen > MAIN_MAX_FUNCTION_LINES:
                offences.append(f"TOO LONG: {path}: {fname}() has {flen} lines (at most {MAIN_MAX_FUNCTION_LINES})")
    if stats:
        path, lines, (name, length), _ = stats[0]
        longest = max(stats, key=lambda s: s[2][1])
        print(f"largest main.cpp: {path}, {lines} lines, its longest function {name}() {length} lines")
        print(f"longest function of any main.cpp: {longest[0]}: {longest[2][0]}() {longest[2][1]} lines")
    for o in offences:
        print(o)
    print(f"{len(offences)} main.cpp offence(s)")
    return 0 if report_only or not offences else 1


# ---- file length ----------------------------------------------------------------------

def check_length(repo, report_only=False):
    long_files, offences = [], []
    for path in cpp_files(repo):
        text = read(repo, path)
        lines = text.count("\n")
        if lines <= FILE_MAX_LINES:
            continue
        head = "\n".join(text.split("\n")[:REASON_WITHIN_LINES])
        reason = REASON_MARKER.search(head)
        long_files.append((path, lines, bool(reason)))
        if not reason:
            offences.append(f"NO REASON: {path} has {lines} lines and no \"longer than 300 lines because\" "
                            f"in its first {REASON_WITHIN_LINES} lines")
    print(f"C++ files over {FILE_MAX_LINES} lines: {len(long_files)}")
    for path, lines, reason in sorted(long_files, key=lambda f: -f[1]):
        print(f"  {path}: {lines} lines{'' if reason else ' (no reason stated)'}")
    for o in offences:
        print(o)
    print(f"{len(offences)} file(s) over {FILE_MAX_LINES} lines without a stated reason")
    return 0 if report_only or not offences else 1


# ---- clang-format ---------------------------------------------------------------------

def check_format(repo):
    files = cpp_files(repo)
    failing = []
    for i in range(0, len(files), 50):
        batch = files[i:i + 50]
        r = subprocess.run(["clang-format", "--dry-run", "-Werror", *batch], cwd=repo, capture_output=True, text=True)
        if r.returncode != 0:
            failing += sorted({line.split(":")[0] for line in r.stderr.splitlines() if ": error:" in line})
    for f in failing:
        print(f"NOT FORMATTED: {f} (clang-format -i {f})")
    print(f"clang-format: {len(files) - len(failing)} of {len(files)} C++ files clean")
    return 1 if failing else 0


def main(argv):
    if len(argv) != 3 or argv[2] not in ("includes", "mains", "length", "format", "report"):
        print(__doc__, file=sys.stderr)
        return 64
    repo, check = argv[1], argv[2]
    if check == "includes":
        return check_includes(repo)
    if check == "mains":
        return check_mains(repo)
    if check == "length":
        return check_length(repo)
    if check == "format":
        return check_format(repo)
    check_includes(repo, True)
    check_mains(repo, True)
    check_length(repo, True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
