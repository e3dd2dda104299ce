#!/usr/bin/env python3
"""Checks facts of the documentation that drift as the code changes:
README.md, bench/README.md and every Markdown page under doc/.

usage: check_doc_facts.py <source dir> <contact program> [--runs DIR ...]
       check_doc_facts.py --self-test

1. README.md shows the two commands of bench/first_hour.py (COMMANDS) in
   its code blocks, and .ci/run runs the second;
2. a default quoted in a parameter block (`set X = a  # b (default), c`)
   or in prose (`` `X = v`, the default `` or `` `X = v` by default ``)
   is the default that `contact --print-parameters --json` declares;
3. the description of every Selection entry names each value it allows
   but its default (a value nobody describes is a value nobody finds);
4. a command of a code block that runs scripts/plot_contact_profile.py,
   scripts/render_contact.py or scripts/plot_history.py on a shipped
   scene's output folder (output-<x>) works after a plain run of that
   scene: the scene writes what the script reads (CSV tables, VTU, the
   convergence history);
5. numbers quoted beside the fuzz test's options (`--count`,
   `--mesh-count`, `--checkpoint-count`, `--timeout` "... N in the suite")
   are the ones tests/CMakeLists.txt passes;
6. no page quotes a build time by hand ("builds in about 90 s", "took
   118 s"): build times come from bench/first_hour.py's CSV, in a quote
   marker (<!-- quote: ... -->);
7. with --runs: every field the VTU files of those run folders hold is
   in doc/user-guide.md's table of fields, every field of that table is
   in one of them, and every file of those folders (digits as NNNNN) is
   named in its table of output files.

Prints one line per problem, 'page:line: what', then a summary; exit code 1
if there is a problem, 0 if not, 2 if the program could not be run.
--self-test runs the checks on made-up pages and asserts that each finds
its problem.
"""
import argparse
import glob
import os
import re
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from doc_sources import Parameters, pages  # noqa: E402

GUIDE = os.path.join("doc", "user-guide.md")
SCRIPT_NEEDS = {"plot_contact_profile.py": ("Postprocess/Visualization/Write csv tables", "true"),
                "render_contact.py": ("Postprocess/Visualization/Write vtu", "true"),
                "plot_history.py": ("Postprocess/Convergence history/Write convergence history",
                                    "true")}
FUZZ_OPTIONS = ("--count", "--mesh-count", "--checkpoint-count", "--timeout")


def read_lines(root, page):
    with open(os.path.join(root, page), errors="replace") as f:
        return f.read().split("\n")


def code_blocks(lines):
    """(first line number, [lines]) of each fenced block."""
    blocks, inside, start, body = [], False, 0, []
    for number, line in enumerate(lines, 1):
        if line.strip().startswith("```"):
            if inside:
                blocks.append((start, body))
            inside, start, body = not inside, number + 1, []
        elif inside:
            body.append(line)
    return blocks


def first_hour_commands(root):
    sys.path.insert(0, os.path.join(root, "bench"))
    import first_hour  # noqa: E402
    return first_hour.COMMANDS


def check_commands(root, problems):
    commands = first_hour_commands(root)
    shown = [line.strip() for _, body in code_blocks(read_lines(root, "README.md"))
             for line in body]
    for command in commands:
        if command not in shown:
            problems.append(f"README.md:1: does not show the command '{command}' "
                            "of bench/first_hour.py")
    ci = os.path.join(root, ".ci", "run")
    if os.path.isfile(ci) and commands[1] not in open(ci).read():
        problems.append(f".ci/run:1: does not run '{commands[1]}'")


def block_settings(body):
    """(offset, full path, value, comment) of each set line of a block."""
    found, sections = [], []
    for offset, line in enumerate(body):
        text, _, comment = line.partition("#")
        text = text.strip()
        if text.startswith("subsection "):
            sections.append(text[len("subsection "):].strip())
        elif text == "end" and sections:
            sections.pop()
        elif text.startswith("set ") and "=" in text:
            name, value = text[4:].split("=", 1)
            found.append((offset, "/".join(sections + [name.strip()]), value.strip(),
                          comment))
    return found


def resolve(parameters, path):
    """The declared entry a (possibly partial) path names, or None."""
    if path in parameters.entries:
        return path
    matches = [p for p in parameters.entries if p.endswith("/" + path)]
    return matches[0] if len(matches) == 1 else None


