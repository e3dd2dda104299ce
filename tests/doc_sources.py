"""What check_docs.py reads: the parameters the program declares
(Parameters), the tests ctest lists (list_tests), the pages to check (pages)
and their blocks (split_blocks), and the source tree (Tree): its files, where
a quoted path exists in it, the text of its code and CMake files, and the
headings of its pages (with slug and normalise_title)."""
import glob
import json
import os
import re
import subprocess
import tempfile

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


# The checker's own files: the names and phrases they quote as examples and
# patterns are not texts of the code.
OWN_FILES = {os.path.join("tests", name)
             for name in ("check_docs.py", "doc_sources.py", "doc_checks.py")}


class Tree:
    """The source tree: its files, where a path exists in it, the text of its
    code and CMake files, the headings of its pages."""

    def __init__(self, root):
        self.root = os.path.abspath(root)
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
        self.headings = {}

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
                        and path not in OWN_FILES:
                    with open(os.path.join(self.root, path),
                              errors="replace") as f:
                        parts.append(f.read())
            self.code_text = "\n".join(parts)
        return self.code_text

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
