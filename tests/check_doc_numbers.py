#!/usr/bin/env python3
"""Checks that the numbers the documentation quotes cannot go stale: README.md,
bench/README.md and every Markdown page under doc/.

usage: check_doc_numbers.py <source dir> <contact program>
       check_doc_numbers.py --self-test

1. no page quotes the size or the run time of the test suite ("352 tests",
   "281 s on 2 cores" in a sentence about ctest or the suite): ctest prints
   both at its end, and a number written down drifts;
2. no page names an issue number ("issue 19", "issue #36", "issues 19 and
   36"): the pages speak of goals and measurements;
3. the tables and inline quotes of the bench CSVs (`<!-- table: name -->`,
   `<!-- quote: name -->text<!-- end quote -->`) are what bench/doc_tables.py
   makes of the CSVs in doc/benchmarks/;
4. doc/benchmarks/README.md names every CSV file of doc/benchmarks/, and
   every CSV file it names is there;
5. doc/adding-a-geometry.md names (as `value`) every value of the Selections
   Geometry/Model name and Contact/Obstacle/Model name that
   `<contact program> --print-parameters --json` declares in 2D or 3D, and
   the first column of its "... shipped" tables names only such values;
6. a tolerance (1e-N) quoted beside a test name, in a table row or a
   sentence of README.md or doc/validation.md, is one that
   tests/*.cmake gives that test (the "name:tolerance:..." items of its
   foreach lists, and `--tolerance` of tests added by name); a sentence on a
   family of tests (FAMILIES: "the contact patch test") that quotes
   tolerances quotes each one the family's tests use, and no other;
   numbers after "measured" are measurements, not tolerances;
7. a tmpfs size quoted ("600 kB tmpfs") is one that a test script under
   tests/ mounts (size=600k).

Prints one line per problem, 'page:line: what', then a summary; exit code 1
if there is a problem, 0 if not, 2 if the program could not be run.
--self-test runs every check on made-up pages in a temporary folder and
asserts that each finds its problem (and nothing on the corrected pages).
"""
import glob
import importlib
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))

# Phrases by which prose names a family of tests, and the start of the names
# of its tests.
FAMILIES = {"contact patch test": "patch_test_"}
# The Selections whose values doc/adding-a-geometry.md lists, and the word
# of the heading of the table that lists them.
SELECTIONS = {"Geometry/Model name": "Geometries",
              "Contact/Obstacle/Model name": "Obstacles"}
GEOMETRY_PAGE = os.path.join("doc", "adding-a-geometry.md")
BENCHMARKS_PAGE = os.path.join("doc", "benchmarks", "README.md")


# -- pages ---------------------------------------------------------------------

def pages(root):
    found = [p for p in ("README.md", os.path.join("bench", "README.md"))
             if os.path.isfile(os.path.join(root, p))]
    for folder, subfolders, names in os.walk(os.path.join(root, "doc")):
        subfolders.sort()
        found += [os.path.relpath(os.path.join(folder, name), root)
                  for name in sorted(names) if name.endswith(".md")]
    return found


def read(root, page):
    with open(os.path.join(root, page), errors="replace") as f:
        return f.read().split("\n")


def units(lines):
    """The prose of a page outside code blocks: ('row', line, text) for each
    table row and ('prose', line, text) for each paragraph or list item
    (its lines joined by newlines). Line numbers start at 1."""
    found = []
    current, start, fence = [], 0, None

    def flush():
        nonlocal current
        if current:
            found.append(("prose", start, "\n".join(current)))
        current = []

    for number, line in enumerate(lines, 1):
        stripped = line.strip()
        marker = re.match(r"(```+|~~~+)", stripped)
        if fence:
            if marker and stripped.startswith(fence):
                fence = None
            continue
        if marker:
            flush()
            fence = marker.group(1)
            continue
        if not stripped or line.startswith("    ") and not current:
            flush()
            continue
        if stripped.startswith("|"):
            flush()
            found.append(("row", number, line))
            continue
        if re.match(r"\s*([-*+]|\d+\.)\s", line) or stripped.startswith("#"):
            flush()
        if not current:
            start = number
        current.append(line)
    flush()
    return found


