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
sources; `--check` tells whether doc/parameters.md is current. The
hand-written text (the introduction and the syntax section) is in
scripts/parameter_reference_text.py.
"""
import argparse
import difflib
import json
import os
import re
import subprocess
import sys
import tempfile

from parameter_reference_text import INTRODUCTION, SYNTAX, SYNTAX_ENTRIES

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


def selection_entries(root):
    """(path, kind, choices, documentation) of every Selection and
    MultipleSelection entry, as the last dimension declares it."""
    selections = []
    for section in root.walk():
        for name, by_dim in section.entries.items():
            entry = by_dim[max(by_dim)]
            kind, choices = options(entry)
            if kind:
                selections.append((section.path + (name,), kind, choices,
                                   entry["documentation"]))
    return selections


def choice_owner(section, selections):
    """(selector path, choice) of the selection with a choice named like
    the section (case aside): of those, the one whose path shares the most
    leading names with the section's parent, then the one in that parent;
    None if no choice is named like it."""
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
    return (best[1], best[2]) if best else None


def families(root):
    """(selectors, owner): selectors maps an entry's path to (kind,
    choices, {choice: Section}); owner maps a subsection's path to
    (selector path, choice)."""
    selections = selection_entries(root)
    owner = {}
    for section in root.walk():
        if not section.path:
            continue
        found = choice_owner(section, selections)
        if found:
            owner[section.path] = found
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
# The page.

DIMS = (2, 3)


def example_anchors(used):
    """Entry path -> the anchor of its worked example in SYNTAX (the
    heading on Prescribed boundaries covers Prescribed displacement)."""
    anchors = {}
    for heading in re.findall(r"^### (.*)$", SYNTAX, re.M):
        anchor = slug(heading, used)
        path = tuple(heading.split(" and ")[0].split("/"))
        anchors[path] = anchor
        if heading.endswith("and Prescribed displacement"):
            anchors[path[:-1] + ("Prescribed displacement",)] = anchor
    return anchors


class Page:
    """What the page's parts are made of: the subsections in the
    program's order, the plugin families, the anchors of the headings, and
    the references in descriptions that match no heading."""

    def __init__(self, trees):
        self.root = Section((), trees)
        self.selectors, self.owner = families(self.root)
        self.sections = list(self.root.walk())
        used = set()
        self.anchors = {s.path: slug(s.title, used) for s in self.sections}
        self.syntax_anchor = slug(
            "Syntax of the boundary conditions and loads", used)
        self.syntax_anchors = example_anchors(used)
        self.by_path = {s.path: s for s in self.sections}
        self.unresolved = []

    def reference(self, section, name):
        """The anchor of <name> in a description of an entry of section:
        a subsection or an entry, by its full path or relative to the
        section or one of its parents."""
        parts = tuple(p.strip() for p in name.split("/"))
        for depth in range(len(section.path), -1, -1):
            full = section.path[:depth] + parts
            if full in self.by_path:
                return self.anchors[full]
            if (full[:-1] in self.by_path
                    and full[-1] in self.by_path[full[:-1]].entries):
                return self.anchors[full[:-1]]
        self.unresolved.append(f"<{name}> in {section.title}")
        return None

    def link(self, path):
        return f"[{'/'.join(path) or 'Top level'}](#{self.anchors[path]})"

    def membership(self, path):
        selector, choice = self.owner[path]
        kind = self.selectors[selector][0]
        return (f"read only when {'/'.join(selector)} "
                f"{'includes' if kind == 'MultipleSelection' else '='} "
                f"`{choice}`")

    def families_table(self):
        """The lines of the section on the plugin families (none if the
        program has none)."""
        if not self.selectors:
            return []
        out = ["## Plugin families\n",
               "These entries choose plugins (a geometry, an obstacle, "
               "a method, ...). A chosen plugin reads its entries from "
               "the subsection named like it (the name with a capital "
               "initial); the subsections of the others are ignored.\n",
               "| entry | default | choices and their subsections |",
               "|---|---|---|"]
        for path, (kind, choices, members) in self.selectors.items():
            by_dim = root_entry(self.root, path)
            default = per_dimension(
                {d: e["default_value"] for d, e in by_dim.items()}, code)
            parts = []
            for choice in choices:
                member = members.get(choice)
                parts.append(f"`{choice}`: {self.link(member.path)}" if member
                             else f"`{choice}`")
            if not members:
                parts.append(f"(no subsections: their entries, if any, are "
                             f"in {self.link(path[:-1])})")
            name = f"[{'/'.join(path)}](#{self.anchors[path[:-1]]})"
            out.append(f"| {name} | {default} | "
                       f"{'; '.join(parts).replace('|', chr(92) + '|')} |")
        out.append("")
        return out

    def contents(self):
        """The lines of the list of subsections."""
        out = ["## Contents\n"]
        for section in self.sections:
            depth = max(len(section.path) - 1, 0)
            note = (f" ({self.membership(section.path)})"
                    if section.path in self.owner else "")
            out.append(f"{'  ' * depth}- {self.link(section.path)}{note}")
        out.append(f"- [Syntax of the boundary conditions and loads]"
                   f"(#{self.syntax_anchor})")
        out.append("")
        return out

    def entry_row(self, section, name, by_dim):
        """The table row of one entry of section."""
        default = per_dimension(
            {d: e["default_value"] for d, e in by_dim.items()}, code,
            mark_only=False)
        allowed = per_dimension(
            {d: allowed_values(e["pattern_description"])
             for d, e in by_dim.items()}, cell, mark_only=False)
        description = per_dimension(
            {d: e["documentation"] for d, e in by_dim.items()},
            lambda text: cell(text, lambda n: self.reference(section, n))
            if text.strip() else "*(no description)*",
            mark_only=False)
        label = cell(name)
        if len(by_dim) < len(DIMS):
            label += "<br>" + " ".join(f"*({d}D only)*"
                                       for d in sorted(by_dim))
        path = section.path + (name,)
        if path in self.syntax_anchors:
            description += (f" See the [example]"
                            f"(#{self.syntax_anchors[path]}).")
        return f"| {label} | {default} | {allowed} | {description} |"

    def choosers(self, section):
        """The lines saying which subsections the entries of section that
        choose plugins read."""
        out = []
        for name in section.entries:
            path = section.path + (name,)
            if path not in self.selectors:
                continue
            kind, choices, members = self.selectors[path]
            if members:
                chosen = ", ".join(f"{self.link(m.path)} (`{c}`)"
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
        return out

    def section_part(self, section):
        """The lines of a subsection's heading, table of entries, plugin
        choices and links to its subsections."""
        out = [f"## {section.title}\n"]
        if section.path in self.owner:
            note = self.membership(section.path)
            out.append(f"*{note[0].upper()}{note[1:]}.*\n")
        if section.entries:
            out.append("| entry | default | allowed values | description |")
            out.append("|---|---|---|---|")
            for name, by_dim in section.entries.items():
                out.append(self.entry_row(section, name, by_dim))
            out.append("")
        out += self.choosers(section)
        if section.subsections:
            out.append("Subsections: " + ", ".join(
                self.link(s.path) for s in section.subsections.values())
                + ".\n")
        return out

    def warnings(self):
        """Entries of SYNTAX_ENTRIES that the program does not declare, and
        the references in descriptions that match no heading (call it
        after the sections' parts are made)."""
        present = {s.path + (n,) for s in self.sections for n in s.entries}
        missing = [p for p in SYNTAX_ENTRIES if p not in present]
        warnings = [f"the syntax section of {SCRIPT} describes "
                    f"<{'/'.join(path)}>, which the program does not declare"
                    for path in missing]
        warnings += [f"a description refers to {name}, which is neither an "
                     f"entry nor a subsection"
                     for name in dict.fromkeys(self.unresolved)]
        return warnings


def render(trees):
    """The page made from the program's parameter trees ({dim: JSON}), and
    the warnings about it."""
    page = Page(trees)
    out = [INTRODUCTION]
    out += page.families_table()
    out += page.contents()
    for section in page.sections:
        out += page.section_part(section)
    out.append(SYNTAX)
    text = "\n".join(out)
    text = re.sub(r"\n{3,}", "\n\n", text).rstrip("\n") + "\n"
    return text, page.warnings()


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
