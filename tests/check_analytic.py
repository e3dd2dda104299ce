#!/usr/bin/env python3
"""Compares a run of a half-ball scene (parameters/hertz_*.prm, or a
rigid ball pressed into a body,
cattaneo_*.prm) or of a dragged block (sliding_block.prm) with the
classical solutions of contact mechanics. Reads the run's `statistics`,
`parameters.prm` and, for the element size, its last `contact-NNNNN.csv`.

usage: check_analytic.py hertz OUTPUT_DIR [--radius-tolerance 0.05]
                                          [--pressure-tolerance 0.10]
                                          [--profile-tolerance 0.05]
       check_analytic.py cattaneo OUTPUT_DIR --rows FIRST-LAST
       check_analytic.py sliding OUTPUT_DIR [--tolerance 1e-6]
       check_analytic.py same-force OUTPUT_DIR --reference OTHER_DIR --tolerance 0.005

hertz: contact radius (3D) or half-width (2D) and peak pressure against
  Hertz's formulas for the measured total normal force P, relative errors
  within the tolerances (an axisymmetric section of a ball: the 3D
  formulas). The contact radius is that of the area of the
  nodes in contact (sum of their lumped areas, all symmetric copies: a =
  sqrt(A / pi), or A / 2 in 2D); the peak pressure is the largest nodal
  pressure (normal reaction over lumped area). With --profile-tolerance,
  also every nodal pressure within 0.8 a of the centre against Hertz's
  profile at its radius, relative to Hertz's p0.
cattaneo: on each row, the stick zone's radius (from the stick area, as
  above) within one element size of a (1 - Q / (mu P))^k, k = 1/3 for the
  ball (Mindlin), 1/2 for the cylinder, with a the measured contact radius.
same-force: the total normal force of the last increment against that of
  another run of the same bodies (a 3D quarter and an axisymmetric section).
sliding: rows where every node in contact slips have T = mu N (relative
  tolerance), rows with sticking nodes have T < mu N; at least one of each.
"""
import argparse
import csv
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_statistics  # noqa: E402


def read_statistics(path):
    """The rows of a statistics file as {column name: value}."""
    columns, rows = check_statistics.read_statistics(path)
    return [{name: float(row[i]) for name, i in columns.items()} for row in rows]


def report(failures):
    """Prints each failure as '*** ...'; the exit code: 1 if any, else 0."""
    for failure in failures:
        print("*** " + failure)
    return 1 if failures else 0


def read_parameters(path):
    """'Material/Young's modulus' -> '1' from a ShortPRM file."""
    values, sections = {}, []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("subsection "):
                sections.append(line[len("subsection "):].strip())
            elif line == "end":
                sections.pop()
            elif line.startswith("set "):
                key, value = line[4:].split("=", 1)
                values["/".join(sections + [key.strip()])] = value.strip()
    return values


def per_body(text, body):
    """The value of a Material entry for @p body: the whole text, or the
    part after 'body:' in 'ball: 1; plate: 2'."""
    if ":" not in text:
        return text.strip()
    for item in text.split(";"):
        name, value = item.split(":", 1)
        if name.strip() == body:
            return value.strip()
    raise KeyError(f"no value for the body {body} in '{text}'")


