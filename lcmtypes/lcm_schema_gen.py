#!/usr/bin/env python3
"""Generate the bounds checkers of the refloc LCM types from their .lcm files.

  lcm_schema_gen.py OUT_DIR FILE.lcm...

Writes into OUT_DIR:
  refloc_lcm_schemas.hpp   one LcmSchema table a type (common/lcm_schema.hpp), LCM-free
  refloc_lcm_schemas.cpp   the tables: fields in wire order, fingerprints, per-array maxima
  refloc_lcm_samples.hpp   fill_lcm_sample(message, n) for tests and fuzz seeds (includes lcmtypes)

The limits live in the .lcm files: every variable-length array and every string carries a
comment that starts with "max N" on its own line, e.g.

  float ranges[nranges];                // max 4096; [m] ...
  string state_detail;                  // max 4096; why the state
  string counter_names[ncounters];      // max 128 x 256

For an array N is the most elements, for a string the most characters (the NUL excluded);
"max N x M" bounds an array of strings: N strings of at most M characters.
A missing limit is an error naming file and line, so no field is ever unbounded. The
fingerprint is computed the way lcm-gen computes it (lcmgen.c: lcm_struct_hash, and the
generated _computeHash); tests/common compares it with every type's getHash(), which proves
this parser reads the same fields in the same order as lcm-gen. Comments do not enter the
fingerprint.
"""

import os
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from lcm_fingerprint import fingerprint  # noqa: E402

PRIMITIVE_BYTES = {"int8_t": 1, "byte": 1, "boolean": 1, "int16_t": 2, "int32_t": 4, "int64_t": 8,
                   "float": 4, "double": 8}
PRIMITIVE_KIND = {"int8_t": "kInt8", "byte": "kByte", "boolean": "kBoolean", "int16_t": "kInt16",
                  "int32_t": "kInt32", "int64_t": "kInt64", "float": "kFloat", "double": "kDouble",
                  "string": "kString"}
INTEGER_TYPES = ("int8_t", "int16_t", "int32_t", "int64_t")
CPP_TYPE = {"int8_t": "int8_t", "byte": "uint8_t", "boolean": "int8_t", "int16_t": "int16_t",
            "int32_t": "int32_t", "int64_t": "int64_t", "float": "float", "double": "double"}
MEMBER = re.compile(r"^([A-Za-z_][\w.]*)\s+([A-Za-z_]\w*)((?:\s*\[\s*\w+\s*\])*)\s*;$")
MAX_COMMENT = re.compile(r"^\s*max\s+(\d+)(?:\s*x\s*(\d+))?\b")


class SchemaError(Exception):
    pass


class Member:
    def __init__(self, type_name, name, dims, limit, where):
        self.type_name, self.name, self.dims, self.where = type_name, name, dims, where
        self.variable = bool(dims) and not dims[0].isdigit()
        first = int(limit.group(1)) if limit else None
        second = int(limit.group(2)) if limit and limit.group(2) else None
        # "max N" bounds an array's count or a string's characters; "max N x M" is N strings of M.
        self.max_count = first if self.variable else None
        self.max_chars = (second if self.variable else first) if type_name == "string" else None

    @property
    def primitive(self):
        return self.type_name in PRIMITIVE_BYTES or self.type_name == "string"


class Struct:
    def __init__(self, package, name, path):
        self.package, self.name, self.path, self.members = package, name, path, []


def strip_block_comments(text):
    return re.sub(r"/\*.*?\*/", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text, flags=re.S)


def parse_file(path):
    text = strip_block_comments(open(path, encoding="utf-8").read())
    package, struct, structs = "", None, []
    for number, raw in enumerate(text.split("\n"), 1):
        where = f"{path}:{number}"
        code, _, comment = raw.partition("//")
        code = code.strip()
        if not code:
            continue
        if m := re.match(r"^package\s+([\w.]+)\s*;$", code):
            package = m.group(1)
        elif m := re.match(r"^struct\s+(\w+)\s*\{?$", code):
            struct = Struct(package, m.group(1), path)
            structs.append(struct)
        elif code in ("{", "}", "};"):
            continue
        elif code.startswith("const "):
            continue  # constants are not on the wire
        elif struct and (m := MEMBER.match(code)):
            type_name = m.group(1).split(".")[-1]
            dims = re.findall(r"\[\s*(\w+)\s*\]", m.group(3))
            struct.members.append(Member(type_name, m.group(2), dims, MAX_COMMENT.match(comment), where))
        else:
            raise SchemaError(f"{where}: cannot read '{code}' (one member a line: type name[dim];)")
    return structs


