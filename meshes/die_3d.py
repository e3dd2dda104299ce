#!/usr/bin/env python3
"""Writes die_3d.obj, the die of parameters/ironing_3d.prm: the lateral
surface of a cylinder of radius 3 whose axis runs along y at x = 2.5,
z = 6 (its lowest line at z = 3, the top of the block), from y = -1 to
y = 2, wider than the block (0 <= y <= 1). Quads, 120 around (the
polygon's sagitta is 1e-3 of the radius) and 3 along, each ordered so
that its normal points away from the axis (out of the tool) by the
right-hand rule, as <Contact/Rigid tool/Surface mesh> wants.

usage: python3 die_3d.py   (in this folder)
"""
import math

AROUND, ALONG = 120, 3
RADIUS, CENTRE, Y0, Y1 = 3.0, (2.5, 6.0), -1.0, 2.0

with open("die_3d.obj", "w") as f:
    f.write("# the die of parameters/ironing_3d.prm, made by die_3d.py\n")
    for j in range(ALONG + 1):
        y = Y0 + (Y1 - Y0) * j / ALONG
        for i in range(AROUND):
            angle = 2 * math.pi * i / AROUND
            f.write(f"v {CENTRE[0] + RADIUS * math.cos(angle):.12g} {y:.12g} "
                    f"{CENTRE[1] + RADIUS * math.sin(angle):.12g}\n")
    for j in range(ALONG):
        for i in range(AROUND):
            a = 1 + j * AROUND + i
            b = 1 + j * AROUND + (i + 1) % AROUND
            # (angle, y), (angle, y + dy), (angle + d, y + dy), (angle + d, y):
            # e_y x e_angle points away from the axis.
            f.write(f"f {a} {a + AROUND} {b + AROUND} {b}\n")
