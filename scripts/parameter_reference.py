#!/usr/bin/env python3
"""Writes doc/parameters.md, the user's reference of every parameter, from
what the program itself declares: `contact --print-parameters --json` (the
2D defaults) and the same for a scene that only sets Dimension = 3 (the 3D
defaults, and the entries that exist only in 3D). The subsections, entries,
defaults, allowed values and descriptions all come from the program; the
introduction and the section on the syntax of the boundary conditions and
loads are written here, in this script, so that regenerating keeps them.

usage: parameter_reference.py [--contact build/contact]
                              [--output doc/parameters.md] [--check]

  --contact  the program (default: build/contact of this project)
  --output   the page to write (default: doc/parameters.md of this project)
  --check    write nothing: regenerate the page in memory and exit with 1,
             printing a unified diff (at most 60 lines), if the page on
             disk differs; else exit with 0

Run it after changing a parameter's declaration or documentation in the C++
sources; `--check` tells whether doc/parameters.md is current.
"""
import argparse
import difflib
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCRIPT = "scripts/parameter_reference.py"
DIFF_LINES = 60


# ---------------------------------------------------------------------------
# Reading the program's parameters.

def run_program(contact, scene=None):
    """The JSON tree of `contact --print-parameters --json [scene]`."""
    command = [contact, "--print-parameters", "--json"]
    if scene:
        command.append(scene)
    with tempfile.TemporaryDirectory() as folder:  # whatever it might write
        try:
            done = subprocess.run(command, capture_output=True, text=True,
                                  cwd=folder, timeout=300)
        except OSError as error:
            fail(f"cannot run {contact}: {error.strerror}")
    if done.returncode != 0:
        fail(f"{' '.join(command)} failed with exit code "
             f"{done.returncode}:\n{done.stderr.strip()}")
    try:
        return json.loads(done.stdout)
    except ValueError as error:
        fail(f"{' '.join(command)} did not print JSON: {error}")


def fail(message):
    """Stops with exit code 2 (1 means: the page is not current)."""
    print(f"{SCRIPT}: {message}", file=sys.stderr)
    sys.exit(2)


def is_entry(node):
    return (isinstance(node, dict) and isinstance(node.get("value"), str)
            and "documentation" in node and "pattern_description" in node)


def merged_order(first, second):
    """The keys of first in their order, with those only in second put
    after their predecessor in second (both lists are sorted alike)."""
    result = list(first)
    previous = None
    for key in second:
        if key not in result:
            result.insert(result.index(previous) + 1 if previous is not None
                          else 0, key)
        previous = key
    return result


class Section:
    """A subsection: its entries (name -> {dim: JSON entry}) and its
    subsections (name -> Section), in the program's order."""

    def __init__(self, path, trees):
        self.path = path          # tuple of names; () is the top level
        self.entries = {}
        self.subsections = {}
        entry_names = [[k for k, v in t.items() if is_entry(v)]
                       for t in trees.values()]
        section_names = [[k for k, v in t.items()
                          if isinstance(v, dict) and not is_entry(v)]
                         for t in trees.values()]
        order = []
        for names in entry_names:
            order = merged_order(order, names)
        for name in order:
            self.entries[name] = {dim: tree[name]
                                  for dim, tree in trees.items()
                                  if name in tree and is_entry(tree[name])}
        order = []
        for names in section_names:
            order = merged_order(order, names)
        for name in order:
            self.subsections[name] = Section(
                path + (name,),
                {dim: tree[name] for dim, tree in trees.items()
                 if isinstance(tree.get(name), dict)
                 and not is_entry(tree[name])})

    @property
    def title(self):
        return "/".join(self.path) if self.path else "Top level"

    def walk(self):
        yield self
        for sub in self.subsections.values():
            yield from sub.walk()


# ---------------------------------------------------------------------------
# Rendering single values.

def number(text):
    return text.replace("MAX_DOUBLE", "max")