def clauses(text):
    """(offset, clause) of a paragraph: split after '. ' before a capital,
    a backtick or a parenthesis, and at ';' outside parentheses."""
    found, begin, depth = [], 0, 0
    for index, char in enumerate(text):
        if char == "(":
            depth += 1
        elif char == ")":
            depth = max(0, depth - 1)
        cut = False
        if char == ";" and depth == 0:
            cut = True
        elif char == "." and re.match(r"\.\s+[A-Z`(*]", text[index:index + 3]) \
                and not re.search(r"\b(e\.g|i\.e|cf|vs|Fig|eq)$", text[begin:index]):
            cut = True
        if cut:
            found.append((begin, text[begin:index + 1]))
            begin = index + 1
    if text[begin:].strip():
        found.append((begin, text[begin:]))
    return found


def line_at(start, text, offset):
    return start + text.count("\n", 0, offset)


# -- 1. the size and time of the test suite -----------------------------------

SUITE = re.compile(r"\b(test suite|the suite|whole suite|ctest)\b", re.I)
TEST_COUNT = re.compile(r"(?<![\w.,])\d[\d,]*\s+(?:[A-Za-z]+\s+)?tests\b")
DURATION = re.compile(r"(?<![\w.])\d+(?:\.\d+)?\s*(?:s|seconds?|min|minutes?|h|hours?)\b")


def suite_numbers(root, page, lines):
    problems = []
    for kind, start, text in units(lines):
        for offset, clause in clauses(text) if kind == "prose" else [(0, text)]:
            if not SUITE.search(clause):
                continue
            for m in TEST_COUNT.finditer(clause):
                problems.append((page, line_at(start, text, offset + m.start()),
                                 f"quotes the size of the test suite ('{m.group(0)}'): "
                                 "ctest prints it at its end; do not write it down"))
            for m in DURATION.finditer(clause):
                after = clause[m.end():m.end() + 40]
                before = clause[max(0, m.start() - 30):m.start()]
                if re.match(r"\s+in the suite", after):
                    continue            # a setting the suite uses
                cores = re.match(r"[\s,]+on \d+ cores?", after)
                if cores or re.search(r"\b(in|takes|took|runs in|ran in)\s+"
                                      r"(?:about\s+|some\s+|roughly\s+|under\s+)?$",
                                      before):
                    problems.append((page, line_at(start, text, offset + m.start()),
                                     f"quotes the run time of the test suite "
                                     f"('{m.group(0)}{cores.group(0) if cores else ''}'): "
                                     "ctest prints it at its end; do not write it down"))
    return problems


# -- 2. issue numbers ------------------------------------------------------------

ISSUE = re.compile(r"\bissues?\s*#?\s*\d+(?:\s*(?:,|and|or)\s*#?\d+)*", re.I)


def issue_numbers(root, page, lines):
    return [(page, number, f"names an issue number ('{m.group(0)}'): say which goal "
             "or change is meant")
            for number, line in enumerate(lines, 1) for m in ISSUE.finditer(line)]


# -- 3. tables and quotes of the bench CSVs -------------------------------------

def csv_quotes(root, doc_tables):
    return [(page, line, f"{what} (run python3 bench/doc_tables.py to rewrite it "
             "from the CSV)")
            for page, line, what in doc_tables.differences(root, check=True)]


# -- 4. the CSV files of doc/benchmarks/ ------------------------------------------

def benchmark_files(root):
    folder = os.path.join(root, "doc", "benchmarks")
    page = os.path.join(root, BENCHMARKS_PAGE)
    if not os.path.isfile(page):
        return [(BENCHMARKS_PAGE, 1, "missing: it should describe the CSV files of "
                 "doc/benchmarks/")]
    lines = read(root, BENCHMARKS_PAGE)
    named = {}
    for number, line in enumerate(lines, 1):
        for m in re.finditer(r"(?<![\w./-])(?:doc/benchmarks/)?([\w.-]+\.csv)\b", line):
            named.setdefault(m.group(1), number)
    problems = []
    present = sorted(os.path.basename(p) for p in glob.glob(os.path.join(folder, "*.csv")))
    for name in present:
        if name not in named:
            problems.append((BENCHMARKS_PAGE, 1, f"does not name {name}, which is in "
                             "doc/benchmarks/: add a line saying which bench script "
                             "writes it and what it holds"))
    for name, number in named.items():
        if name not in present:
            problems.append((BENCHMARKS_PAGE, number, f"names {name}, which is not in "
                             "doc/benchmarks/"))
    return problems