class Scene:
    def __init__(self, directory):
        p = read_parameters(directory + "/parameters.prm")
        self.rows = read_statistics(directory + "/statistics")
        self.dim = int(p.get("Dimension", "2"))
        # An axisymmetric section of a ball (x = r): Hertz's 3D formulas,
        # its forces and areas already those of the whole ball.
        self.axisymmetric = self.dim == 2 and p.get(
            "Material/Two-dimensional model", "").strip() == "axisymmetric"
        # One body on a rigid plane (half ball), or a ball on an elastic
        # plate: 1/E* = sum over the bodies of (1 - nu^2) / E (plane
        # strain and 3D; E in plane stress).
        two_bodies = p.get("Geometry/Model name") == "ball on plate"
        bodies = ["ball", "plate"] if two_bodies else [None]
        compliance = 0
        try:
            for body in bodies:
                E = float(per_body(p["Material/Young's modulus"], body))
                nu = float(per_body(p["Material/Poisson's ratio"], body))
                plane_stress = self.dim == 2 and per_body(
                    p["Material/Two-dimensional model"], body) == "plane stress"
                compliance += 1 / E if plane_stress else (1 - nu ** 2) / E
            self.E_star = 1 / compliance
        except KeyError:
            self.E_star = float("nan")  # bodies of their own materials: no Hertz
        # A pair's own coefficient (its third field) wins over the scene's.
        first_pair = p.get("Contact/Pairs", "").split(";")[0].split(":")
        self.mu = float(first_pair[2]) if len(first_pair) == 3 else \
            float(p["Contact/Friction coefficient"])
        geometry = "Geometry/Ball on plate/" if two_bodies else "Geometry/Half ball/"
        # Only a ball has a radius Hertz can use (a flat punch has none).
        ball = two_bodies or p.get("Geometry/Model name") == "half ball"
        self.radius = float(p.get(geometry + "Radius", "nan")) if ball else float("nan")
        # Or a rigid ball (the sphere obstacle) pressed into the body.
        if not ball and p.get("Contact/Obstacle/Model name") == "sphere":
            self.radius = float(p["Contact/Obstacle/Sphere/Radius"])
        self.center = [0.0] * 3 if two_bodies else \
            [float(c) for c in p.get(geometry + "Center", "0, 0, 0").split(",")]
        self.planes = int(p.get(geometry + "Symmetry planes", "0"))
        self.copies = 1 if self.axisymmetric else 2 ** self.planes
        self.directory = directory

    def label(self):
        return "axisymmetric" if self.axisymmetric else f"{self.dim}D"

    def normal_force(self, row):
        # The force on the slave side: on the ball, upwards; on the plate
        # (slave and master swapped), downwards.
        return self.copies * abs(row["Contact force " + "xyz"[self.dim - 1]])

    def tangential_force(self, row):
        # Components along the surface not cut by a symmetry plane (x is
        # cut by the first plane, y by the second).
        axes = [a for a in range(self.planes, self.dim - 1)]
        return self.copies * math.sqrt(
            sum(row["Contact force " + "xyz"[a]] ** 2 for a in axes))

    def radius_of_area(self, area):
        area *= self.copies
        return area / 2 if self.dim == 2 and not self.axisymmetric else \
            math.sqrt(area / math.pi)

    def element_size(self):
        """Median distance from a node in contact to its nearest neighbour."""
        files = sorted(glob.glob(self.directory + "/contact-*.csv"))
        if not files:
            sys.exit("no contact-*.csv: set Postprocess/Visualization/Write csv tables = true")
        with open(files[-1]) as f:
            header = f.readline().strip().split(",")
            points = []
            for line in f:
                row = dict(zip(header, line.strip().split(",")))
                if row["state"] != "free":
                    points.append([float(row[c]) for c in "xyz"[:self.dim]])
        distances = sorted(min(math.dist(p, q) for q in points if q is not p)
                           for p in points)
        return distances[len(distances) // 2]


def hertz(scene):
    """The last increment's total normal force P, contact radius (half-width
    in 2D) and peak pressure, and Hertz's radius and peak pressure for P."""
    row = scene.rows[-1]
    P, R, E = scene.normal_force(row), scene.radius, scene.E_star
    a = scene.radius_of_area(row["Contact area"])
    p0 = row["Max contact pressure"]
    if scene.dim == 2 and not scene.axisymmetric:
        a_hertz = math.sqrt(4 * P * R / (math.pi * E))
        p_hertz = 2 * P / (math.pi * a_hertz)
    else:
        a_hertz = (3 * P * R / (4 * E)) ** (1 / 3)
        p_hertz = 3 * P / (2 * math.pi * a_hertz ** 2)
    return P, a, a_hertz, p0, p_hertz


def radius_of_profile(scene):
    """The contact radius (half-width in 2D) of Hertz's profile
    p0 sqrt(1 - r^2 / a^2) fitted by least squares to the last increment's
    nodal pressures (p^2 linear in r^2; every node with a pressure). The
    radius of the contact area moves by up to half a cell with the mesh,
    most for an axisymmetric section's one line of nodes; the fit takes
    every node's pressure."""
    files = sorted(glob.glob(scene.directory + "/contact-*.csv"))
    if not files:
        sys.exit("no contact-*.csv: set Postprocess/Visualization/Write csv tables = true")
    points = []
    with open(files[-1]) as f:
        for row in csv.DictReader(f):
            p = float(row["pressure"])
            if p > 0:
                r2 = sum((float(row[c]) - scene.center[i]) ** 2
                         for i, c in enumerate("xyz"[:scene.dim - 1]))
                points.append((r2, p * p))
    n = len(points)
    sx, sy = sum(x for x, _ in points), sum(y for _, y in points)
    sxx, sxy = sum(x * x for x, _ in points), sum(x * y for x, y in points)
    slope = (n * sxy - sx * sy) / (n * sxx - sx * sx)
    return math.sqrt(-(sy - slope * sx) / n / slope)


def pressure_profile_error(scene, a_hertz, p_hertz):
    """The largest difference, over the contact nodes within 0.8 a of the
    centre, between the nodal pressure and Hertz's profile
    p0 sqrt(1 - r^2 / a^2) at the node's radius, relative to p0, and the
    number of such nodes: a pressure that oscillates from node to node (a
    locking element) fails this even where its peak is right."""
    files = sorted(glob.glob(scene.directory + "/contact-*.csv"))
    if not files:
        sys.exit("no contact-*.csv: set Postprocess/Visualization/Write csv tables = true")
    with open(files[-1]) as f:
        rows = list(csv.DictReader(f))
    worst, count = 0.0, 0
    for row in rows:
        x = [float(row[c]) - scene.center[i]
             for i, c in enumerate("xyz"[:scene.dim - 1])]
        r = math.sqrt(sum(c * c for c in x))
        if r > 0.8 * a_hertz:
            continue
        exact = p_hertz * math.sqrt(1 - (r / a_hertz) ** 2)
        worst = max(worst, abs(float(row["pressure"]) - exact) / p_hertz)
        count += 1
    return worst, count


def check_hertz(scene, args):
    P, a, a_hertz, p0, p_hertz = hertz(scene)
    error_a = abs(a - a_hertz) / a_hertz
    error_p = abs(p0 - p_hertz) / p_hertz
    ok = error_a <= args.radius_tolerance and error_p <= args.pressure_tolerance
    if args.profile_tolerance is not None:
        error_profile, count = pressure_profile_error(scene, a_hertz, p_hertz)
        passed = count > 0 and error_profile <= args.profile_tolerance
        ok = ok and passed
        print(f"Hertz {scene.label()}: nodal pressures within 0.8 a ({count} "
              f"nodes) differ from Hertz's profile by at most "
              f"{100 * error_profile:.2f} % of p0 (allowed "
              f"{100 * args.profile_tolerance:g} %)")
    name = "half-width" if scene.dim == 2 and not scene.axisymmetric else "radius"
    print(f"Hertz {scene.label()}: P = {P:.6g}, contact {name} {a:.6g} against "
          f"{a_hertz:.6g} (error {100 * error_a:.2f} %, allowed "
          f"{100 * args.radius_tolerance:g} %), peak pressure {p0:.6g} against "
          f"{p_hertz:.6g} (error {100 * error_p:.2f} %, allowed "
          f"{100 * args.pressure_tolerance:g} %)")
    return ok


def check_cattaneo(scene, args):
    first, last = (int(x) for x in args.rows.split("-"))
    h = scene.element_size()
    exponent = 1 / 2 if scene.dim == 2 else 1 / 3
    ok = len(scene.rows) >= last
    for row in scene.rows[first - 1:last]:
        P, Q = scene.normal_force(row), scene.tangential_force(row)
        a = scene.radius_of_area(row["Contact area"])
        c = scene.radius_of_area(row["Stick area"])
        ratio = Q / (scene.mu * P)
        c_theory = a * (1 - ratio) ** exponent
        passed = 0 < ratio < 1 and abs(c - c_theory) <= h
        ok = ok and passed
        print(f"increment {int(row['Increment'])}: Q / (mu P) = {ratio:.4f}, "
              f"a = {a:.5g}, stick radius {c:.5g} against {c_theory:.5g} "
              f"(difference {abs(c - c_theory):.2g}, element size {h:.2g}: "
              f"{'ok' if passed else 'TOO LARGE'})")
    return ok


def check_sliding(scene, args):
    sliding = sticking = 0
    ok = True
    for row in scene.rows:
        N, T = row["Normal contact force"], row["Tangential contact force"]
        if N <= 0:
            continue
        ratio = T / N
        if row["Stick nodes"] == 0 and row["Slip nodes"] > 0:
            sliding += 1
            error = abs(ratio - scene.mu) / scene.mu
            passed = error <= args.tolerance
            print(f"increment {int(row['Increment'])}: slides, T / N = "
                  f"{ratio:.10f} (relative error {error:.1e}, "
                  f"{'ok' if passed else 'ABOVE'} {args.tolerance:g})")
        else:
            sticking += 1
            passed = ratio < scene.mu
            print(f"increment {int(row['Increment'])}: sticks "
                  f"({int(row['Stick nodes'])} nodes), T / N = {ratio:.6f} "
                  f"({'<' if passed else 'NOT <'} mu = {scene.mu:g})")
        ok = ok and passed
    if sliding == 0 or sticking == 0:
        print(f"expected increments that stick and that slide, got "
              f"{sticking} and {sliding}")
        ok = False
    return ok


def check_same_force(scene, args):
    """The total normal force of the last increment against that of the
    run in --reference (each with its symmetric copies: a 3D quarter and
    an axisymmetric section of the same bodies give the whole force)."""
    P = scene.normal_force(scene.rows[-1])
    reference = Scene(args.reference)
    P_reference = reference.normal_force(reference.rows[-1])
    error = abs(P - P_reference) / abs(P_reference)
    print(f"{scene.label()}: P = {P:.6g} against {P_reference:.6g} of the "
          f"{reference.label()} run (difference {100 * error:.3f} %, allowed "
          f"{100 * args.tolerance:g} %)")
    return error <= args.tolerance


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("problem", choices=["hertz", "cattaneo", "sliding", "same-force"])
    parser.add_argument("directory")
    parser.add_argument("--radius-tolerance", type=float, default=0.05)
    parser.add_argument("--pressure-tolerance", type=float, default=0.10)
    parser.add_argument("--rows", default="2-3")
    parser.add_argument("--tolerance", type=float, default=1e-6)
    parser.add_argument("--profile-tolerance", type=float, default=None)
    parser.add_argument("--reference", help="same-force: the other run's output folder")
    args = parser.parse_args()
    scene = Scene(args.directory)
    check = {"hertz": check_hertz, "cattaneo": check_cattaneo,
             "sliding": check_sliding, "same-force": check_same_force}[args.problem]
    ok = check(scene, args)
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