def allowed_values(description):
    """A shortened reading of deal.II's pattern description."""
    text = description.strip()
    match = re.fullmatch(r"\[(\w+)\s*(.*?)\s*\]", text, re.S)
    if not match:
        return text
    kind, rest = match.group(1), match.group(2)
    if kind == "Selection":
        return ", ".join(o.strip() for o in rest.split("|"))
    if kind == "MultipleSelection":
        return ("any of " + ", ".join(o.strip() for o in rest.split("|"))
                + " (separated by commas)")
    if kind == "Bool":
        return "true, false"
    if kind == "Anything":
        return "text"
    if kind in ("Double", "Integer"):
        name = "number" if kind == "Double" else "integer"
        bounds = re.fullmatch(r"(?:range\s+)?(\S+?)\.\.\.(\S+)"
                              r"(?:\s*\((inclusive|exclusive)\))?", rest)
        if not bounds:
            return name if not rest else f"{name} {rest}"
        low, high = bounds.group(1), bounds.group(2)
        unbounded_low = low in ("-MAX_DOUBLE", "-2147483648",
                                "-2147483647")
        unbounded_high = high in ("MAX_DOUBLE", "2147483647", "4294967295")
        if unbounded_low and unbounded_high:
            return name
        if unbounded_high:
            return f"{name} >= {number(low)}"
        if unbounded_low:
            return f"{name} <= {number(high)}"
        if kind == "Integer":
            try:
                if int(high) - int(low) == 1:
                    return f"{low} or {high}"
            except ValueError:
                pass
            return f"integer from {low} to {high}"
        return f"number from {low} to {high}"
    if kind == "DirectoryName":
        return "a folder"
    if kind == "FileName":
        return "a file name"
    if kind == "List":
        inner = re.match(r"of <(\[.*\])> of length", rest, re.S)
        separator = re.search(r"separated by <(.*?)>", rest)
        if inner:
            return ("list of " + allowed_values(inner.group(1))
                    + (f" (separated by '{separator.group(1)}')"
                       if separator else ""))
    return text.strip("[] ")


def cell(text, reference=None):
    """Table cell text: '|' escaped, '<' escaped where it could open an
    HTML tag (the program writes entries as <Section/Entry>), line breaks
    as <br>. reference(name) gives the anchor of such a name, or None."""
    text = text.replace("\\", "\\\\").replace("|", "\\|")

    def bracketed(match):
        name = match.group(1)
        anchor = reference(name) if reference and name else None
        if anchor:
            return f"[\\<{name}>](#{anchor})"
        return "\\" + match.group(0)

    text = re.sub(r"<([A-Za-z][^<>\n]*)>|<(?=[A-Za-z/!?])", bracketed, text)
    return "<br>".join(line.strip() for line in text.strip().split("\n"))


def code(value):
    """A value as a code span ('|' escaped for the table)."""
    if value == "":
        return "*(empty)*"
    ticks = "``" if "`" in value else "`"
    pad = " " if value.startswith("`") or value.endswith("`") else ""
    return f"{ticks}{pad}{value}{pad}{ticks}".replace("|", "\\|")


def per_dimension(values, render, mark_only=True):
    """values: {dim: text}. One rendering if the dimensions agree, else
    one per dimension, and '(3D only)' for an entry only one has."""
    dims = sorted(values)
    if len(dims) == 1 and len(DIMS) > 1 and mark_only:
        return f"{render(values[dims[0]])} ({dims[0]}D only)"
    if len(set(values.values())) == 1:
        return render(values[dims[0]])
    return "<br>".join(f"{render(values[d])} ({d}D)" for d in dims)


def slug(title, used):
    """GitHub's anchor of a heading."""
    anchor = re.sub(r"[^\w\- ]", "", title.strip().lower()).replace(" ", "-")
    base, n = anchor, 0
    while anchor in used:
        n += 1
        anchor = f"{base}-{n}"
    used.add(anchor)
    return anchor


# ---------------------------------------------------------------------------
# Plugin families: a selection entry whose choices have subsections named
# like them (`Model name = box` reads `Box`), or whose documentation lists
# its "Choices:", or a multiple selection (the postprocessors).

