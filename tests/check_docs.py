#!/usr/bin/env python3
"""Checks that what the documentation quotes exists: README.md, bench/README.md
and every Markdown page under doc/.

usage: check_docs.py <source dir> <contact program> [<build dir>]

- parameter paths (`Contact solver/Method`, <Material/Formulation>, partial
  ones like `Half ball/Radius`, `set Name = value`, `subsection X / set Y`,
  and the subsection/set/end lines of parameter blocks) must name an entry or
  subsection that `contact --print-parameters --json` declares (in 2D or 3D),
  and a quoted value of a Selection or Bool entry must be one it allows;
- files and folders (backticked, in code blocks, in prose, and Markdown
  links; globs must match something) must exist, relative to the source
  folder, to the page's folder, to source/, include/frictional_contact/ or
  tests/ (links: to the page's folder only); outputs of a run (output-*,
  out-*, build/, absolute paths, NNNNN, <...>) are not checked;
- test names (`restart_adaptive`, `errors/no_convergence_aspect_50`,
  `hertz_2d_adaptive.analytic`, `units_*`) must be tests that
  `ctest --test-dir <build dir> -N` lists, or name files under tests/ (a build
  folder configured before a test was added does not list it yet);
- options quoted with a script (`bench/run_series.py --quick`,
  `scripts/setup.sh --tests`, `contact --fclib`) must appear in that script's
  text (for the program: in its --help); an option quoted alone is looked up
  in the scripts named in its paragraph, else in the code block just before
  it, else in the section's scripts and the program (not after "Slurm's",
  nor in a paragraph that quotes another program such as `perf record`);
- also: link anchors and quoted section names (doc/validation.md, "Hertz")
  must be headings or bold run-in headings; FRICTIONAL_CONTACT_* names and
  -D<variable> options must occur in the code or the CMake files; a quoted
  name of several words (`Contact area`, `Axis direction`) must be a
  parameter, a value of one, or a text of the code, tests or scripts.

Prints one line per problem, 'page:line: what', then a summary; exit code 1
if there is a problem, 0 if not, 2 if the program or ctest could not be run.
CHECK_DOCS_VERBOSE=1 also lists everything checked.
"""
import difflib
import fnmatch
import glob
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile

# Extensions of files (a token 'a.b' with one of these is a file, not a test).
FILE_EXTENSIONS = {
    "prm", "output", "cc", "h", "c", "sh", "py", "md", "csv", "png", "txt",
    "pvd", "pvtu", "vtu", "hdf5", "msh", "geo", "json", "cmake", "pvsm",
    "data", "inp", "part", "new", "lock", "so", "log", "pdf", "svg", "xml"}
# Bare file names (no folder) with these extensions must exist somewhere in
# the tree: they name code or pages, never the outputs of a run.
BARE_MUST_EXIST = {"py", "sh", "md", "cc", "h", "c", "cmake"}
# Commands whose options are not ours: after one of them, options belong to it.
FOREIGN_COMMANDS = {
    "python", "python3", "pvbatch", "pvpython", "paraview", "mpirun", "mpiexec",
    "srun", "sbatch", "sh", "bash", "env", "sudo", "apt-get", "apt", "ctest",
    "cmake", "make", "ninja", "gmsh", "heaptrack", "perf", "gdb", "valgrind",
    "git", "time", "timeout", "xvfb-run", "ls", "cat", "grep", "sed", "kill",
    "pip", "pip3"}
# Names that stand for any subsection or entry (`subsection Name`,
# `set Entry = value`).
PLACEHOLDER_NAMES = {"Name", "Entry", "Subsection", "Entry name"}
PLACEHOLDER_VALUES = {"...", "…", "n", "N", "x", "value", "<value>"}


