#!/usr/bin/env python3
"""The dependency rule of docs/ARCHITECTURE.md, checked on the sources.

Reads every `#include "metricmap/<module>/..."` line under src/metricmap and fails when
  * a module includes a module of a higher layer, or one of its own layer that the table below
    does not allow;
  * the module graph has a cycle;
  * a folder's .cpp files are not all built into that folder's CMake library (SPLIT_FILES lists
    the documented exceptions, each with its reason);
  * the graph drawn in docs/ARCHITECTURE.md (between the dependency-graph markers) differs from
    the graph read from the sources.
`--print` prints the graph block the page should hold; `--write` puts it into the page.
"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
SRC = os.path.join(ROOT, "src", "metricmap")

# Bottom to top. A module may include any module of a lower layer.
LAYERS = [
    ("types", ["common"]),
    ("internals", ["detail"]),
    ("readers and writers", ["io"]),
    ("sources", ["datasets"]),
    ("algorithms", ["grid", "octree", "lines", "camera", "registration", "occupancy", "mapping",
                    "posegraph", "slam", "evaluation", "distance"]),
    ("pipelines", ["sequence", "distributed", "slam3d", "localization"]),
    ("drawing", ["viz"]),
]

# Includes allowed inside one layer (the algorithms build on each other, never in a ring).
SAME_LAYER = {
    "octree": {"grid"},
    "registration": {"grid"},
    "mapping": {"grid", "occupancy"},
    "slam": {"mapping", "occupancy", "posegraph"},
    "distance": {"occupancy", "mapping", "grid"},
    "localization": {"slam3d", "sequence"},
    "distributed": {"sequence"},
    "slam3d": {"sequence"},
}

# The CMake library each folder's sources are built into.
LIBRARIES = {
    "common": "metricmap_core", "detail": "metricmap_core", "grid": "metricmap_core",
    "octree": "metricmap_core", "lines": "metricmap_core",
    "io": "metricmap_io", "datasets": "metricmap_io",
    "camera": "metricmap_mapping", "evaluation": "metricmap_mapping",
    "mapping": "metricmap_mapping", "occupancy": "metricmap_mapping",
    "registration": "metricmap_mapping",
    "sequence": "metricmap_sequence", "posegraph": "metricmap_posegraph",
    "slam": "metricmap_slam", "distance": "metricmap_distance",
    "localization": "metricmap_localization", "viz": "metricmap_viz",
    "distributed": "metricmap_mpi", "slam3d": "metricmap_slam3d",
}

# Files built into another library than their folder's, and why.
SPLIT_FILES = {
    # liboctomap and PCL's registration stay out of metricmap_mapping, so that a consumer of the
    # maps alone needs neither (PCL's registration makes PCL's config look for VTK).
    "registration/scan_registration.cpp": ("metricmap_sequence", "PCL's registration"),
    "occupancy/cast_totals.cpp": ("metricmap_sequence", "casts scans of sources"),
    "occupancy/occupancy_inputs.cpp": ("metricmap_sequence", "reads bags and clouds"),
    "occupancy/octomap_export_use.cpp": ("metricmap_sequence", "liboctomap"),
    "occupancy/octomap_file_check.cpp": ("metricmap_sequence", "liboctomap"),
    "occupancy/octomap_io.cpp": ("metricmap_sequence", "liboctomap"),
    "occupancy/octomap_quiet.cpp": ("metricmap_sequence", "wraps octomap_io.cpp"),
    "occupancy/scan_casting.cpp": ("metricmap_sequence", "casts scans of sources"),
    # What the viewer shows, computed without VTK so that tests and Python need no VTK.
    "viz/scene_content.cpp": ("metricmap_mapping", "no VTK"),
    "viz/view_content.cpp": ("metricmap_mapping", "no VTK"),
}

INCLUDE = re.compile(r'\s*#\s*include\s*[<"]metricmap/([A-Za-z_0-9]+)/')


def read_graph():
    edges, where = {}, {}
    for folder, _, names in os.walk(SRC):
        rel = os.path.relpath(folder, SRC)
        if rel == ".":
            continue
        module = rel.split(os.sep)[0]
        edges.setdefault(module, set())
        for name in sorted(names):
            if not name.endswith((".h", ".hpp", ".cpp")):
                continue
            path = os.path.join(folder, name)
            with open(path, encoding="utf-8", errors="replace") as f:
                for number, line in enumerate(f, 1):
                    m = INCLUDE.match(line)
                    if m and m.group(1) != module:
                        edges[module].add(m.group(1))
                        where.setdefault((module, m.group(1)),
                                         f"{os.path.relpath(path, ROOT)}:{number}")
    return edges, where


def layer_of(module):
    for index, (_, modules) in enumerate(LAYERS):
        if module in modules:
            return index
    return None


def find_cycle(edges):
    state, stack = {}, []

    def visit(node):
        state[node] = 1
        stack.append(node)
        for nxt in sorted(edges.get(node, ())):
            if state.get(nxt) == 1:
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state:
                found = visit(nxt)
                if found:
                    return found
        stack.pop()
        state[node] = 2
        return None

    for node in sorted(edges):
        if node not in state:
            found = visit(node)
            if found:
                return found
    return None


def cmake_libraries():
    """file (relative to src/metricmap) -> library, from every add_library of src/CMakeLists.txt."""
    text = open(os.path.join(ROOT, "src", "CMakeLists.txt"), encoding="utf-8").read()
    owner = {}
    for m in re.finditer(r"add_library\((metricmap_\w+)([^)]*)\)", text):
        for item in re.findall(r"metricmap/(\S+\.cpp)", m.group(2)):
            owner[item] = m.group(1)
    return owner


def graph_block(edges):
    lines = []
    for index, (name, modules) in reversed(list(enumerate(LAYERS))):
        for module in modules:
            if module not in edges:
                continue
            deps = sorted(edges[module], key=lambda d: (-(layer_of(d) or 0), d))
            lines.append(f"{module:<13} ({name}) -> {', '.join(deps) if deps else '(nothing)'}")
    return "\n".join(lines)


def main():
    edges, where = read_graph()
    if "--print" in sys.argv:
        print(graph_block(edges))
        return 0
    if "--write" in sys.argv:
        path = os.path.join(ROOT, "docs", "ARCHITECTURE.md")
        text = open(path, encoding="utf-8").read()
        text = re.sub(r"(<!-- dependency-graph -->\n```\n).*?(\n```\n<!-- /dependency-graph -->)",
                      lambda m: m.group(1) + graph_block(edges) + m.group(2), text, flags=re.S)
        open(path, "w", encoding="utf-8").write(text)
    errors = []
    for module in sorted(edges):
        mine = layer_of(module)
        if mine is None:
            errors.append(f"module '{module}' has no layer in tests/architecture/check_dependencies.py")
            continue
        for dep in sorted(edges[module]):
            theirs = layer_of(dep)
            if theirs is None:
                errors.append(f"{where[(module, dep)]}: includes '{dep}', which has no layer")
            elif theirs > mine:
                errors.append(f"{where[(module, dep)]}: {module} ({LAYERS[mine][0]}) includes "
                              f"{dep} ({LAYERS[theirs][0]}), a higher layer")
            elif theirs == mine and dep not in SAME_LAYER.get(module, set()):
                errors.append(f"{where[(module, dep)]}: {module} includes {dep} of its own layer, "
                              f"not allowed by SAME_LAYER")
    cycle = find_cycle(edges)
    if cycle:
        errors.append("cycle between modules: " + " -> ".join(cycle))

    owner = cmake_libraries()
    for folder, _, names in os.walk(SRC):
        for name in sorted(names):
            if not name.endswith(".cpp"):
                continue
            rel = os.path.relpath(os.path.join(folder, name), SRC)
            module = rel.split(os.sep)[0]
            expected = SPLIT_FILES[rel][0] if rel in SPLIT_FILES else LIBRARIES.get(module)
            built = owner.get(rel)
            if built is None:
                errors.append(f"src/metricmap/{rel}: in no add_library of src/CMakeLists.txt")
            elif built != expected:
                errors.append(f"src/metricmap/{rel}: built into {built}, its folder's library is "
                              f"{expected} (or list it in SPLIT_FILES with the reason)")

    doc = open(os.path.join(ROOT, "docs", "ARCHITECTURE.md"), encoding="utf-8").read()
    m = re.search(r"<!-- dependency-graph -->\n```\n(.*?)\n```\n<!-- /dependency-graph -->", doc, re.S)
    if not m:
        errors.append("docs/ARCHITECTURE.md: no dependency-graph block")
    elif m.group(1).strip() != graph_block(edges).strip():
        errors.append("docs/ARCHITECTURE.md: the drawn graph differs from the include graph; "
                      "tests/architecture/check_dependencies.py --print gives the current one")
    for e in errors:
        print(e)
    if errors:
        return 1
    print(f"{len(edges)} modules, {sum(len(v) for v in edges.values())} module dependencies, "
          "acyclic, layered, folders match libraries")
    return 0


if __name__ == "__main__":
    sys.exit(main())