def options(entry):
    match = re.fullmatch(r"\[(Selection|MultipleSelection)\s+(.*?)\s*\]",
                         entry["pattern_description"].strip(), re.S)
    if not match:
        return None, []
    return match.group(1), [o.strip() for o in match.group(2).split("|")]


def families(root):
    """(selectors, owner): selectors maps an entry's path to (kind,
    choices, {choice: Section}); owner maps a subsection's path to
    (selector path, choice)."""
    selections = []
    for section in root.walk():
        for name, by_dim in section.entries.items():
            entry = by_dim[max(by_dim)]
            kind, choices = options(entry)
            if kind:
                selections.append((section.path + (name,), kind, choices,
                                   entry["documentation"]))
    owner = {}
    for section in root.walk():
        if not section.path:
            continue
        best = None
        for path, kind, choices, _ in selections:
            lowered = [c.lower() for c in choices]
            if section.path[-1].lower() not in lowered:
                continue
            parent = section.path[:-1]
            common = 0
            while (common < min(len(parent), len(path) - 1)
                   and parent[common] == path[common]):
                common += 1
            score = (common, parent == path[:-1])
            if best is None or score > best[0]:
                best = (score, path,
                        choices[lowered.index(section.path[-1].lower())])
        if best:
            owner[section.path] = (best[1], best[2])
    selectors = {}
    sections = {s.path: s for s in root.walk()}
    for path, kind, choices, documentation in selections:
        members = {choice: sections[p] for p, (sel, choice) in owner.items()
                   if sel == path}
        listed = re.search(r"Choices:\s*\n\s*'", documentation)
        if members or listed or kind == "MultipleSelection":
            selectors[path] = (kind, choices, members)
    return selectors, owner


# ---------------------------------------------------------------------------
# The hand-written parts.

INTRODUCTION = """\
# Parameter reference

<!-- generated by scripts/parameter_reference.py; do not edit: the tables
come from the program's declarations (change the C++ sources), the other
text from the script. Run scripts/parameter_reference.py to regenerate and
scripts/parameter_reference.py --check to see whether this page is current. -->

*This page is generated by `scripts/parameter_reference.py`; do not edit
it by hand. The tables come from the program's own declarations
(`build/contact --print-parameters --json`), the rest of the text from the
script.*

A scene is a deal.II parameter file. It sets only what differs from the
defaults below, with `set` lines inside `subsection` ... `end` blocks
(the headings below are the paths of these subsections); `#` starts a
comment. For example:

```
set Dimension = 3
subsection Contact
  set Friction coefficient = 0.5
  subsection Obstacle
    set Model name = sphere
  end
end
```

- `build/contact --print-parameters` prints every parameter with its
  documentation and default; `build/contact --print-parameters scene.prm`
  prints what a scene resolves to (the defaults with the scene's
  settings); add `--json` for the same as JSON, from which this page is
  made.
- A line `include other.prm` reads another parameter file in its place
  (a path relative to the file with the `include` line); the lines after
  it override what it set. `parameters/hertz_3d_rubber.prm` starts with
  `include hertz_3d.prm` and then changes the mesh refinement, the
  material and how far the ball is pressed.
- A wrong value stops the run before it starts, with exit code 1 and one
  line: a misspelt entry or subsection, or a value outside the allowed
  values of the tables, with the file and the line; a text entry that the
  program cannot read, with the entry's full path, the value and what is
  expected, for example `<Boundary conditions/Body force> = '1,2,3' is not
  valid: 2 numbers separated by commas are expected (one per coordinate
  direction)`.
- A few defaults depend on `Dimension` (the number of components of a
  vector or a function); both are shown, marked (2D) and (3D). Entries
  marked (3D only) do not exist in a 2D scene.
- *Allowed values*: `number` and `integer` with their bounds as the
  program checks them when it reads the file; `text` is checked when the
  run starts (the syntax of the lists, vectors and functions is in
  [Syntax of the boundary conditions and loads](#syntax-of-the-boundary-conditions-and-loads)).
"""