def check(structs):
    by_name = {s.name: s for s in structs}
    for s in structs:
        seen = {}
        for index, m in enumerate(s.members):
            if not m.primitive and m.type_name not in by_name:
                raise SchemaError(f"{m.where}: unknown type {m.type_name}")
            if len(m.dims) > 1:
                raise SchemaError(f"{m.where}: {m.name}: multi-dimensional arrays are not supported")
            if m.variable:
                length = seen.get(m.dims[0])
                if length is None or s.members[length].type_name not in INTEGER_TYPES or s.members[length].dims:
                    raise SchemaError(f"{m.where}: {m.name}[{m.dims[0]}]: the length must be an integer member declared before")
            if m.variable and m.max_count is None:
                raise SchemaError(f"{m.where}: {m.name}[] has no limit: start its comment with 'max N'")
            if m.type_name == "string" and m.max_chars is None:
                form = "max N x M (N strings of at most M characters)" if m.variable else "max N (characters)"
                raise SchemaError(f"{m.where}: string {m.name} has no limit: start its comment with '{form}'")
            seen[m.name] = index
    visiting = set()

    def visit(name):
        if name in visiting:
            raise SchemaError(f"{by_name[name].path}: {name} contains itself")
        visiting.add(name)
        for m in by_name[name].members:
            if not m.primitive:
                visit(m.type_name)
        visiting.discard(name)
    for s in structs:
        visit(s.name)
    return by_name


def min_bytes(name, by_name):
    total = 0
    for m in by_name[name].members:
        count = int(m.dims[0]) if m.dims and m.dims[0].isdigit() else (0 if m.dims else 1)
        one = 5 if m.type_name == "string" else PRIMITIVE_BYTES.get(m.type_name) or min_bytes(m.type_name, by_name)
        total += count * one
    return total


def ordered(by_name):
    """Types so that a nested type's table comes before its users'."""
    out = []

    def add(name):
        if name in out:
            return
        for m in by_name[name].members:
            if not m.primitive:
                add(m.type_name)
        out.append(name)
    for name in sorted(by_name):
        add(name)
    return out


HEADER = "// Generated by lcmtypes/lcm_schema_gen.py from lcmtypes/*.lcm; do not edit.\n"


def write_schemas_hpp(by_name, namespace):
    lines = [HEADER, "#pragma once\n", '#include "common/lcm_schema.hpp"\n',
             f"namespace {namespace} {{"]
    lines += [f"class {n};" for n in sorted(by_name)]
    lines += ["", "/// Every type generated from lcmtypes/, for tests and fuzz targets: X(type_name)."]
    lines.append("#define REFLOC_LCM_TYPES(X) " + " ".join(f"X({n})" for n in sorted(by_name)))
    lines.append("/// The same as a comma-separated list of the qualified types (testing::Types<...>).")
    lines.append("#define REFLOC_LCM_TYPE_LIST " + ", ".join(f"{namespace}::{n}" for n in sorted(by_name)))
    lines.append("")
    lines += [f"template <>\nconst LcmSchema& lcm_schema_of<{n}>();" for n in sorted(by_name)]
    lines += ["", f"}}  // namespace {namespace}", ""]
    return "\n".join(lines)


def field_line(s, m, by_name):
    names = [x.name for x in s.members]
    fixed = 0 if m.variable else (int(m.dims[0]) if m.dims else 1)
    kind = PRIMITIVE_KIND.get(m.type_name, "kStruct")
    nested = f"&kSchema_{m.type_name}" if kind == "kStruct" else "nullptr"
    length = names.index(m.dims[0]) if m.variable else -1
    max_count = m.max_count if m.variable else fixed
    max_string = m.max_chars if m.type_name == "string" else 0
    return (f'    {{"{m.name}", LcmFieldKind::{kind}, {nested}, {fixed}, {length}, {max_count}, {max_string}}},')


