#!/usr/bin/python3
"""Requirement (issue 25): the folders show the architecture. Each folder of src/ and
include/vibrotherm/ may include only folders listed before it in LAYERS (its own
included): no folder includes one above it, so no two folders include each other.
The order, bottom to top, is that of docs/ARCHITECTURE.md's map. A new folder must be
placed here before it can be used.

Requirement (issue 42): PETSc's options database is looked at directly (PetscOptionsGet*,
PetscOptionsHasName) only in src/options/: modules read their options in their readers,
and the few checks of whether an option was given go through options/query.

usage: test_layers.py REPO"""
import os
import re
import sys

LAYERS = [
    "contact",            # crack laws, PETSc-free
    "options",            # command line and options files, PETSc-free
    "options/query",      # the one direct look at PETSc's options database (was an option given, its value)
    "util",               # errors, stages, gathers across ranks, version
    "geometry",           # points and frames, PETSc-free
    "store",              # atomic files, the checkpoint store
    "options/petsc",      # PETSc option helpers and the option audit
    "mesh/plex",          # generic DMPlex tools (facets, crack split, partitioners)
    "mesh",               # the specimen and its 2D meshing
    "fe",                 # Lagrange spaces, cell and point location
    "wave",               # elastodynamics
    "heat",               # heat conduction
    "interface",          # crack contact cells between the wave solver and the laws
    "io",                 # output files
    "coupling/exchange",  # what flows between the solvers (friction heat and its near field, thermoelastic, thermal stress)
    "coupling/observe",   # what a run writes (recorder, field peak, probe temperatures, IR camera)
    "coupling/continuation",  # periodic continuation, behind continued_parts.hpp (the run implements it)
    "coupling/run",       # run order, components, observers, scene, checkpoint schedule
    "modes",              # modal analysis run
    "app",                # executables
]
NESTED = ("coupling/", "mesh/plex", "options/petsc", "options/query")


def folder_of(path):
    """`path` relative to src/ or include/vibrotherm/ → its layer."""
    parts = path.split("/")[:-1]
    two = "/".join(parts[:2])
    return two if two.startswith(NESTED) else parts[0]


def main(repo):
    rank = {name: i for i, name in enumerate(LAYERS)}
    failures, files = [], 0
    for root in ("src", "include/vibrotherm"):
        for dirpath, _, names in os.walk(os.path.join(repo, root)):
            for name in names:
                path = os.path.join(dirpath, name)
                own = folder_of(os.path.relpath(path, os.path.join(repo, root)))
                if own not in rank:
                    failures.append("%s: folder %s is not in LAYERS" % (path, own))
                    continue
                files += 1
                for header in re.findall(r'#include "vibrotherm/([a-z_0-9/]+\.hpp)"', open(path).read()):
                    other = folder_of(header)
                    if rank.get(other, len(LAYERS)) > rank[own]:
                        failures.append("%s (%s) includes %s (%s, a layer above)" % (path, own, header, other))
    direct = re.compile(r"PetscOptions(Get[A-Za-z]*|HasName)\s*\(")
    for dirpath, _, names in os.walk(os.path.join(repo, "src")):
        if os.path.relpath(dirpath, os.path.join(repo, "src")).split(os.sep)[0] == "options":
            continue
        for name in names:
            path = os.path.join(dirpath, name)
            for number, line in enumerate(open(path), 1):
                if direct.search(line):
                    failures.append("%s:%d reads PETSc's options database directly (options/query)" % (path, number))
    for f in failures:
        print("FAILED:", f)
    print("folder layers: %d files, %d violations" % (files, len(failures)))
    return 1 if failures or files < 100 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