# -- 5. the geometries and obstacles of doc/adding-a-geometry.md ------------------

def declared_selections(program):
    """Entry path -> the values of its Selection, in 2D and 3D."""
    environment = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
                       OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    values = {path: set() for path in SELECTIONS}
    with tempfile.TemporaryDirectory() as folder:
        scene = os.path.join(folder, "three_d.prm")
        with open(scene, "w") as out:
            out.write("set Dimension = 3\n")
        for extra in ([], [scene]):
            done = subprocess.run([program, "--print-parameters", "--json"] + extra,
                                  capture_output=True, text=True, cwd=folder,
                                  env=environment, timeout=300)
            if done.returncode != 0:
                raise RuntimeError(f"'{program} --print-parameters --json "
                                   f"{' '.join(extra)}' exited with {done.returncode}: "
                                   f"{done.stderr.strip()}")
            tree = json.loads(done.stdout)
            for path in SELECTIONS:
                node = tree
                for part in path.split("/"):
                    node = node.get(part, {}) if isinstance(node, dict) else {}
                m = re.match(r"\[Selection (.*?) ?\]$", node.get("pattern_description", ""))
                if not m:
                    raise RuntimeError(f"the program declares no Selection {path}")
                values[path].update(v.strip() for v in m.group(1).split("|"))
    return values


def geometry_page(root, selections):
    if not os.path.isfile(os.path.join(root, GEOMETRY_PAGE)):
        return [(GEOMETRY_PAGE, 1, "missing")]
    lines = read(root, GEOMETRY_PAGE)
    spans = {m.group(1).strip() for line in lines
             for m in re.finditer(r"`([^`]+)`", line)}
    problems = []
    heading_lines = {}
    section = None
    for number, line in enumerate(lines, 1):
        if line.startswith("#"):
            section = None
            for path, word in SELECTIONS.items():
                if word.lower() in line.lower() and "shipped" in line.lower():
                    section = path
                    heading_lines[path] = number
            continue
        m = re.match(r"\|\s*`([^`]+)`\s*\|", line)
        header = number < len(lines) and re.match(r"\s*\|\s*:?-", lines[number])
        if section and m and not header and m.group(1).strip() not in selections[section]:
            problems.append((GEOMETRY_PAGE, number,
                             f"lists '{m.group(1)}', which is no value of {section} "
                             f"({'|'.join(sorted(selections[section]))})"))
    for path, values in selections.items():
        for value in sorted(values - spans):
            problems.append((GEOMETRY_PAGE, heading_lines.get(path, 1),
                             f"does not name `{value}`, a value of {path}: list it "
                             "with its class and source file"))
    return problems


# -- 6. tolerances beside test names ----------------------------------------------

NUMBER = r"\d+(?:\.\d+)?(?:[eE][-+]?\d+)?"
TOLERANCE = re.compile(r"(?<![\w.])\d(?:\.\d+)?e-\d+\b")


def calls(text, name):
    """The argument texts of every call `name(...)` in CMake text (quotes and
    nested parentheses inside it kept)."""
    found = []
    for m in re.finditer(r"\b%s\s*\(" % re.escape(name), text):
        depth, quoted, index = 1, False, m.end()
        while index < len(text) and depth:
            char = text[index]
            if char == '"':
                quoted = not quoted
            elif not quoted and char == "(":
                depth += 1
            elif not quoted and char == ")":
                depth -= 1
            index += 1
        found.append(text[m.end():index - 1])
    return found


def base_name(test):
    return re.sub(r"\.mpirun=\d+", "", test).split(".")[0]