def write_schemas_cpp(by_name, namespace):
    lines = [HEADER, '#include "refloc_lcm_schemas.hpp"\n', f"namespace {namespace} {{", "namespace {", ""]
    for name in ordered(by_name):
        s = by_name[name]
        lines.append(f"// {os.path.basename(s.path)}")
        lines.append(f"const LcmFieldSchema kFields_{name}[] = {{")
        lines += [field_line(s, m, by_name) for m in s.members]
        lines.append("};")
        lines.append(f'const LcmSchema kSchema_{name} = {{"{name}", 0x{fingerprint(name, by_name):016x}ULL, '
                     f"kFields_{name}, {len(s.members)}, {min_bytes(name, by_name)}}};")
        lines.append("")
    lines += ["}  // namespace", ""]
    for name in sorted(by_name):
        lines += [f"template <>\nconst LcmSchema& lcm_schema_of<{name}>() {{\n  return kSchema_{name};\n}}", ""]
    lines += [f"}}  // namespace {namespace}", ""]
    return "\n".join(lines)


def sample_value(m, index):
    if m.type_name == "boolean":
        return "1"
    if m.type_name in ("float", "double"):
        return f"{index}.25"
    return f"{index % 100 + 1}"


def fill_statements(s, by_name):
    out, lengths = [], {m.dims[0] for m in s.members if m.dims and not m.dims[0].isdigit()}
    for index, m in enumerate(s.members, 1):
        if m.name in lengths:
            out.append(f"  m.{m.name} = static_cast<{CPP_TYPE[m.type_name]}>(n);")
            continue
        if m.type_name == "string":
            element = f'std::string("{m.name}")'
        elif m.primitive:
            element = f"static_cast<{CPP_TYPE[m.type_name]}>({sample_value(m, index)})"
        else:
            element = None
        if not m.dims:
            out.append(f"  fill_lcm_sample(m.{m.name}, n);" if element is None else f"  m.{m.name} = {element};")
            continue
        count = m.dims[0] if m.dims[0].isdigit() else "static_cast<size_t>(n)"
        if not m.dims[0].isdigit():
            out.append(f"  m.{m.name}.resize({count});")
        if element is None:
            out.append(f"  for (auto& e : m.{m.name}) fill_lcm_sample(e, n);")
        else:
            out.append(f"  for (auto& e : m.{m.name}) e = {element};")
    return out


def write_samples_hpp(by_name, package, namespace):
    lines = [HEADER, "#pragma once", "// Test and fuzz-seed helper: a message of every type with every variable array",
             "// n elements long and every other field set. Includes the lcm-gen headers.\n",
             "#include <cstddef>", "#include <cstdint>", "#include <string>\n"]
    lines += [f"#include <{package}/{n}.hpp>" for n in sorted(by_name)]
    lines += ["", f"namespace {namespace} {{", ""]
    lines += [f"inline void fill_lcm_sample({n}& m, int32_t n);" for n in sorted(by_name)]
    lines.append("")
    for name in sorted(by_name):
        lines.append(f"inline void fill_lcm_sample({name}& m, int32_t n) {{")
        lines += fill_statements(by_name[name], by_name)
        lines += ["  (void)n;", "}", ""]
    lines += [f"}}  // namespace {namespace}", ""]
    return "\n".join(lines)


def write_file(path, text):
    # Always written: the build compares the outputs' times with the .lcm files'.
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 64
    out_dir, files = argv[1], argv[2:]
    try:
        structs = [s for f in files for s in parse_file(f)]
        packages = {s.package for s in structs}
        if len(packages) != 1:
            raise SchemaError(f"expected one package, got {sorted(packages)}")
        package = packages.pop()
        by_name = check(structs)
        namespace = package.replace(".", "::")
        os.makedirs(out_dir, exist_ok=True)
        write_file(os.path.join(out_dir, "refloc_lcm_schemas.hpp"), write_schemas_hpp(by_name, namespace))
        write_file(os.path.join(out_dir, "refloc_lcm_schemas.cpp"), write_schemas_cpp(by_name, namespace))
        write_file(os.path.join(out_dir, "refloc_lcm_samples.hpp"), write_samples_hpp(by_name, package, namespace))
    except SchemaError as e:
        print(f"lcm_schema_gen: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
