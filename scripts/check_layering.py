#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Fails on an include between folders of src/drydem that goes against the layering of
ARCHITECTURE.md ("Folders and layers"), on an include cycle between folders, and on a folder the
layering does not name. Run by ctest (test `layering`); usage: check_layering.py [SRC_DIR].

A folder may include only itself and folders of a lower layer. Folders in one layer are
independent of each other. The few includes that still go upwards are listed in KNOWN_EXCEPTIONS
with the reason; an exception that no longer occurs must be removed from the list (the test
fails), so the list only shrinks.
"""
import re
import sys
from collections import defaultdict
from pathlib import Path

# Lowest first: the data flow from configuration to the command line (ARCHITECTURE.md).
LAYERS = [
    ["core"],                          # vectors, box, particle store, errors: no physics
    ["io"],                            # config (units, schema, defaults), particle files, output folder
    ["setup"],                         # formulation -> recipe and particles; Eq. 4 (setup/solids)
    ["dryer_model"],                   # the dryer model (uses Eq. 4 from setup/solids)
    ["forces"],                        # pair and body laws (and their list), their time scales
    ["neighbor"],                      # neighbour list, holding the pair laws' per-pair state
    ["parallel"],                      # MPI: domain decomposition, halo exchanges of particles
    ["engine"],                        # the simulation: pair loop, integration, stability estimate
    ["analysis"],                      # structure analysis of a particle set
    ["output"],                        # writers of results: frames, series, dump, analysis, checkpoint
    ["drying"],                        # the drying run: set-up, scaling, driver, its outputs
    ["calendering"],                   # the calendering run on a dried film
    ["study"],                         # loadings x seeds as separate runs
    ["app"],                           # the `drydem` command line
]

# (including file relative to src/drydem, included folder): why it is still there.
KNOWN_EXCEPTIONS = {}

INCLUDE = re.compile(r'^\s*#\s*include\s+"drydem/([^/"]+)/')


def folder_includes(src: Path):
    """{(file, folder)} of every include of another folder of src/drydem."""
    found = set()
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".hpp", ".cpp", ".h", ".cc") or not path.is_file():
            continue
        rel = path.relative_to(src).as_posix()
        here = rel.split("/")[0]
        if "/" not in rel:
            continue
        for line in path.read_text(encoding="utf-8", errors="replace").splitlines():
            m = INCLUDE.match(line)
            if m and m.group(1) != here:
                found.add((rel, m.group(1)))
    return found


def find_cycle(edges):
    """A cycle of the folder graph as a list of folders, or None."""
    state, stack = {}, []

    def visit(n):
        state[n] = "open"
        stack.append(n)
        for m in sorted(edges[n]):
            if state.get(m) == "open":
                return stack[stack.index(m):] + [m]
            if m not in state:
                c = visit(m)
                if c:
                    return c
        state[n] = "done"
        stack.pop()
        return None

    for n in sorted(edges):
        if n not in state:
            c = visit(n)
            if c:
                return c
    return None


def main():
    src = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent / "src" / "drydem"
    rank = {f: i for i, layer in enumerate(LAYERS) for f in layer}
    folders = sorted(p.name for p in src.iterdir() if p.is_dir())
    problems = []
    for f in folders:
        if f not in rank:
            problems.append(f"folder {f}/ is in no layer: add it to LAYERS here and to ARCHITECTURE.md")
    includes = folder_includes(src)
    edges = defaultdict(set)
    for rel, to in sorted(includes):
        here = rel.split("/")[0]
        if here not in rank or to not in rank:
            continue
        if (rel, to) in KNOWN_EXCEPTIONS:
            continue
        edges[here].add(to)
        if rank[to] > rank[here]:
            problems.append(f"{rel} includes {to}/: {to} is above {here} in the layering")
        elif rank[to] == rank[here]:
            problems.append(f"{rel} includes {to}/: {here} and {to} are one layer, independent of each other")
    cycle = find_cycle(edges)
    if cycle:
        problems.append("include cycle between folders: " + " -> ".join(cycle))
    for (rel, to), why in sorted(KNOWN_EXCEPTIONS.items()):
        if (rel, to) not in includes:
            problems.append(f"known exception {rel} -> {to}/ no longer occurs: remove it from KNOWN_EXCEPTIONS")
    graph = {f: sorted(edges[f]) for f in folders if edges[f]}
    print("folder graph (known exceptions left out):")
    for f in folders:
        print(f"  {f:10s} -> {', '.join(graph.get(f, [])) or '-'}")
    print(f"known exceptions: {len(KNOWN_EXCEPTIONS)}")
    for (rel, to), why in sorted(KNOWN_EXCEPTIONS.items()):
        print(f"  {rel} -> {to}/: {why}")
    if problems:
        print("LAYERING VIOLATED:")
        for p in problems:
            print("  " + p)
        return 1
    print("layering OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