def cmake_tolerances(root):
    """Test name (without .mpirun=N and suffixes) -> the tolerances the
    CMake files give it."""
    tolerances = {}
    for path in sorted(glob.glob(os.path.join(root, "tests", "*.cmake"))):
        with open(path) as f:
            text = re.sub(r"#[^\n]*", "", f.read())
        for arguments in calls(text, "foreach"):
            for item in re.findall(r'"[^"]*"|[^\s"]+', arguments)[1:]:
                fields = item.strip('"').split(":")
                if len(fields) >= 2 and re.fullmatch(NUMBER, fields[1]) \
                        and re.fullmatch(r"[\w.=]+", fields[0]):
                    tolerances.setdefault(base_name(fields[0]), set()).add(
                        float(fields[1]))
        for function in ("add_test", "contact_compare_tables", "contact_compare_statistics"):
            for arguments in calls(text, function):
                words = re.findall(r'"[^"]*"|[^\s"]+', arguments)
                if words and words[0] == "NAME":
                    words = words[1:]
                tolerance = [words[i + 1] for i, w in enumerate(words[:-1])
                             if w == "--tolerance"]
                if words and "$" not in words[0] and tolerance \
                        and re.fullmatch(NUMBER, tolerance[0]):
                    tolerances.setdefault(base_name(words[0]), set()).add(
                        float(tolerance[0]))
    return tolerances


def quoted_tolerances(text):
    """The tolerances quoted in a text: 1e-N not after 'measured'."""
    return [(m.start(), m.group(0)) for m in TOLERANCE.finditer(text)
            if not re.search(r"measured[^,;()]{0,12}$", text[:m.start()])]


def names(values):
    return " and ".join(re.sub(r"e([-+])0*(\d)", r"e\1\2", f"{v:g}")
                        for v in sorted(values, reverse=True))


def test_tolerances(root, page, lines, tolerances):
    problems = []
    if page not in ("README.md", os.path.join("doc", "validation.md")):
        return problems
    for kind, start, text in units(lines):
        parts = [(0, text)] if kind == "row" else clauses(text)
        for offset, part in parts:
            quoted = quoted_tolerances(part)
            if not quoted:
                continue
            tests = {base_name(re.sub(r"^tests/|\.(prm|output)$", "", m.group(1)))
                     for m in re.finditer(r"`([\w./=-]+)`", part)}
            tests &= set(tolerances)
            if tests:
                allowed = set().union(*(tolerances[t] for t in tests))
                for position, value in quoted:
                    if float(value) not in allowed:
                        problems.append((page, line_at(start, text, offset + position),
                                         f"quotes {value} for {', '.join(sorted(tests))}; "
                                         f"tests/*.cmake holds it to {names(allowed)}"))
                continue
            if kind != "prose":
                continue
            for phrase, prefix in FAMILIES.items():
                if phrase not in part.lower():
                    continue
                family = set().union(*([tolerances[t] for t in tolerances
                                        if t.startswith(prefix)] or [set()]))
                if not family:
                    continue
                said = {float(v) for _, v in quoted}
                if said != family:
                    problems.append((page, line_at(start, text, offset + quoted[0][0]),
                                     f"quotes {names(said)} for the {phrase}; the tests "
                                     f"{prefix}* of tests/*.cmake are held to {names(family)}: "
                                     "say which tests are held to which"))
    return problems


# -- 7. tmpfs sizes ----------------------------------------------------------------

def tmpfs_sizes(root, page, lines):
    mounted = set()
    for script in glob.glob(os.path.join(root, "tests", "**", "*.sh"), recursive=True):
        with open(script, errors="replace") as f:
            text = f.read()
        if "tmpfs" in text:
            mounted |= {int(m.group(1)) for m in re.finditer(r"size=(\d+)k\b", text)}
    problems = []
    for number, line in enumerate(lines, 1):
        for m in re.finditer(r"(\d+)\s*kB\s+tmpfs|tmpfs of (\d+)\s*kB", line):
            size = int(m.group(1) or m.group(2))
            if size not in mounted:
                problems.append((page, number, f"quotes a {size} kB tmpfs; the test "
                                 f"scripts mount {', '.join(f'{s} kB' for s in sorted(mounted)) or 'none'}"))
    return problems