class Parameters:
    """The declared parameters: full paths of entries and subsections."""

    def __init__(self, program):
        self.entries = {}       # full path -> entry (dict)
        self.subsections = set()
        environment = dict(os.environ, OMP_NUM_THREADS="1",
                           OMPI_ALLOW_RUN_AS_ROOT="1",
                           OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        with tempfile.TemporaryDirectory() as folder:
            scene = os.path.join(folder, "three_d.prm")
            with open(scene, "w") as out:
                out.write("set Dimension = 3\n")
            for extra in ([], [scene]):
                done = subprocess.run(
                    [program, "--print-parameters", "--json"] + extra,
                    capture_output=True, text=True, cwd=folder,
                    env=environment, timeout=300)
                if done.returncode != 0:
                    raise RuntimeError(
                        f"'{program} --print-parameters --json {' '.join(extra)}'"
                        f" exited with {done.returncode}: {done.stderr.strip()}")
                self._walk(json.loads(done.stdout), ())
            done = subprocess.run([program, "--help"], capture_output=True,
                                  text=True, cwd=folder, env=environment,
                                  timeout=60)
            self.help_text = done.stdout + done.stderr
        self.paths = [tuple(p.split("/")) for p in self.entries] + \
            [tuple(p.split("/")) for p in self.subsections]
        self.names = {p[-1] for p in self.paths}
        self.subsection_names = {p.split("/")[-1] for p in self.subsections}
        self.top_level = {p for p in self.subsections if "/" not in p}
        self.selection_values = set()
        for entry in self.entries.values():
            m = re.match(r"\[(?:Multiple)?Selection (.*?) ?\]$",
                         entry["pattern_description"])
            if m:
                self.selection_values.update(m.group(1).split("|"))

    def _walk(self, node, prefix):
        for key, value in node.items():
            path = prefix + (key,)
            if isinstance(value, dict) and isinstance(value.get("value"), str) \
                    and "pattern_description" in value:
                self.entries["/".join(path)] = value
            elif isinstance(value, dict):
                self.subsections.add("/".join(path))
                self._walk(value, path)

    def matches(self, components):
        """Declared full paths whose last components are these (a component
        '<...>' stands for any name)."""
        n = len(components)
        found = []
        for path in self.paths:
            if len(path) < n:
                continue
            tail = path[len(path) - n:]
            if all(c.startswith("<") or c in PLACEHOLDER_NAMES or c == t
                   for c, t in zip(components, tail)):
                found.append("/".join(path))
        return found

    def value_problem(self, full_paths, value):
        """None if the value suits one of these entries (or cannot be judged),
        else the allowed values."""
        value = value.strip().strip("'\"`").strip()
        if not value or value in PLACEHOLDER_VALUES or "<" in value \
                or "..." in value or re.fullmatch(r"[A-Za-z]", value):
            return None
        allowed_any = []
        for path in full_paths:
            entry = self.entries.get(path)
            if entry is None:
                return None            # a subsection: nothing to judge
            description = entry["pattern_description"]
            match = re.match(r"\[Selection (.*?) ?\]$", description)
            if match:
                allowed = match.group(1).split("|")
            elif description.startswith("[Bool"):
                allowed = ["true", "false", "yes", "no"]
            else:
                return None
            candidates = {value}
            for separator in (":", ";", " (", ",", " #", "  "):
                candidates.add(value.split(separator)[0].strip())
            alternatives = value.split("|")
            if any(c in allowed for c in candidates) or \
                    all(a.strip() in allowed for a in alternatives):
                return None
            allowed_any += allowed
        return "|".join(dict.fromkeys(allowed_any)) if allowed_any else None


class Checker:
    def __init__(self, root, parameters, tests):
        self.root = os.path.abspath(root)
        self.parameters = parameters
        self.tests = tests                     # None: no build folder
        self.test_bases = set()
        self.test_suffixes = set()
        self.test_groups = set()
        for name in tests or []:
            if "/" in name:
                self.test_groups.add(name.split("/")[0])
            base, _, rest = name.partition(".")
            self.test_bases.add(base.split("/")[-1])
            for suffix in rest.split("."):
                if suffix and not suffix.startswith("mpirun=") \
                        and suffix not in FILE_EXTENSIONS:
                    self.test_suffixes.add(suffix)
        self.problems = []
        self.counts = {"parameter": 0, "file": 0, "test": 0, "option": 0,
                       "anchor": 0, "name": 0}
        self.files = []                 # every file of the tree, relative
        for folder, subfolders, names in os.walk(self.root):
            relative = os.path.relpath(folder, self.root)
            subfolders[:] = [s for s in subfolders if not s.startswith(".")
                             and not (relative == "." and (
                                 s == "build" or s.startswith("output")
                                 or s.startswith("out-")))]
            for name in names:
                self.files.append(os.path.normpath(os.path.join(relative, name)))
        self.basenames = {}
        for path in self.files:
            self.basenames.setdefault(os.path.basename(path), []).append(path)
        self.top_folders = {p.split(os.sep)[0] for p in self.files if os.sep in p}
        self.roots = ["", "source", os.path.join("include", "frictional_contact"),
                      "tests"]
        self.code_text = None
        self.words_in_code = {}
        self.script_texts = {}
        self.headings = {}

    # -- reporting ---------------------------------------------------------
    def checked(self, kind, page, line, token):
        self.counts[kind] += 1
        if os.environ.get("CHECK_DOCS_VERBOSE"):
            print(f"  checked {kind} {page}:{line}: {token}")

    def problem(self, page, line, what, token, why):
        self.problems.append((page, line, f"{what} '{token}' does not exist ({why})"))

    # -- files ---------------------------------------------------------------
    def exists(self, relative_path, base=""):
        """True if the path (glob allowed) relative to base exists in the tree."""
        path = os.path.normpath(os.path.join(self.root, base, relative_path))
        if not (path + os.sep).startswith(self.root + os.sep) and path != self.root:
            return None                         # outside the tree: not judged
        if any(c in relative_path for c in "*?["):
            return bool(glob.glob(path)) or bool(glob.glob(path.rstrip(os.sep)))
        return os.path.exists(path)

    def find(self, token, page_dir, extra_dirs=()):
        """The first folder (relative) in which the token exists, or None;
        'outside' if it lies outside the tree."""
        for base in [page_dir] + self.roots + list(extra_dirs):
            found = self.exists(token, base)
            if found is None:
                return "outside"
            if found:
                return base
        return None

    @staticmethod
    def is_output(token):
        stripped = token.lstrip("./")
        return (token.startswith("/") or token.startswith("~")
                or token.startswith("$") or "NNNNN" in token or "<" in token
                or "..." in token or "…" in token or "{" in token
                or re.match(r"(output|out)[-_/]", stripped) is not None
                or stripped == "output" or stripped.startswith("build/")
                or stripped == "build")

    def check_path(self, page, line, token, page_dir, strict):
        """A token with a '/' (a file, folder or glob); strict: it was quoted
        (code span or link), so an unknown first folder is also a problem."""
        token = re.sub(r"[.,;:)]+$", "", token.strip("'\""))
        if not token or "://" in token or self.is_output(token) or \
                not re.search(r"[A-Za-z0-9]", token):
            return
        if not re.fullmatch(r"[\w.*?\[\]+=,-]+(/[\w.*?\[\]+=,-]*)+", token):
            return
        first = token.split("/")[0]
        if first in ("", ".", ".."):
            if self.exists(token, page_dir) is None:
                return
        found = self.find(token, page_dir)
        if found == "outside":
            return
        if found is not None:
            self.checked("file", page, line, token)
            return
        # Not a file: a test name?
        if self.check_test_like(page, line, token, report=False):
            return
        first_exists = any(self.exists(first, base) for base in
                           [page_dir] + self.roots)
        extension = token.rsplit(".", 1)[-1] if "." in token.split("/")[-1] else ""
        if self.tests is None and extension not in FILE_EXTENSIONS:
            return                  # may be a test name: not judged without ctest
        if first in self.test_groups and (not first_exists or
                                          extension not in FILE_EXTENSIONS):
            self.checked("test", page, line, token)
            self.problem(page, line, "test", token,
                         "not listed by 'ctest -N', and no such file or folder")
        elif first_exists or (strict and extension in FILE_EXTENSIONS):
            self.checked("file", page, line, token)
            self.problem(page, line, "file", token,
                         "no such file or folder, relative to the source "
                         "folder, the page, source/, include/frictional_contact/ "
                         "or tests/")

    def check_link(self, page, line, target, page_dir):
        target = target.strip("<>")
        if re.match(r"[a-z]+:", target) or target.startswith("//"):
            return
        path, _, anchor = target.partition("#")
        if path:
            self.checked("file", page, line, target)
            found = self.exists(path, page_dir)
            if found is False:
                self.problem(page, line, "link target", target,
                             f"no such file relative to {page_dir or '.'}/")
                return
            linked = os.path.normpath(os.path.join(page_dir, path))
        else:
            linked = page
        if anchor and linked.endswith(".md"):
            self.checked("anchor", page, line, target)
            slugs = {slug(h) for h in self.page_headings(linked)[0]}
            if anchor not in slugs:
                self.problem(page, line, "anchor", target,
                             f"no heading of {linked} has it")

    def check_bare(self, page, line, token, page_dir, siblings):
        """A file name without a folder, e.g. `run_series.py`, `hertz_3d.prm`."""
        token = re.sub(r"[.,;:)]+$", "", token.strip("'\""))
        match = re.fullmatch(r"[\w*?-][\w.*?-]*\.([A-Za-z0-9]+)", token)
        if not match or self.is_output(token):
            return
        extension = match.group(1)
        if extension not in FILE_EXTENSIONS:
            return
        same_extension = [os.path.dirname(s) for s in siblings
                          if s.endswith("." + extension)]
        if glob.glob(os.path.join(self.root, page_dir, "*." + extension)):
            same_extension.append(page_dir)     # a page about the files next to it
        if self.find(token, page_dir, same_extension) is not None:
            self.checked("file", page, line, token)
            return
        pattern_matches = [p for p in self.files
                           if fnmatch.fnmatch(os.path.basename(p), token)]
        if extension in BARE_MUST_EXIST:
            self.checked("file", page, line, token)
            if not pattern_matches:
                self.problem(page, line, "file", token,
                             "no file of that name in the tree")
        elif same_extension:
            self.checked("file", page, line, token)
            if not pattern_matches:
                self.problem(page, line, "file", token, "not in "
                             + ", ".join(sorted(set(d + "/" for d in same_extension)))
                             + " nor anywhere in the tree")

    # -- tests ---------------------------------------------------------------
    def test_exists(self, name):
        if self.tests is not None:
            if any(c in name for c in "*?[") and fnmatch.filter(self.tests, name):
                return True
            if name in self.tests:
                return True
        # A test the build folder does not list yet (configured before the
        # test was added): the file CMake makes it from, under tests/
        # (<name>.prm, .cc, .sh, <name>[.mpirun=N].output; also for the
        # <name>.run and <name>.other_blas made from them).
        stem = re.sub(r"\.(run|other_blas)$", "", name)
        for pattern in (stem + ".prm", stem + ".cc", stem + ".sh",
                        stem + ".output"):
            if glob.glob(os.path.join(self.root, "tests", pattern)):
                return True
        return False

    def check_test_like(self, page, line, token, report=True,
                        in_test_context=False):
        """True if the token is a test (or several: 'a_2d/3d.x'); reports it
        when it looks like a test name but is none."""
        if self.tests is None and not in_test_context:
            return False
        token = re.sub(r"[,;:)]+$", "", token)
        if not re.fullmatch(r"[\w*?=./-]+", token) or token.startswith(".") \
                or token.endswith("/") or not re.search(r"[A-Za-z]", token):
            return False
        if token.rsplit(".", 1)[-1] in FILE_EXTENSIONS and "." in token:
            # A file name, unless a test is called so (one_increment.pvd).
            if self.tests is not None and token in self.tests:
                self.checked("test", page, line, token)
                return True
            return False
        names = [token]
        if "/" in token:
            left, right = token.split("/", 1)
            head = right.split(".")[0]
            if left.split("/")[0] not in self.test_groups and head and \
                    len(left) > len(head):
                names = [left + right[len(head):], left[:-len(head)] + right]
        if all(self.test_exists(n) for n in names):
            self.checked("test", page, line, token)
            return True
        parts = token.split(".")
        base, suffixes = parts[0], parts[1:]
        looks_like_test = in_test_context
        if "/" in token and token.split("/")[0] in self.test_groups:
            looks_like_test = True
        if suffixes and suffixes[-1] not in FILE_EXTENSIONS:
            last = suffixes[-1]
            if last in self.test_suffixes or last.startswith("mpirun=") or \
                    any(fnmatch.fnmatch(b, base.split("/")[-1])
                        for b in self.test_bases):
                looks_like_test = True
        close = []
        if not looks_like_test and self.tests is not None and "_" in token \
                and not any(c in token for c in "*?[") and \
                not self.in_code(token):
            close = difflib.get_close_matches(token, self.tests, 1, 0.9)
            looks_like_test = bool(close)
        if looks_like_test and report and self.tests is not None:
            self.checked("test", page, line, token)
            self.problem(page, line, "test", token,
                         "not listed by 'ctest -N' and no such file under tests/"
                         + (f"; did you mean '{close[0]}'?" if close else ""))
            return True
        return False

    # -- parameters ------------------------------------------------------------
    def check_parameter(self, page, line, path_text, value=None, exact=False):
        components = [re.sub(r"\s+", " ", c).strip() for c in path_text.split("/")]
        if not all(components):
            return
        self.checked("parameter", page, line, path_text)
        if exact:
            full = "/".join(components)
            found = [full] if (full in self.parameters.entries or
                               full in self.parameters.subsections) else []
        else:
            found = self.parameters.matches(components)
        if not found:
            self.problem(page, line, "parameter", "/".join(components),
                         "not declared by 'contact --print-parameters'")
            return
        if value is not None:
            allowed = self.parameters.value_problem(found, value)
            if allowed:
                self.problems.append((page, line, f"parameter value "
                                      f"'{'/'.join(components)} = {value.strip()}' "
                                      f"does not exist (allowed: {allowed})"))

    def parameter_span(self, page, line, text, context):
        """Checks a code span if it is a parameter reference; True if it was."""
        p = self.parameters
        # subsection A / subsection B / set C = v
        if re.match(r"subsection\s", text):
            pieces = [s.strip() for s in re.split(r"\s/\s", text)]
            path, value = [], None
            for piece in pieces:
                m = re.fullmatch(r"subsection\s+(.+)", piece)
                s = re.fullmatch(r"set\s+(.+?)\s*(?:=\s*(.*))?", piece)
                if m:
                    path.append(m.group(1).strip())
                elif s:
                    path.append(s.group(1).strip())
                    value = s.group(2)
                else:
                    return False
            self.check_parameter(page, line, "/".join(path), value)
            return True
        # set Name = value (in `subsection X` if the sentence says so)
        m = re.fullmatch(r"set\s+([A-Z][\w' /<>-]*?)\s*(?:=\s*(.*))?", text)
        if m:
            name, value = m.group(1), m.group(2)
            subsection = context.get("subsection")
            if subsection and "/" not in name:
                self.check_parameter(page, line, subsection + "/" + name, value)
            else:
                self.check_parameter(page, line, name, value)
            return True
        # Path/with/components [= value], or Name = value
        m = re.fullmatch(r"<?([^=<>]*?(?:<[^>]*>[^=<>]*?)*)>?(?:\s+=\s*(.*))?", text)
        if not m:
            return False
        path, value = m.group(1).strip(), m.group(2)
        if "/" in path:
            if " / " in path or "//" in path or "://" in path:
                return False
            components = path.split("/")
            if not all(re.fullmatch(r"<[^<>]+>|[A-Z][\w' -]*", c.strip())
                       for c in components):
                return False
            first = components[0].strip()
            if not (first in p.subsection_names or first in p.names
                    or any(" " in c.strip() or c.startswith("<")
                           for c in components)):
                return False
            self.check_parameter(page, line, path, value)
            return True
        if value is not None and \
                re.fullmatch(r"[A-Z][A-Za-z'-]*( [A-Za-z0-9'][A-Za-z0-9'-]*)*", path) \
                and re.search(r"[a-z]{3}", path):
            first_words = {n.split()[0] for n in p.names}
            if path in p.names or path.split()[0] in first_words or \
                    difflib.get_close_matches(path, p.names, 1, 0.8):
                self.check_parameter(page, line, path, value)
                return True
            return False
        if value is None and \
                re.fullmatch(r"[A-Z][A-Za-z'-]*( [A-Za-z][A-Za-z'-]*)+", path) \
                and re.search(r"[a-z]{2}", path):
            # A name of two or more words: a parameter, one of its values,
            # or a text of the program (a statistics column, a message).
            self.check_phrase(page, line, path)
            return True
        return False

    def check_phrase(self, page, line, phrase):
        p = self.parameters
        self.checked("name", page, line, phrase)
        if phrase in p.names or phrase in p.selection_values:
            return
        if re.search(re.escape(phrase), self.code()):
            return
        close = difflib.get_close_matches(phrase, p.names, 1, 0.75)
        self.problem(page, line, "name", phrase,
                     "neither a parameter nor one of its values, nor a text of "
                     "the program, the tests or the scripts"
                     + (f"; did you mean '{close[0]}'?" if close else ""))

    def angle_parameters(self, page, line, text):
        for m in re.finditer(r"<([A-Z][^<>\n]*/[^<>\n]*)>", text):
            inner = m.group(1)
            if all(re.fullmatch(r"[A-Z][\w' -]*", c) for c in inner.split("/")):
                self.check_parameter(page, line, inner)

    def prm_block(self, page, first_line, lines):
        stack = []
        exact = None
        for number, text in enumerate(lines, first_line):
            text = text.split("#")[0].strip()
            if not text:
                continue
            m = re.fullmatch(r"subsection\s+(.+)", text)
            if m:
                stack.append(m.group(1).strip())
                if exact is None:
                    exact = stack[0] in self.parameters.top_level
                self.check_parameter(page, number, "/".join(stack), exact=exact)
                continue
            if text == "end":
                if stack:
                    stack.pop()
                continue
            m = re.fullmatch(r"set\s+(.+?)\s*=\s*(.*)", text)
            if m:
                if exact is None:
                    exact = True        # a 'set' at the top level
                self.check_parameter(page, number, "/".join(stack + [m.group(1)]),
                                     m.group(2), exact=exact)

    # -- scripts and options -----------------------------------------------------
    def script_path(self, token, page_dir):
        token = token.strip("'\"")
        if not re.fullmatch(r"[\w./-]+\.(py|sh)", token) or self.is_output(token):
            return None
        base = self.find(token, page_dir) if "/" in token else None
        if base is None and "/" not in token:
            base = self.find(token, page_dir)
            if base is None:
                candidates = self.basenames.get(token, [])
                if len(candidates) == 1:
                    return candidates[0]
                return None
        if base in (None, "outside"):
            return None
        return os.path.normpath(os.path.join(base, token))

    def option_known(self, script, option):
        if script == "contact":
            text = self.parameters.help_text
        else:
            if script not in self.script_texts:
                with open(os.path.join(self.root, script), errors="replace") as f:
                    self.script_texts[script] = f.read()
            text = self.script_texts[script]
        return re.search(r"(?<![\w-])" + re.escape(option) + r"(?![\w-])", text) \
            is not None

    def check_option(self, page, line, option, scripts):
        scripts = [s for s in dict.fromkeys(scripts) if s]
        if not scripts:
            return
        self.checked("option", page, line, option)
        if not any(self.option_known(s, option) for s in scripts):
            self.problem(page, line, "option", option,
                         "not in " + " nor ".join(
                             "the program's --help" if s == "contact" else s
                             for s in scripts))

    def command_words(self, page, line, words, page_dir, strict, context,
                      siblings):
        """Words of a command line or a code span: scripts and their options,
        files, tests. Returns the scripts it named."""
        current = None
        named = []
        previous_was_option = False
        for index, word in enumerate(words):
            if word in ("&&", "||", ";", "|", "&") or word.startswith("#"):
                current = None
                if word.startswith("#"):
                    break
                continue
            definition = re.fullmatch(r"-D([A-Za-z_]\w*)(?::\w+)?=.*", word)
            if definition:
                # A CMake variable: ours must occur in the CMake files.
                variable = definition.group(1)
                self.checked("name", page, line, variable)
                if not variable.startswith("CMAKE_") and not re.search(
                        r"\b" + variable + r"\b", self.cmake_text()):
                    self.problem(page, line, "CMake variable", variable,
                                 "not in CMakeLists.txt, cmake/ or tests/*.cmake")
                continue
            option = re.fullmatch(r"(--?[A-Za-z][\w-]*)(=.*)?", word)
            if option:
                if current is not None and current != "foreign":
                    self.check_option(page, line, option.group(1), [current])
                elif current is None and context is not None and index == 0:
                    self.check_option(page, line, option.group(1),
                                      context.get("scripts", []))
                previous_was_option = option.group(2) is None
                continue
            value_of_option = previous_was_option
            previous_was_option = False
            if re.fullmatch(r"[A-Z_][A-Z0-9_]*=.*", word):
                continue                # VARIABLE=value
            script = self.script_path(word, page_dir)
            if script:
                current = script
                named.append(script)
                self.checked("file", page, line, word)
                continue
            name = word.strip("'\"")
            if name == "contact" or name.endswith("/contact"):
                current = "contact"
                named.append("contact")
                continue
            if os.path.basename(name) in FOREIGN_COMMANDS:
                current = "foreign"
                continue
            if "=" in word and "/" in word:
                continue                # LABEL=file, key=value
            if "/" in name:
                self.check_path(page, line, name, page_dir, strict)
                if strict and not self.is_output(name):
                    siblings.append(re.sub(r"[.,;:)]+$", "", name))
            elif strict:
                if not value_of_option and self.check_test_like(
                        page, line, name,
                        in_test_context=context is not None and
                        context.get("test_context", False)):
                    continue
                if not value_of_option:
                    self.check_bare(page, line, name, page_dir, siblings)
        return named

    # -- names -------------------------------------------------------------------
    def cmake_text(self):
        parts = []
        for path in self.files:
            if os.path.basename(path) == "CMakeLists.txt" or path.endswith(".cmake"):
                with open(os.path.join(self.root, path), errors="replace") as f:
                    parts.append(f.read())
        return "\n".join(parts)

    def in_code(self, word):
        """Whether the code (code()) has @p word as a word; memoised: pages
        quote the same names many times, and each search reads all of it."""
        if word not in self.words_in_code:
            # As re.search(r"\b" + re.escape(word) + r"\b") would say, by
            # substring search (a regular expression took seconds here).
            text = self.code()
            def is_word(c):
                return c.isalnum() or c == "_"
            def boundary(before, after):
                return is_word(before) != is_word(after)
            found = False
            i = text.find(word)
            while i >= 0 and not found:
                j = i + len(word)
                found = boundary(text[i - 1] if i > 0 else " ", word[0]) and \
                    boundary(word[-1], text[j] if j < len(text) else " ")
                i = text.find(word, i + 1)
            self.words_in_code[word] = found
        return self.words_in_code[word]

    def code(self):
        """The text of the code, the tests, the scripts and the CMake files."""
        if self.code_text is None:
            parts = []
            for path in self.files:
                if path.endswith((".cc", ".h", ".c", ".cmake", ".txt", ".sh",
                                  ".py", ".in", ".prm", ".output")) \
                        and not path.startswith("doc" + os.sep) \
                        and path != os.path.join("tests", "check_docs.py"):
                    with open(os.path.join(self.root, path),
                              errors="replace") as f:
                        parts.append(f.read())
            self.code_text = "\n".join(parts)
        return self.code_text

    def check_names(self, page, line, text):
        for m in re.finditer(r"\bFRICTIONAL_CONTACT_[A-Z0-9_]+", text):
            name = m.group(0)
            self.checked("name", page, line, name)
            if not re.search(r"\b" + name + r"\b", self.code()):
                self.problem(page, line, "name", name,
                             "not in the code, the tests or the CMake files")

    # -- pages -------------------------------------------------------------------
    def page_headings(self, page):
        if page not in self.headings:
            headings, bold = [], []
            try:
                with open(os.path.join(self.root, page), errors="replace") as f:
                    text = f.read()
            except OSError:
                text = ""
            fenced = False
            for raw in text.splitlines():
                if re.match(r"\s*(```|~~~)", raw):
                    fenced = not fenced
                    continue
                if fenced:
                    continue
                m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", raw)
                if m:
                    headings.append(m.group(1))
                bold += re.findall(r"\*\*([^*]+)\*\*", raw)
            self.headings[page] = (headings, bold)
        return self.headings[page]

    def check_section(self, page, line, target_page, section):
        self.checked("anchor", page, line, section)
        headings, bold = self.page_headings(target_page)
        wanted = normalise_title(section)
        for title in headings + bold:
            if normalise_title(title).startswith(wanted):
                return
        self.problem(page, line, "section", f'{section}',
                     f"no heading or bold run-in heading of {target_page} "
                     "starts with it")

    def check_page(self, page):
        with open(os.path.join(self.root, page), errors="replace") as f:
            lines = f.read().split("\n")
        page_dir = os.path.dirname(page)
        blocks = split_blocks(lines)
        previous_code_scripts = []
        section_scripts = []            # named since the last heading
        for kind, first, body, language in blocks:
            if kind == "text" and body[0].startswith("#"):
                section_scripts = []
            if kind == "fence":
                previous_code_scripts = self.code_block(page, first, body,
                                                        page_dir, language)
                section_scripts += previous_code_scripts
            elif kind == "indented":
                previous_code_scripts = self.code_block(page, first, body,
                                                        page_dir, "")
                section_scripts += previous_code_scripts
            else:
                section_scripts += self.paragraph(
                    page, first, body, page_dir, previous_code_scripts,
                    section_scripts)
                previous_code_scripts = []

    def code_block(self, page, first, body, page_dir, language):
        language = language.lower()
        if language in ("cpp", "c++", "c", "python", "py", "json", "cmake",
                        "diff", "text"):
            return []
        if any(re.match(r"\s*(subsection\s|set\s.*=)", l) for l in body):
            self.prm_block(page, first, body)
            return []
        scripts = []
        siblings = []
        index = 0
        while index < len(body):
            number = first + index
            text = body[index]
            while text.rstrip().endswith("\\") and index + 1 < len(body):
                index += 1
                text = text.rstrip()[:-1] + " " + body[index]
            index += 1
            self.angle_parameters(page, number, text)
            self.check_names(page, number, text)
            command = re.split(r"(?:^|\s)#", text)[0]
            try:
                words = shlex.split(command)
            except ValueError:
                words = command.split()
            if language in ("sh", "bash", "shell", "console"):
                scripts += self.command_words(page, number, words, page_dir,
                                              True, None, siblings)
            else:
                # Unlabelled or indented: messages, pseudo-code, art; only
                # paths in existing top-level folders, and script options.
                for word in words:
                    if "/" in word and not self.is_output(word):
                        self.check_path(page, number, word, page_dir, False)
                scripts += self.command_words(
                    page, number, [w for w in words if "/" not in w or
                                   self.script_path(w, page_dir)],
                    page_dir, False, None, [])
        return scripts

    def paragraph(self, page, first, body, page_dir, previous_code_scripts,
                  section_scripts):
        text = "\n".join(body)
        line_starts = [0]
        for l in body:
            line_starts.append(line_starts[-1] + len(l) + 1)

        def line_of(offset):
            n = 0
            while n + 1 < len(line_starts) and line_starts[n + 1] <= offset:
                n += 1
            return first + n

        spans = [(m.start(), m.end(), m.group(2))
                 for m in re.finditer(r"(?<!`)(`+)(?!`)(.+?)(?<!`)\1(?!`)", text,
                                      re.S)]
        masked = list(text)
        for start, end, _ in spans:
            masked[start:end] = " " * (end - start)
        masked = "".join(masked)
        links = [(m.start(), m.group(1)) for m in
                 re.finditer(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)", masked)]
        prose = masked
        for m in re.finditer(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)", masked):
            prose = prose[:m.start()] + " " * (m.end() - m.start()) + prose[m.end():]

        # Markdown links.
        for offset, target in links:
            self.check_link(page, line_of(offset), target, page_dir)
        # Parameter paths in angle brackets, FRICTIONAL_CONTACT_ names.
        for m in re.finditer(r"<([A-Z][^<>\n]*/[^<>\n]*)>", prose):
            self.angle_parameters(page, line_of(m.start()), m.group(0))
        for m in re.finditer(r"\bFRICTIONAL_CONTACT_[A-Z0-9_]+", text):
            self.check_names(page, line_of(m.start()), m.group(0))
        # Paths in prose: in the tree's top-level folders only.
        folders = "|".join(re.escape(f) for f in sorted(self.top_folders)
                           if f not in ("build",) and not f.startswith("output"))
        for m in re.finditer(r"(?<![\w/.<>-])((?:%s)/[\w./*-]*)" % folders, prose):
            self.check_path(page, line_of(m.start()), m.group(1), page_dir, False)
        # Section names: doc/x.md, "Section" and (README, "Section").
        for m in re.finditer(r"`?((?:[\w./-]+/)?[\w.-]+\.md|README)`?,?\s+\"([^\"\n]+)\"",
                             masked + " "):
            target = m.group(1)
            bases = (page_dir, "")
            if target == "README":
                target, bases = "README.md", ("",)
            target_page = None
            for base in bases:
                if os.path.isfile(os.path.join(self.root, base, target)):
                    target_page = os.path.normpath(os.path.join(base, target))
                    break
            if target_page:
                self.check_section(page, line_of(m.start()), target_page, m.group(2))
        for m in re.finditer(r"\(\"([A-Za-z0-9][\w ,'-]{0,60})\"\)", masked):
            self.check_section(page, line_of(m.start()), page, m.group(1))

        # Code spans.
        context = {"scripts": [], "subsection": None}
        siblings = []
        span_scripts = []
        for start, end, code in spans:
            normalised = re.sub(r"\s+", " ", code).strip()
            m = re.fullmatch(r"(?:\.\./)?([\w./-]+\.(?:py|sh))(\s.*)?", normalised)
            if m and self.script_path(m.group(1), page_dir):
                span_scripts.append(self.script_path(m.group(1), page_dir))
            if normalised == "contact" or normalised.startswith("contact ") or \
                    re.match(r"\S*/contact( |$)", normalised):
                span_scripts.append("contact")
        option_scripts = [s for s in span_scripts if s != "contact"] + \
            [s for s in previous_code_scripts if s != "contact"]
        if not option_scripts:
            option_scripts = span_scripts + previous_code_scripts
        # Else the scripts of the section, unless the paragraph quotes another
        # program (`perf record ... --call-graph`) or names none of ours.
        foreign = any(os.path.basename(code.split()[0]) in FOREIGN_COMMANDS
                      for _, _, code in spans if code.split())
        if not option_scripts and not foreign and \
                any(s != "contact" for s in section_scripts):
            option_scripts = section_scripts + ["contact"]

        for index, (start, end, code) in enumerate(spans):
            line = line_of(start)
            normalised = re.sub(r"\s+", " ", code).strip()
            if not normalised or "://" in normalised:
                continue
            # The sentence around the span: its `subsection X`, "test(s)".
            sentence_start = max(text.rfind(". ", 0, start), text.rfind("\n\n", 0, start))
            sentence_end = text.find(". ", end)
            sentence_end = len(text) if sentence_end < 0 else sentence_end
            subsection = None
            for s_start, s_end, s_code in spans:
                if s_start >= sentence_start and s_end <= sentence_end + 1:
                    m = re.fullmatch(r"subsection\s+([^/]+)", re.sub(r"\s+", " ", s_code).strip())
                    if m:
                        subsection = m.group(1).strip()
            context["subsection"] = subsection
            context["test_context"] = self.test_context(text, spans, index)
            # "Slurm's `--signal`": another program's option.
            context["scripts"] = [] if re.search(r"\w's\s*$", text[:start]) \
                else option_scripts
            if self.parameter_span(page, line, normalised, context):
                continue
            self.angle_parameters(page, line, normalised)
            try:
                words = shlex.split(normalised)
            except ValueError:
                words = normalised.split()
            if len(words) > 1 and not re.match(r"[\w./-]+$", words[0]) and \
                    not words[0].startswith("-"):
                # Not a command (a formula, a message): only its file names.
                words = [w for w in words if "/" in w or "." in w]
            self.command_words(page, line, words, page_dir, True, context, siblings)
        return span_scripts

    @staticmethod
    def test_context(text, spans, index):
        """True if the span follows the word test(s), maybe after other spans
        joined by commas and 'and'."""
        j = index
        while True:
            gap = text[spans[j - 1][1] if j > 0 else 0:spans[j][0]]
            if re.search(r"\b[Tt]ests?:?\s*\(?$", gap):
                return True
            if j > 0 and re.fullmatch(r"[\s,;/]*(?:and|or)?[\s,]*", gap):
                j -= 1
                continue
            return False


def normalise_title(title):
    title = re.sub(r"[`*_\"]", "", title).lower()
    return re.sub(r"\s+", " ", title).strip()


def slug(heading):
    """GitHub's anchor of a heading."""
    text = re.sub(r"[`*]", "", heading).strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def split_blocks(lines):
    """Blocks of a Markdown page: ('fence', first line, lines, language),
    ('indented', ...) and ('text', ...) for paragraphs, list items, table
    rows and headings. Line numbers start at 1."""
    blocks = []
    index = 0
    paragraph = []
    paragraph_start = 0
    in_list = False

    def flush():
        nonlocal paragraph
        if paragraph:
            blocks.append(("text", paragraph_start, paragraph, ""))
        paragraph = []

    previous_blank = True
    while index < len(lines):
        raw = lines[index]
        fence = re.match(r"\s*(```+|~~~+)\s*([\w+-]*)", raw)
        if fence:
            flush()
            marker = fence.group(1)
            body = []
            start = index + 2
            index += 1
            while index < len(lines) and not lines[index].strip().startswith(marker):
                body.append(lines[index])
                index += 1
            blocks.append(("fence", start, body, fence.group(2)))
            index += 1
            previous_blank = False
            continue
        if not raw.strip():
            flush()
            previous_blank = True
            index += 1
            continue
        if previous_blank and raw.startswith("    ") and not in_list:
            flush()
            body = []
            start = index + 1
            while index < len(lines) and (lines[index].startswith("    ") or
                                          not lines[index].strip()):
                if not lines[index].strip() and (
                        index + 1 >= len(lines) or
                        not lines[index + 1].startswith("    ")):
                    break
                body.append(lines[index][4:])
                index += 1
            blocks.append(("indented", start, body, ""))
            previous_blank = False
            continue
        item = re.match(r"\s*([-*+]|\d+\.)\s", raw)
        if previous_blank:
            in_list = bool(item) or (in_list and raw.startswith("  "))
        if item or raw.lstrip().startswith("|") or raw.startswith("#"):
            flush()
        if not paragraph:
            paragraph_start = index + 1
        paragraph.append(raw)
        if raw.startswith("#"):
            flush()
        previous_blank = False
        index += 1
    flush()
    return blocks


def list_tests(build):
    done = subprocess.run(["ctest", "--test-dir", build, "-N"],
                          capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        raise RuntimeError(f"'ctest --test-dir {build} -N' exited with "
                           f"{done.returncode}: {done.stderr.strip()}")
    tests = [m.group(1) for m in
             re.finditer(r"^\s*Test\s+#\d+:\s+(\S+)\s*$", done.stdout, re.M)]
    if not tests:
        raise RuntimeError(f"'ctest --test-dir {build} -N' lists no test")
    return tests


def pages(root):
    found = [p for p in ("README.md", os.path.join("bench", "README.md"))
             if os.path.isfile(os.path.join(root, p))]
    for folder, subfolders, names in os.walk(os.path.join(root, "doc")):
        subfolders.sort()
        for name in sorted(names):
            if name.endswith(".md"):
                found.append(os.path.relpath(os.path.join(folder, name), root))
    return found


def main():
    if len(sys.argv) in (1, 2) or sys.argv[1] in ("-h", "--help") \
            or len(sys.argv) > 4:
        print(__doc__)
        return 0 if len(sys.argv) == 2 and sys.argv[1] in ("-h", "--help") else 2
    root, program = sys.argv[1], sys.argv[2]
    if os.sep in program:
        program = os.path.abspath(program)
    try:
        parameters = Parameters(program)
        tests = list_tests(sys.argv[3]) if len(sys.argv) == 4 else None
    except (OSError, RuntimeError, ValueError, subprocess.SubprocessError) as error:
        print(f"check_docs.py: {error}")
        return 2
    checker = Checker(root, parameters, tests)
    checked = pages(root)
    for page in checked:
        checker.check_page(page)
    seen = set()
    for page, line, message in checker.problems:
        if (page, line, message) not in seen:
            seen.add((page, line, message))
            print(f"{page}:{line}: {message}")
    counts = checker.counts
    print(f"{len(seen)} problem(s) in {len(checked)} pages; checked "
          f"{counts['parameter']} parameter paths, {counts['file']} files, "
          f"{counts['test']} test names, {counts['option']} options, "
          f"{counts['anchor']} anchors and sections, {counts['name']} names"
          + ("" if tests is not None else
             " (no build folder: test names not checked)"))
    return 1 if seen else 0


if __name__ == "__main__":
    sys.exit(main())
