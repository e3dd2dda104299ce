#!/usr/bin/env python3
"""Writes press_fit_2d.msh (Gmsh 2.2, quadrilaterals): the axisymmetric
sections of a shaft (x = r in [0, 1]) and of a ring on it (r in
[1 - interference, 2]), both y in [0, 0.5], meshed apart and not matching
along the fit (10 and 7 cells along y). Physical groups: surfaces "shaft"
and "ring"; curves "shaft bottom", "shaft top", "shaft outer", "shaft
axis", "ring bottom", "ring top", "ring inner", "ring outer".

usage: press_fit_2d.py [--interference 0.001] [-o press_fit_2d.msh]
"""
import argparse
import os

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("--interference", type=float, default=0.001)
parser.add_argument("-o", "--output",
                    default=os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                         "press_fit_2d.msh"))
args = parser.parse_args()

nodes, quads, lines = [], [], []
names = {1: "shaft bottom", 2: "shaft top", 3: "shaft outer", 4: "shaft axis",
         5: "ring bottom", 6: "ring top", 7: "ring inner", 8: "ring outer",
         10: "shaft", 11: "ring"}


def block(r0, r1, nx, ny, surface, bottom, top, inner, outer):
    first = len(nodes) + 1
    for j in range(ny + 1):
        for i in range(nx + 1):
            nodes.append((r0 + (r1 - r0) * i / nx, 0.5 * j / ny))
    at = lambda i, j: first + j * (nx + 1) + i
    for j in range(ny):
        for i in range(nx):
            quads.append((surface, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)))
    for i in range(nx):
        lines.append((bottom, at(i, 0), at(i + 1, 0)))
        lines.append((top, at(i + 1, ny), at(i, ny)))
    for j in range(ny):
        lines.append((outer, at(nx, j), at(nx, j + 1)))
        lines.append((inner, at(0, j + 1), at(0, j)))


block(0.0, 1.0, 10, 10, 10, 1, 2, 4, 3)
block(1.0 - args.interference, 2.0, 10, 7, 11, 5, 6, 7, 8)
with open(args.output, "w") as f:
    f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n")
    f.write(f"{len(names)}\n")
    for tag, name in names.items():
        f.write(f'{2 if tag >= 10 else 1} {tag} "{name}"\n')
    f.write(f"$EndPhysicalNames\n$Nodes\n{len(nodes)}\n")
    for n, (x, y) in enumerate(nodes, 1):
        f.write(f"{n} {x:.17g} {y:.17g} 0\n")
    f.write(f"$EndNodes\n$Elements\n{len(lines) + len(quads)}\n")
    number = 0
    for tag, a, b in lines:
        number += 1
        f.write(f"{number} 1 2 {tag} {tag} {a} {b}\n")
    for tag, a, b, c, d in quads:
        number += 1
        f.write(f"{number} 3 2 {tag} {tag} {a} {b} {c} {d}\n")
    f.write("$EndElements\n")
print(f"wrote {args.output}")