# One worked example per entry, each from a shipped scene where one exists.
# The entry paths are checked against the program's parameters (a missing
# one is reported when the page is made).
SYNTAX_ENTRIES = [
    ("Boundary conditions", "Fixed boundaries"),
    ("Boundary conditions", "Prescribed boundaries"),
    ("Boundary conditions", "Prescribed displacement"),
    ("Boundary conditions", "Traction"),
    ("Boundary conditions", "Pressure"),
    ("Boundary conditions", "Body force"),
    ("Loading", "Load factor"),
    ("Loading", "Load table"),
    ("Loading", "Increment times"),
    ("Contact", "Obstacle", "Rigid displacement"),
    ("Material", "Formulation"),
]

SYNTAX = """\
## Syntax of the boundary conditions and loads

The entries below are text that the program reads when the run starts.
Three separators occur:

| separator | between | in |
|---|---|---|
| `;` | boundaries, or table rows | Fixed boundaries, Prescribed boundaries, Traction, Pressure, Load table (and Contact/Contact boundaries) |
| `;` | the components of a function (whose expressions may hold commas, as in `min(t, 1)`) | Prescribed displacement, Contact/Obstacle/Rigid displacement |
| `,` | the components of a constant vector, or a list of numbers | Traction (after the `:`), Body force, Increment times (and points and directions such as Contact/Obstacle/Plane/Point) |

A boundary is one of the geometry's boundary names (listed in the
description of Geometry/Model name; for a mesh file its Gmsh physical names
or Geometry/From file/Boundary names) or a boundary id (a number). A vector
has one number per coordinate direction, two in 2D and three in 3D.
Functions are muParser expressions: `+ - * / ^` (`^` for powers; `**` is an
error), `min`, `max`, `abs`, `sqrt`, `exp`, `sin`, `cos`, `if(t < 1, a, b)`,
the constant `pi`, and the time `t` (and the position where the entry says
so). Time runs from 0 to the end of the last increment; the defaults apply
the full load at t = 1.

### Boundary conditions/Fixed boundaries

From `parameters/hertz_3d.prm`, the half ball of Hertz's problem cut by
two symmetry planes (a quarter of it is computed):

```
subsection Boundary conditions
  set Fixed boundaries = x symmetry: x; y symmetry: y   # symmetry planes
end
```

The boundaries are separated by `;`. A boundary alone is clamped (all
components held at zero, as `set Fixed boundaries = left` in
`parameters/example1.prm`); `boundary: letters` holds only the components
named by the letters among `x`, `y` (and `z` in 3D), in any combination,
for example `top: yz`. Here each symmetry plane is held only normal to
itself and may slide in its plane.

### Boundary conditions/Prescribed boundaries and Prescribed displacement

From `parameters/cattaneo_3d.prm`, a half ball pressed down by its top face
and then pulled sideways:

```
subsection Boundary conditions
  set Fixed boundaries = x symmetry: x        # symmetry plane
  set Prescribed boundaries = top: yz         # pressed and pulled by its top face
  set Prescribed displacement = 0; 0.002 * max(t - 1, 0); -0.01 * min(t, 1)   # press, then pull along y
end
```

Prescribed boundaries has the syntax of Fixed boundaries. Prescribed
displacement has one muParser expression per component, separated by `;`
(two in 2D, three in 3D, also for components that no boundary prescribes:
those expressions are not used), each a function of the position `x`, `y`
(`z`) and the time `t`. It is the displacement from the start: each
increment imposes its change from the start to the end of the increment
(so a value at t = 0 is never applied). Here the top face moves down
0.01 until t = 1, then 0.002 per unit time along y; its x component is
free. A boundary both fixed and prescribed in a component stays fixed (the
program says so). The load factor does not scale prescribed displacements.

### Boundary conditions/Traction

From `parameters/example1.prm`, Kanno's example I:

```
subsection Boundary conditions
  set Fixed boundaries = left                # clamped edge x = 0
  set Traction = top: 0, -0.01               # uniform downward traction
end
```

Each item is `boundary: t_x, t_y` (`t_x, t_y, t_z` in 3D), a force per
area in the global x, y (z) directions, the same all over the boundary;
items are separated by `;`, as in `top: 0, -0.01; right: 0.001, 0`, and
two items on one boundary add up. Tractions are multiplied by the load
factor.

### Boundary conditions/Pressure

From `parameters/lame_3d.prm`, Lame's thick-walled sphere:

```
subsection Boundary conditions
  set Fixed boundaries = x symmetry: x; y symmetry: y; z symmetry: z   # symmetry planes
  set Pressure = inner: 0.01                  # internal pressure (force/area)
end
```

Each item is `boundary: p`, items separated by `;`. A positive pressure
pushes on the surface against its outward normal (into the body), a
negative one pulls. Unlike a traction it follows the direction of the
normal along a curved boundary (the normal of the undeformed mesh). It is
multiplied by the load factor, and adds to a traction on the same
boundary.

### Boundary conditions/Body force

No shipped scene sets a body force. The weight of a steel body in SI
units, along -z in a 3D scene (density 7850 kg/m^3 times g = 9.81 m/s^2):

```
subsection Boundary conditions
  set Body force = 0, 0, -7.7e4   # N/m^3
end
```

The force per volume, one number per coordinate direction separated by
commas (`0, -7.7e4` in 2D), constant over the body and multiplied by the
load factor. A count that does not match Dimension is an error.

### Loading/Load factor

From `tests/one_increment.prm`, the full load of example I reached in one
increment ending at t = 2:

```
subsection Loading
  set End time = 2
  set Number of increments = 1
  set Load factor = t / 2
end
```

lambda(t), a muParser expression of the time `t`, multiplies the loads:
Traction, Pressure and Body force. It does not scale Prescribed
displacement or the obstacle's Rigid displacement, which are functions of
t themselves. The default `t` reaches the full load at t = 1.

### Loading/Load table

From `parameters/press_and_drag.prm`, press, hold, drag, unload:

```
subsection Loading
  set Load table = 0: 0; 1: 1; 3: 1; 4: 0    # press, hold, drag, unload
end
```

Pairs `t: lambda` separated by `;`, with increasing times; lambda is
linear between them and constant before the first and after the last.
A table replaces Load factor (the program says so if both are set). Here
the load rises to its full value by t = 1, holds until t = 3 (while the
obstacle is dragged, see below) and is removed by t = 4.

### Loading/Increment times

From `parameters/cattaneo_3d.prm`:

```
subsection Loading
  set Increment times = 1, 2, 3               # pressed; Q / mu P about 0.3 and 0.55
end
```

The end times of the increments, positive and increasing, separated by
commas; the first increment starts at t = 0. They replace End time and
Number of increments (here the same as `End time = 3` and `Number of
increments = 3`); uneven steps, as in `parameters/press_and_drag.prm`,
need the list.

### Contact/Obstacle/Rigid displacement

From `parameters/press_and_drag.prm`, the floor dragged sideways:

```
subsection Contact
  subsection Obstacle
    set Rigid displacement = 0.02 * min(max(t - 2, 0), 1); 0   # floor moves +x in [2, 3]
    subsection Plane
      set Point = 0, -0.01                   # floor 0.01 below the body
    end
  end
end
```

The translation of the whole obstacle from where its subsection (here
Plane) puts it: one muParser expression of `t` per component, separated
by `;`. Here the floor moves 0.02 along +x between t = 2 and t = 3 and
stays put otherwise. The obstacle does not rotate.

### Material/Formulation

From `tests/lame_3d_standard.prm`, Lame's sphere at nu = 0.4999 with the
standard element forced (to show that it locks):

```
subsection Material
  set Formulation = standard
end
```

`auto` (the default) uses the B-bar element when Poisson's ratio exceeds
0.45, in 3D and in plane strain, and the standard Q1 element otherwise;
`standard` and `B-bar` force one. Forcing the standard element on a nearly
incompressible body gives a warning. Linear solver/Nearly incompressible
solves chooses how the B-bar systems are solved.
"""


