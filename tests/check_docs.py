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

The checks live in doc_checks.py, what they read (the declared parameters,
the tests, the pages, the source tree) in doc_sources.py; this script walks
the pages.

Prints one line per problem, 'page:line: what', then a summary; exit code 1
if there is a problem, 0 if not, 2 if the program or ctest could not be run.
CHECK_DOCS_VERBOSE=1 also lists everything checked.
"""
import os
import re
import shlex
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from doc_checks import (FOREIGN_COMMANDS, CommandChecks,  # noqa: E402
                        ParameterChecks, PathChecks, TestNameChecks)
from doc_sources import Parameters, list_tests, pages, split_blocks  # noqa: E402


class Checker(PathChecks, TestNameChecks, ParameterChecks, CommandChecks):
    """Walks a page block by block and hands what each quotes to the checks;
    an option quoted alone goes to the scripts its paragraph, the code block
    before it or its section names."""

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
        self.check_prose(page, text, masked, page_dir, line_of)

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

    def check_prose(self, page, text, masked, page_dir, line_of):
        """What a paragraph quotes outside its code spans (masked: the text
        with its code spans blanked out): links, parameter paths in angle
        brackets, FRICTIONAL_CONTACT_* names, paths and section names."""
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
