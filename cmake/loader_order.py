#!/usr/bin/env python3
"""Prints the libraries that a program linked to deal.II names, one per
line, in the order it names them (cmake/loader_order.cmake says why):
first deal.II and the libraries it loads with at least --minimum symbol
relocations, most first, of those that can move without changing what
any symbol binds to; then all others but OpenBLAS in the order the loader
found them.

Moving a library ahead of another changes which definition the dynamic
loader finds first for a symbol both define. Where every definition is
weak (template instantiations, inline functions, type information: the
same code by the one-definition rule) that does not matter. Where one is
not, it does: OpenBLAS, PETSc (copies of Open MPI's Fortran sentinels),
Scotch and PT-Scotch, the SUNDIALS solvers define the same symbols with
code of their own. A library that defines such a symbol keeps its place
among the others, and so do the BLAS and LAPACK, chosen at run time
(Debian's alternatives, LD_LIBRARY_PATH).

usage: loader_order.py <deal.II library> [--minimum 200]
"""
import argparse
import concurrent.futures
import os
import re
import subprocess
import sys

# Symbols the linker defines in every shared object.
LINKER_DEFINED = {"_init", "_fini", "_edata", "_end", "__bss_start", "_etext",
                  "__data_start", "_DYNAMIC", "_GLOBAL_OFFSET_TABLE_"}
WEAK_TYPES = set("WVwvu")
RUN_TIME_CHOICE = re.compile(r"/lib(open|c)?blas[^/]*$|/liblapack[^/]*$")
# The BLAS behind libblas.so.3 and liblapack.so.3 where they are
# OpenBLAS's: named by the program, it would load (and serve every BLAS
# call) also where LD_LIBRARY_PATH chooses the reference BLAS.
IMPLEMENTATION = re.compile(r"/libopenblas[^/]*$")


def run(command):
    return subprocess.run(command, capture_output=True, text=True, check=True).stdout


def loaded_libraries(deal_ii):
    """deal.II and what it loads, in the loader's order (ldd)."""
    found = re.findall(r"=> (/\S+) \(", run(["ldd", deal_ii]))
    return [deal_ii] + [f for f in found if f != deal_ii]


def symbol_relocations(library):
    """All relocation entries (24 bytes each) less the relative ones."""
    dynamic = run(["readelf", "-dW", library])

    def tag(name):
        match = re.search(r"\(" + name + r"\) +(\d+)", dynamic)
        return int(match.group(1)) if match else 0
    return (tag("RELASZ") + tag("PLTRELSZ")) // 24 - tag("RELACOUNT")


def definitions(library):
    """{symbol: weak?} of the library's defined dynamic symbols."""
    found = {}
    for line in run(["nm", "-D", "--defined-only", library]).splitlines():
        fields = line.split()
        if len(fields) < 3 or fields[1] == "A":
            continue
        name = fields[2].split("@")[0]
        if name not in LINKER_DEFINED:
            found[name] = found.get(name, True) and fields[1] in WEAK_TYPES
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("deal_ii")
    parser.add_argument("--minimum", type=int, default=200)
    args = parser.parse_args()
    libraries = loaded_libraries(args.deal_ii)
    # The runs of nm and readelf, one per library, are independent: on
    # every core (configure waits for them before anything compiles).
    with concurrent.futures.ThreadPoolExecutor(os.cpu_count() or 1) as pool:
        defined = dict(zip(libraries, pool.map(definitions, libraries)))
    # How many libraries define each symbol, and whether all of them weakly.
    count, all_weak = {}, {}
    for symbols in defined.values():
        for name, weak in symbols.items():
            count[name] = count.get(name, 0) + 1
            all_weak[name] = all_weak.get(name, True) and weak
    movable = [library for library in libraries
               if not RUN_TIME_CHOICE.search(library)
               and all(count[name] == 1 or all_weak[name] for name in defined[library])]
    with concurrent.futures.ThreadPoolExecutor(os.cpu_count() or 1) as pool:
        weighed = list(zip(pool.map(symbol_relocations, movable), movable))
    first = [library for relocations, library in sorted(weighed, key=lambda w: -w[0])
             if relocations >= args.minimum]
    # Then every other library in the loader's own order, so that no two
    # that define a symbol both trade places (named by the program, they
    # come before the libraries they load).
    rest = [library for library in libraries
            if library not in first and not IMPLEMENTATION.search(library)]
    print("\n".join(first + rest))


if __name__ == "__main__":
    try:
        main()
    except (OSError, subprocess.CalledProcessError) as e:
        sys.exit(f"loader_order.py: {e}")