# ---------------------------------------------------------------------------
# The page.

DIMS = (2, 3)


def render(trees):
    root = Section((), trees)
    selectors, owner = families(root)
    sections = list(root.walk())
    used = set()
    anchors = {s.path: slug(s.title, used) for s in sections}
    syntax_anchor = slug("Syntax of the boundary conditions and loads", used)
    syntax_anchors = {}
    for heading in re.findall(r"^### (.*)$", SYNTAX, re.M):
        anchor = slug(heading, used)
        path = tuple(heading.split(" and ")[0].split("/"))
        syntax_anchors[path] = anchor
        if heading.endswith("and Prescribed displacement"):
            syntax_anchors[path[:-1] + ("Prescribed displacement",)] = anchor

    by_path = {s.path: s for s in sections}
    unresolved = []

    def reference(section, name):
        """The anchor of <name> in a description of an entry of section:
        a subsection or an entry, by its full path or relative to the
        section or one of its parents."""
        parts = tuple(p.strip() for p in name.split("/"))
        for depth in range(len(section.path), -1, -1):
            full = section.path[:depth] + parts
            if full in by_path:
                return anchors[full]
            if full[:-1] in by_path and full[-1] in by_path[full[:-1]].entries:
                return anchors[full[:-1]]
        unresolved.append(f"<{name}> in {section.title}")
        return None

    def link(path):
        return f"[{'/'.join(path) or 'Top level'}](#{anchors[path]})"

    def membership(path):
        selector, choice = owner[path]
        return (f"read only when {'/'.join(selector)} "
                f"{'includes' if selectors[selector][0] == 'MultipleSelection' else '='} "
                f"`{choice}`")

    out = [INTRODUCTION]

    # Plugin families.
    if selectors:
        out.append("## Plugin families\n")
        out.append("These entries choose plugins (a geometry, an obstacle, "
                   "a method, ...). A chosen plugin reads its entries from "
                   "the subsection named like it (the name with a capital "
                   "initial); the subsections of the others are ignored.\n")
        out.append("| entry | default | choices and their subsections |")
        out.append("|---|---|---|")
        for path, (kind, choices, members) in selectors.items():
            by_dim = root_entry(root, path)
            default = per_dimension(
                {d: e["default_value"] for d, e in by_dim.items()}, code)
            parts = []
            for choice in choices:
                member = members.get(choice)
                parts.append(f"`{choice}`: {link(member.path)}" if member
                             else f"`{choice}`")
            if not members:
                parts.append(f"(no subsections: their entries, if any, are "
                             f"in {link(path[:-1])})")
            name = f"[{'/'.join(path)}](#{anchors[path[:-1]]})"
            out.append(f"| {name} | {default} | "
                       f"{'; '.join(parts).replace('|', chr(92) + '|')} |")
        out.append("")

    # Contents.
    out.append("## Contents\n")
    for section in sections:
        depth = max(len(section.path) - 1, 0)
        note = f" ({membership(section.path)})" if section.path in owner else ""
        out.append(f"{'  ' * depth}- {link(section.path)}{note}")
    out.append(f"- [Syntax of the boundary conditions and loads]"
               f"(#{syntax_anchor})")
    out.append("")

    # One table per subsection.
    for section in sections:
        out.append(f"## {section.title}\n")
        if section.path in owner:
            note = membership(section.path)
            out.append(f"*{note[0].upper()}{note[1:]}.*\n")
        if section.entries:
            out.append("| entry | default | allowed values | description |")
            out.append("|---|---|---|---|")
            for name, by_dim in section.entries.items():
                default = per_dimension(
                    {d: e["default_value"] for d, e in by_dim.items()}, code,
                    mark_only=False)
                allowed = per_dimension(
                    {d: allowed_values(e["pattern_description"])
                     for d, e in by_dim.items()}, cell, mark_only=False)
                description = per_dimension(
                    {d: e["documentation"] for d, e in by_dim.items()},
                    lambda text: cell(text, lambda n: reference(section, n))
                    if text.strip() else "*(no description)*",
                    mark_only=False)
                label = cell(name)
                if len(by_dim) < len(DIMS):
                    label += "<br>" + " ".join(f"*({d}D only)*"
                                               for d in sorted(by_dim))
                path = section.path + (name,)
                if path in syntax_anchors:
                    description += (f" See the [example]"
                                    f"(#{syntax_anchors[path]}).")
                out.append(f"| {label} | {default} | {allowed} | "
                           f"{description} |")
            out.append("")
        for name in section.entries:
            path = section.path + (name,)
            if path not in selectors:
                continue
            kind, choices, members = selectors[path]
            if members:
                chosen = ", ".join(f"{link(m.path)} (`{c}`)"
                                   for c, m in members.items())
                rest = [c for c in choices if c not in members]
                out.append(
                    f"**{name}** chooses "
                    + ("plugins" if kind == "MultipleSelection"
                       else "a plugin")
                    + f"; each choice reads its own subsection: {chosen}."
                    + (f" Without a subsection (no entries of their own): "
                       f"{', '.join(f'`{c}`' for c in rest)}." if rest else "")
                    + "\n")
            else:
                out.append(f"**{name}** chooses plugins; they have no "
                           f"subsections of their own: their entries, if "
                           f"any, are in the table above.\n")
        if section.subsections:
            out.append("Subsections: " + ", ".join(
                link(s.path) for s in section.subsections.values()) + ".\n")

    out.append(SYNTAX)
    text = "\n".join(out)
    text = re.sub(r"\n{3,}", "\n\n", text).rstrip("\n") + "\n"

    present = {s.path + (n,) for s in sections for n in s.entries}
    missing = [p for p in SYNTAX_ENTRIES if p not in present]
    warnings = [f"the syntax section of {SCRIPT} describes "
                f"<{'/'.join(path)}>, which the program does not declare"
                for path in missing]
    warnings += [f"a description refers to {name}, which is neither an "
                 f"entry nor a subsection" for name in dict.fromkeys(unresolved)]
    return text, warnings


