"""What check_docs.py checks of the things a page quotes, one class for
each kind of thing; its Checker, which walks the pages, joins them:
PathChecks (files, folders, links and their anchors, section names),
TestNameChecks (test names), ParameterChecks (parameter paths, values and
names of several words), CommandChecks (scripts and their options,
FRICTIONAL_CONTACT_* names, -D<variable> options). Checks, which they share,
keeps the problems found and counts what was checked."""
import difflib
import fnmatch
import glob
import os
import re

from doc_sources import Tree, normalise_title, slug

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


class Checks(Tree):
    """The source tree, the declared parameters and the tests that ctest
    lists; the problems found and the counts of what was checked."""

    def __init__(self, root, parameters, tests):
        super().__init__(root)
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
        self.script_texts = {}

    def checked(self, kind, page, line, token):
        self.counts[kind] += 1
        if os.environ.get("CHECK_DOCS_VERBOSE"):
            print(f"  checked {kind} {page}:{line}: {token}")

    def problem(self, page, line, what, token, why):
        self.problems.append((page, line, f"{what} '{token}' does not exist ({why})"))


class PathChecks(Checks):
    """Files, folders and globs, Markdown links and their anchors, and quoted
    section names."""

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


class TestNameChecks(Checks):
    """Test names: ctest lists them, or a file under tests/ makes them."""

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


class ParameterChecks(Checks):
    """Parameter paths and values (code spans, <Path/In/Angle/Brackets>,
    parameter blocks) and quoted names of several words."""

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


class CommandChecks(Checks):
    """Command lines and code spans: the scripts they name and those scripts'
    options, files and tests among their words, -D<variable> options and
    FRICTIONAL_CONTACT_* names."""

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

    def check_names(self, page, line, text):
        for m in re.finditer(r"\bFRICTIONAL_CONTACT_[A-Z0-9_]+", text):
            name = m.group(0)
            self.checked("name", page, line, name)
            if not re.search(r"\b" + name + r"\b", self.code()):
                self.problem(page, line, "name", name,
                             "not in the code, the tests or the CMake files")