def check_defaults(root, page, lines, parameters, problems):
    for start, body in code_blocks(lines):
        for offset, path, value, comment in block_settings(body):
            m = re.search(r"([\w .'-]+?) \(default\)", comment)
            entry = resolve(parameters, path)
            if m and entry:
                quoted = m.group(1).split(",")[-1].strip()
                quoted = re.sub(r"^(or|and) ", "", quoted)
                default = parameters.entries[entry]["default_value"]
                if quoted != default:
                    problems.append(f"{page}:{start + offset}: '{quoted}' is quoted as the "
                                    f"default of {entry}, which is '{default}'")
    prose = "\n".join(lines)
    for m in re.finditer(r"`([A-Z][^`=]*?) = ([^`]+)`(,? the default|,? by default| by default)",
                         prose):
        entry = resolve(parameters, " ".join(m.group(1).split()))
        value = " ".join(m.group(2).split())
        if entry and parameters.entries[entry]["default_value"] != value:
            line = prose.count("\n", 0, m.start()) + 1
            problems.append(f"{page}:{line}: '{value}' is quoted as the default "
                            f"of {entry}, which is "
                            f"'{parameters.entries[entry]['default_value']}'")


def check_selections(parameters, problems):
    for path, entry in sorted(parameters.entries.items()):
        m = re.match(r"\[Selection (.*?) ?\]$", entry["pattern_description"])
        if not m:
            continue
        text = entry.get("documentation", "")
        for value in m.group(1).split("|"):
            if value != entry["default_value"] and value not in text:
                problems.append(f"{path}: its description does not name the value '{value}'")


def scene_outputs(root, program):
    """{output folder name: scene file} of the shipped scenes."""
    found = {}
    for scene in glob.glob(os.path.join(os.path.abspath(root), "parameters", "*.prm")):
        for line in open(scene):
            m = re.match(r"\s*set Output directory\s*=\s*(\S+)", line)
            if m:
                found[m.group(1)] = scene
    return found


def scene_settings(program, scene):
    import json
    import subprocess
    with tempfile.TemporaryDirectory() as folder:
        done = subprocess.run([program, "--print-parameters", "--json", scene],
                              capture_output=True, text=True, cwd=folder, timeout=120)
    settings = {}

    def walk(node, prefix):
        for key, value in node.items():
            if isinstance(value, dict) and "value" in value and "pattern_description" in value:
                settings["/".join(prefix + [key])] = value["value"]
            elif isinstance(value, dict):
                walk(value, prefix + [key])
    walk(json.loads(done.stdout), [])
    return settings


def check_script_commands(root, page, lines, program, outputs, problems):
    for start, body in code_blocks(lines):
        for offset, line in enumerate(body):
            for script, (entry, needed) in SCRIPT_NEEDS.items():
                if script not in line:
                    continue
                for folder in re.findall(r"\b(output-[\w-]+)", line):
                    if folder not in outputs:
                        continue
                    value = scene_settings(program, outputs[folder]).get(entry)
                    if value != needed:
                        problems.append(
                            f"{page}:{start + offset}: '{script} {folder}' needs <{entry}> = "
                            f"{needed}, which {os.path.relpath(outputs[folder], root)} does not set")


def fuzz_arguments(root):
    text = open(os.path.join(root, "tests", "CMakeLists.txt")).read()
    call = re.search(r"add_test\(NAME fuzz\s.*?\)", text, re.S).group(0)
    return {option: value for option, value in re.findall(r"(--[\w-]+) (\d+)", call)}


def check_fuzz_numbers(root, page, lines, problems):
    arguments = fuzz_arguments(root)
    for number, line in enumerate(lines, 1):
        for option in FUZZ_OPTIONS:
            for m in re.finditer(r"`" + re.escape(option) + r"`[^.;]{0,40}?(\d+)(?: s)? in the suite",
                                 line):
                if arguments.get(option) != m.group(1):
                    problems.append(f"{page}:{number}: {option} {m.group(1)} in the suite, "
                                    f"tests/CMakeLists.txt passes {arguments.get(option)}")


BUILD_TIME = re.compile(r"(build|compil|sanitiz)[^.]{0,80}?\b\d+ s\b|\b\d+ s\b[^.]{0,40}?(to build|build)",
                        re.I)