def root_entry(root, path):
    section = root
    for name in path[:-1]:
        section = section.subsections[name]
    return section.entries[path[-1]]


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        usage="%(prog)s [--contact build/contact] "
              "[--output doc/parameters.md] [--check]")
    parser.add_argument("--contact",
                        default=os.path.join(ROOT, "build", "contact"),
                        help="the program (default: build/contact of this "
                             "project)")
    parser.add_argument("--output",
                        default=os.path.join(ROOT, "doc", "parameters.md"),
                        help="the page (default: doc/parameters.md of this "
                             "project)")
    parser.add_argument("--check", action="store_true",
                        help="write nothing; exit with 1 and show the "
                             "difference if the page is not current")
    arguments = parser.parse_args()

    trees = {2: run_program(arguments.contact)}
    with tempfile.NamedTemporaryFile("w", suffix=".prm",
                                     delete=False) as scene:
        scene.write("set Dimension = 3\n")
    try:
        trees[3] = run_program(arguments.contact, scene.name)
    finally:
        os.unlink(scene.name)
    text, warnings = render(trees)
    for warning in warnings:
        print(f"warning: {warning}", file=sys.stderr)

    if arguments.check:
        try:
            with open(arguments.output, encoding="utf-8") as f:
                current = f.read()
        except OSError as error:
            print(f"{arguments.output}: {error.strerror}; run {SCRIPT}")
            return 1
        if current == text:
            print(f"{arguments.output} is current")
            return 0
        diff = list(difflib.unified_diff(
            current.splitlines(), text.splitlines(),
            os.path.relpath(arguments.output) + " (on disk)",
            os.path.relpath(arguments.output) + " (regenerated)",
            lineterm=""))
        print("\n".join(diff[:DIFF_LINES]))
        if len(diff) > DIFF_LINES:
            print(f"... ({len(diff) - DIFF_LINES} more lines of difference)")
        print(f"{arguments.output} is out of date: run {SCRIPT}")
        return 1

    with open(arguments.output, "w", encoding="utf-8") as f:
        f.write(text)
    print(f"wrote {arguments.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
