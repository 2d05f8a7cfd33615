#!/usr/bin/env python3
"""Checks the installed API's headers: the list, and a /// comment on
every declaration.

The installed headers are the files under <module>/include/hullcover/ of
lib/geometry, lib/mesh, lib/covering, bvh and validate (cmake/
HullcoverInstall.cmake installs exactly those). Their list must equal
EXPECTED below, so a header cannot become public unnoticed. In each, every
declaration at namespace scope (a struct, class, enum, alias, constant,
function or function template) and every public member function must
follow a `///` comment (or carry a trailing `///<`). No header may
include one of the project's internal headers (<module>/internal/).

Usage: scripts/check_public_headers.py [REPOSITORY_ROOT]; exit 1 on any
finding, printed one per line.
"""
import os
import re
import sys

MODULES = ("lib/geometry", "lib/mesh", "lib/covering", "bvh", "validate")

EXPECTED = """
hullcover/bvh/collectors.h
hullcover/bvh/covering_hulls.h
hullcover/bvh/fcl_covering.h
hullcover/bvh/hull_contact.h
hullcover/bvh/hull_queries.h
hullcover/bvh/hull_world.h
hullcover/bvh/query_shape.h
hullcover/bvh/query_threads.h
hullcover/bvh/query_types.h
hullcover/bvh/runtime_file.h
hullcover/bvh/runtime_hull.h
hullcover/bvh/streamed_world.h
hullcover/bvh/triangle_world.h
hullcover/covering/cell_cache.h
hullcover/covering/covering.h
hullcover/covering/covering_export.h
hullcover/covering/covering_types.h
hullcover/covering/decompose_options.h
hullcover/covering/movement_covering.h
hullcover/covering/movement_options.h
hullcover/covering/staged_decomposition.h
hullcover/covering/validity.h
hullcover/geometry/aabb.h
hullcover/geometry/aabb_tree.h
hullcover/geometry/mappable_array.h
hullcover/geometry/convex_polytope.h
hullcover/geometry/mesh.h
hullcover/geometry/status.h
hullcover/geometry/tolerances.h
hullcover/mesh/import_limits.h
hullcover/mesh/mesh_connectivity.h
hullcover/mesh/mesh_export.h
hullcover/mesh/mesh_import.h
hullcover/mesh/mesh_islands.h
hullcover/mesh/prepared_mesh.h
hullcover/mesh/scene_builder.h
hullcover/mesh/tolerance.h
hullcover/validate/accessible_space.h
hullcover/validate/allowance_audit.h
hullcover/validate/audit.h
hullcover/validate/behaviour_equivalence.h
hullcover/validate/hull_set.h
hullcover/validate/hull_under_check.h
hullcover/validate/movement_audit.h
hullcover/validate/validity_recheck.h
""".split()

INCLUDE = re.compile(r'^\s*#\s*include\s+"(hullcover/[^"]+)"')
# A line that starts a declaration at namespace or class scope.
DECLARATION = re.compile(
    r"^\s*(template\s*<|struct\s+\w|class\s+\w|enum\s|using\s+\w+\s*=|inline\s+constexpr|constexpr\s|"
    r"\[\[nodiscard\]\]|static\s|virtual\s|explicit\s|[A-Za-z_][\w:<>,\s\*&]*[\s\*&]~?\w+\s*\()")
IGNORED = re.compile(r"^\s*(public:|private:|protected:|friend\s|namespace\s|}|#|//|$|.*=\s*delete;|.*=\s*default;)")


def undocumented(lines):
    """Line numbers (1-based) of declarations with no /// before or ///< after."""
    found = []
    depth_private = []  # per open class: True inside a private: section
    brace_depth = 0
    previous = ""
    in_body = 0  # > 0 inside a function body or an initialiser (not checked)
    for number, line in enumerate(lines, 1):
        stripped = line.strip()
        if stripped.startswith(("private:", "protected:")) and depth_private:
            depth_private[-1] = True
        elif stripped.startswith("public:") and depth_private:
            depth_private[-1] = False
        private = bool(depth_private) and depth_private[-1]
        checked = in_body == 0 and not private and not IGNORED.match(line) and DECLARATION.match(line)
        # A forward declaration, or the out-of-line definition of a member
        # declared (and documented) in its class, needs no comment of its own.
        following = lines[number] if number < len(lines) else ""
        if re.match(r"^\s*(struct|class)\s+\w+;\s*$", line) or (
                stripped.startswith("template") and "::" in following.split("(")[0]):
            checked = False
        if checked and not (previous.startswith("///") or previous.endswith("*/") or "///<" in line or
                            previous.startswith("template")):
            found.append(number)
        opens, closes = line.count("{"), line.count("}")
        if re.match(r"^\s*namespace\b.*{", line):
            opens -= 1
        elif re.match(r"^}\s*//\s*namespace", line):
            closes -= 1
        if re.match(r"^\s*(struct|class)\s+\w[^;]*$", line) or re.match(r"^\s*(struct|class)\s+\w.*{\s*$", line):
            depth_private.append(stripped.startswith("class"))
            opens -= 1 if "{" in line else 0
        elif stripped.startswith("};") and depth_private and in_body == 0:
            depth_private.pop()
            closes -= 1
        in_body = max(0, in_body + opens - closes)
        if stripped:
            previous = stripped
    return found


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    problems = []
    headers = {}
    for module in MODULES:
        base = os.path.join(root, module, "include")
        for folder, _, names in os.walk(base):
            for name in names:
                if name.endswith(".h"):
                    full = os.path.join(folder, name)
                    headers[os.path.relpath(full, base).replace(os.sep, "/")] = full
    for extra in sorted(set(headers) - set(EXPECTED)):
        problems.append(f"{extra}: public, but not in the expected list (make it internal, or list it here)")
    for missing in sorted(set(EXPECTED) - set(headers)):
        problems.append(f"{missing}: expected, but not found")
    internal = set()
    for module in MODULES:
        base = os.path.join(root, module, "internal")
        for folder, _, names in os.walk(base):
            for name in names:
                internal.add(os.path.relpath(os.path.join(folder, name), base).replace(os.sep, "/"))
    for name, full in sorted(headers.items()):
        with open(full, encoding="utf-8") as text:
            lines = text.read().split("\n")
        for number, line in enumerate(lines, 1):
            m = INCLUDE.match(line)
            if m and m.group(1) in internal:
                problems.append(f"{name}:{number}: includes the internal header {m.group(1)}")
        for number in undocumented(lines):
            problems.append(f"{name}:{number}: declaration without ///: {lines[number - 1].strip()}")
    for p in problems:
        print(p)
    print(f"{len(headers)} installed headers, {len(problems)} findings")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