def check_build_times(page, lines, problems):
    text = re.sub(r"<!-- quote: .*?<!-- end quote -->", "", "\n".join(lines), flags=re.S)
    inside = False
    for number, line in enumerate(text.split("\n"), 1):
        if line.strip().startswith("```"):
            inside = not inside
        elif not inside and BUILD_TIME.search(line):
            problems.append(f"{page}:{number}: quotes a build time by hand "
                            "(quote bench/first_hour.py's CSV instead)")


def guide_table(root, heading_words):
    """The backticked names of the first column of the guide's table whose
    header row starts with @p heading_words."""
    names, inside = [], False
    for line in read_lines(root, GUIDE):
        if line.startswith("| " + heading_words):
            inside = True
            continue
        if inside and not line.startswith("|"):
            break
        if inside:
            names += re.findall(r"`([^`]+)`", line.split("|")[1])
    return names


def check_run_folders(root, folders, problems):
    fields = set(guide_table(root, "field |"))
    files = guide_table(root, "file |")
    patterns = [re.compile("^" + re.sub(r"N+", r"\\d+", re.escape(f)) + "$") for f in files]
    seen = set()
    for folder in folders:
        for vtu in glob.glob(os.path.join(folder, "solution", "*.vtu")):
            for name in re.findall(r'Name="([^"]+)"', open(vtu, errors="replace").read(200000)):
                if name in ("offsets", "types", "connectivity", "TIME", "CYCLE"):
                    continue
                seen.add(name)
                if name not in fields:
                    problems.append(f"{GUIDE}:1: the field '{name}' of {folder} is not in its "
                                    "table of fields")
        for path in glob.glob(os.path.join(folder, "**"), recursive=True):
            relative = os.path.relpath(path, folder)
            if os.path.isdir(path) or relative.startswith("checkpoint") or \
                    relative.startswith(".") or relative.startswith("figures"):
                continue
            if not any(p.match(relative) for p in patterns):
                problems.append(f"{GUIDE}:1: the file '{relative}' a run writes is not in "
                                "its table of output files")
    for name in sorted(fields - seen):
        problems.append(f"{GUIDE}:1: the field '{name}' of its table is in no VTU of "
                        f"{', '.join(folders)}")


def run_checks(root, program, folders):
    problems = []
    parameters = Parameters(program) if program else None
    check_commands(root, problems)
    outputs = scene_outputs(root, program) if program else {}
    for page in pages(root):
        lines = read_lines(root, page)
        if parameters:
            check_defaults(root, page, lines, parameters, problems)
            check_script_commands(root, page, lines, program, outputs, problems)
        check_fuzz_numbers(root, page, lines, problems)
        check_build_times(page, lines, problems)
    if parameters:
        check_selections(parameters, problems)
    if folders:
        check_run_folders(root, folders, problems)
    return list(dict.fromkeys(problems))


def self_test():
    """Each check on a made-up page finds its problem."""
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "doc"))
        os.makedirs(os.path.join(root, "bench"))
        os.makedirs(os.path.join(root, "tests"))
        with open(os.path.join(root, "bench", "first_hour.py"), "w") as f:
            f.write('COMMANDS = ["a && b", "c && d"]\n')
        with open(os.path.join(root, "README.md"), "w") as f:
            f.write("```sh\na && b\n```\n")
        with open(os.path.join(root, "tests", "CMakeLists.txt"), "w") as f:
            f.write("add_test(NAME fuzz COMMAND x --count 8 --timeout 10)\n")
        with open(os.path.join(root, "doc", "robustness.md"), "w") as f:
            f.write("Runs `--count`, 24 in the suite. The sanitized program builds in about 90 s.\n")
        found = run_checks(root, None, [])
        expected = ["does not show the command 'c && d'", "--count 24 in the suite",
                    "quotes a build time"]
        missing = [e for e in expected if not any(e in p for p in found)]
        if missing:
            sys.exit("self-test: not found: " + "; ".join(missing))
    print("self-test: every check finds its problem")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("source", nargs="?")
    parser.add_argument("program", nargs="?")
    parser.add_argument("--runs", nargs="*", default=[])
    parser.add_argument("--self-test", action="store_true")
    args = parser.parse_args()
    if args.self_test:
        return self_test()
    if not args.source or not args.program:
        parser.error("give the source folder and the program")
    try:
        problems = run_checks(args.source, args.program, args.runs)
    except RuntimeError as error:
        print(error)
        sys.exit(2)
    for problem in problems:
        print(problem)
    print(f"{len(problems)} problem(s)")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