# -- all of them --------------------------------------------------------------------

def import_doc_tables(bench_folder):
    sys.path.insert(0, bench_folder)
    try:
        return importlib.import_module("doc_tables")
    finally:
        sys.path.remove(bench_folder)


def check(root, selections, doc_tables, only=None):
    """Every problem, (page, line, what); only: the numbers of the checks to
    run (all by default)."""
    only = only or {1, 2, 3, 4, 5, 6, 7}
    problems = []
    tolerances = cmake_tolerances(root) if 6 in only else {}
    for page in pages(root):
        lines = read(root, page)
        if 1 in only:
            problems += suite_numbers(root, page, lines)
        if 2 in only:
            problems += issue_numbers(root, page, lines)
        if 6 in only:
            problems += test_tolerances(root, page, lines, tolerances)
        if 7 in only:
            problems += tmpfs_sizes(root, page, lines)
    if 3 in only:
        problems += csv_quotes(root, doc_tables)
    if 4 in only:
        problems += benchmark_files(root)
    if 5 in only:
        problems += geometry_page(root, selections)
    return problems


# -- self-test -------------------------------------------------------------------------

SELF_TEST_SELECTIONS = {"Geometry/Model name": {"box", "half ball"},
                        "Contact/Obstacle/Model name": {"plane", "sphere"}}

SELF_TEST_FILES = {
    "tests/comparisons.cmake": '''
foreach(_case
    "patch_test_two_bodies_2d:1e-10:ux=0.39*0.01/(0.91*2)*x:uy=-0.005*y:0.01/(0.91*2)"
    "patch_test_two_bodies_2d_friction:1e-8:ux=0.39*0.01/(0.91*2)*x:uy=-0.005*y:0.01"
    hertz_2d:hertz)
endforeach()
add_test(NAME patch_test_2d.exact
  COMMAND compare_csv.py out.csv --exact "ux=0.05*x" --tolerance 1e-8)
''',
    "tests/full_disk.sh": "mount -t tmpfs -o size=600k tmpfs disk\n",
    "doc/benchmarks/multigrid.csv":
        "n_y,ranks,path,newton_iterations,contact_krylov_iterations,converged\n"
        '64,2,"geometric multigrid, K matrix-free",19,189,1\n',
    "doc/benchmarks/series.csv": "a,b\n1,2\n",
}

# Check number -> (page, bad text, its corrected text, a word of the problem).
SELF_TEST_CASES = {
    1: ("README.md",
        "`ctest --test-dir build` runs the whole suite (352 tests; 281 s on 2 "
        "cores in the last run).\n\nThe test suite runs in about 6 minutes.\n",
        "`ctest --test-dir build` runs the whole suite; ctest prints how many "
        "tests ran and how long they took (`--timeout`, 10 s in the suite).\n",
        "test suite"),
    2: ("doc/performance.md",
        "## Goals of issue 19 and where they stand\n\nThe goal of issue #36 "
        "and of issues 31 and 33.\n",
        "## Performance goals and where they stand\n\nThe goal of the "
        "multigrid.\n",
        "issue number"),
    3: ("doc/algorithm.md",
        "went to <!-- quote: multigrid-1.6m -->22 and\n195<!-- end quote --> with it\n",
        "went to <!-- quote: multigrid-1.6m -->19\nand 189<!-- end quote --> with it\n",
        "multigrid-1.6m"),
    4: ("doc/benchmarks/README.md",
        "| `gone.csv` | nothing |\n",
        "| `series.csv` | the series (`bench/run_series.py`) |\n"
        "| `multigrid.csv` | the multigrid (`bench/multigrid.py`) |\n",
        ".csv"),
    5: ("doc/adding-a-geometry.md",
        "## Obstacles shipped\n\n| `plane` | P |\n| `torus` | T |\n\n"
        "## Geometries shipped\n\n| `box` | B |\n",
        "## Obstacles shipped\n\n| `plane` | P |\n| `sphere` | S |\n\n"
        "## Geometries shipped\n\n| `box` | B |\n| `half ball` | H |\n",
        "value"),
    6: ("doc/validation.md",
        "| `patch_test_two_bodies_2d_friction` | 1 | 1e-10 (measured 2e-15) |\n\n"
        "The contact patch test holds to 1e-10 with and without friction.\n",
        "| `patch_test_two_bodies_2d_friction` | 1 | 1e-8 (measured 2e-15) |\n\n"
        "The contact patch test holds to 1e-10 without friction and 1e-8 with.\n",
        "1e-10"),
    7: ("doc/robustness.md",
        "`tests/full_disk.sh` fills a 400 kB tmpfs.\n",
        "`tests/full_disk.sh` fills a 600 kB tmpfs.\n",
        "tmpfs"),
}


def self_test():
    doc_tables = import_doc_tables(os.path.join(os.path.dirname(HERE), "bench"))
    failures = []
    for number, (page, bad, good, word) in SELF_TEST_CASES.items():
        for text, expect in ((bad, True), (good, False)):
            with tempfile.TemporaryDirectory() as root:
                for name, content in list(SELF_TEST_FILES.items()) + [(page, text)]:
                    path = os.path.join(root, name)
                    os.makedirs(os.path.dirname(path), exist_ok=True)
                    with open(path, "w") as out:
                        out.write(content)
                # Check 4 needs the page that names the CSVs on every run.
                if page != BENCHMARKS_PAGE:
                    with open(os.path.join(root, BENCHMARKS_PAGE), "w") as out:
                        out.write(SELF_TEST_CASES[4][2])
                found = check(root, SELF_TEST_SELECTIONS, doc_tables, {number})
                relevant = [p for p in found if p[0] == page and word in p[2]]
                if expect and not relevant:
                    failures.append(f"check {number} found nothing in the made-up "
                                    f"{page}: {found}")
                elif not expect and found:
                    failures.append(f"check {number} found problems in the corrected "
                                    f"{page}: {found}")
                elif expect:
                    print(f"check {number} finds: {relevant[0][0]}:{relevant[0][1]}: "
                          f"{relevant[0][2]}")
    expected_counts = {1: 3, 2: 3, 5: 3, 6: 2}
    for number, count in expected_counts.items():
        page, bad, _, _ = SELF_TEST_CASES[number]
        with tempfile.TemporaryDirectory() as root:
            for name, content in list(SELF_TEST_FILES.items()) + [(page, bad)]:
                path = os.path.join(root, name)
                os.makedirs(os.path.dirname(path), exist_ok=True)
                with open(path, "w") as out:
                    out.write(content)
            found = [p for p in check(root, SELF_TEST_SELECTIONS, doc_tables, {number})
                     if p[0] == page]
            if len(found) != count:
                failures.append(f"check {number}: {len(found)} problems in the made-up "
                                f"{page}, expected {count}: {found}")
    for failure in failures:
        print("*** " + failure)
    print("self-test: " + ("failed" if failures else
                           f"each of the {len(SELF_TEST_CASES)} checks finds its problem"))
    return 1 if failures else 0


def main():
    if len(sys.argv) == 2 and sys.argv[1] == "--self-test":
        return self_test()
    if len(sys.argv) != 3 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(sys.argv) == 2 and sys.argv[1] in ("-h", "--help") else 2
    root, program = os.path.abspath(sys.argv[1]), sys.argv[2]
    if os.sep in program:
        program = os.path.abspath(program)
    try:
        selections = declared_selections(program)
    except (OSError, RuntimeError, ValueError, subprocess.SubprocessError) as error:
        print(f"check_doc_numbers.py: {error}")
        return 2
    doc_tables = import_doc_tables(os.path.join(root, "bench"))
    problems = sorted(set(check(root, selections, doc_tables)))
    for page, line, what in problems:
        print(f"{page}:{line}: {what}")
    print(f"{len(problems)} problem(s) in {len(pages(root))} pages")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
