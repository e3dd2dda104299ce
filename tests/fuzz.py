#!/usr/bin/env python3
"""Feeds mutated parameter files to the program and checks that each one
either runs or stops with a clear error (exit code 1 or 2 and exactly one
line "Error: ..."), and that none crashes: no signal, no other exit code,
no sanitizer report, no stack trace. The mutations (deleted and duplicated
lines, swapped values, random bytes, huge and negative numbers, unknown
words) start from the shipped scenes. The seed changes every day (days
since 1970), so that successive runs of the suite try new cases; it is
printed first, and --seed repeats a run.

It also damages files the program reads besides the scene (cut short,
bytes changed, lines deleted or doubled, numbers made huge): the mesh files
of the scenes that read one (--mesh-count), and the files of a checkpoint
it then resumes from (--checkpoint-count, the manifest included).

usage: fuzz.py <contact executable> <parameters folder> [--count 200]
               [--mesh-count 0] [--checkpoint-count 0] [--seed N]
               [--timeout 20] [--keep-failures DIR]
"""
import argparse
import glob
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

NUMBERS = ["0", "-1", "1e300", "-1e300", "1e-300", "123456789", "2147483648",
           "nan", "inf", "-0", "1e9", "0.5", "3", "-7.25"]
WORDS = ["foo", "left", "bottom; top", "top: 1, 2, 3", "x", ";", ":", ",", "",
         "plane", "box", "true", "semismooth Newton", "if(t, 1)", "t/0",
         "\u00e9t\u00e9", "sqrt(-1)"]


def mutate(lines, rng):
    lines = list(lines)
    sets = [i for i, l in enumerate(lines) if l.strip().startswith("set ")]
    kind = rng.randrange(9)
    if kind == 0 and lines:                      # delete a line
        del lines[rng.randrange(len(lines))]
    elif kind == 1 and lines:                    # duplicate a line
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
    elif kind == 2 and len(sets) > 1:            # swap two values
        a, b = rng.sample(sets, 2)
        va, vb = lines[a].split("=", 1)[1], lines[b].split("=", 1)[1]
        lines[a] = lines[a].split("=", 1)[0] + "=" + vb
        lines[b] = lines[b].split("=", 1)[0] + "=" + va
    elif kind == 3 and sets:                     # a number where a value was
        i = rng.choice(sets)
        lines[i] = lines[i].split("=", 1)[0] + "= " + rng.choice(NUMBERS) + "\n"
    elif kind == 4 and sets:                     # a word where a value was
        i = rng.choice(sets)
        lines[i] = lines[i].split("=", 1)[0] + "= " + rng.choice(WORDS) + "\n"
    elif kind == 5 and lines:                    # random bytes in a line
        i = rng.randrange(len(lines))
        position = rng.randrange(len(lines[i]) + 1)
        noise = "".join(chr(rng.randrange(1, 256)) for _ in range(rng.randrange(1, 6)))
        lines[i] = lines[i][:position] + noise + lines[i][position:]
    elif kind == 6 and sets:                     # a number scaled hugely
        i = rng.choice(sets)
        lines[i] = re.sub(r"\d+(\.\d*)?", lambda m: m.group(0) + "e" +
                          str(rng.choice([-300, -20, 20, 300])), lines[i], count=1)
    elif kind == 7:                              # an entry nobody declared
        lines.insert(rng.randrange(len(lines) + 1), "set Frobnication = 3\n")
    elif kind == 8 and lines:                    # cut the file short
        lines = lines[:rng.randrange(len(lines))]
    return lines


def corrupt(data, rng):
    """A damaged copy of a file's bytes: cut short, bytes changed, a line
    deleted or doubled, or a number made huge."""
    kind = rng.randrange(5)
    if kind == 0 or len(data) < 2:
        return data[:rng.randrange(len(data) + 1)]
    if kind == 1:
        data = bytearray(data)
        for _ in range(rng.randrange(1, 8)):
            data[rng.randrange(len(data))] = rng.randrange(256)
        return bytes(data)
    lines = data.split(b"\n")
    i = rng.randrange(len(lines))
    if kind == 2:
        del lines[i]
    elif kind == 3:
        lines.insert(i, lines[i])
    else:
        lines[i] = re.sub(rb"\d+", b"99999999999", lines[i], count=1)
    return b"\n".join(lines)


class Runner:
    """Runs the program on one input and sorts the outcome."""

    def __init__(self, contact, folder, timeout, keep_failures):
        self.contact, self.folder, self.timeout = contact, folder, timeout
        self.keep_failures = keep_failures
        self.counts = {"ran": 0, "clear error": 0, "timeout": 0, "crash": 0}
        self.environment = dict(
            os.environ, ASAN_OPTIONS="detect_leaks=0:detect_container_overflow=0",
            UBSAN_OPTIONS="print_stacktrace=1", OMP_NUM_THREADS="1")

    def run(self, name, text, what):
        scene = os.path.join(self.folder, f"{name}.prm")
        with open(scene, "w", encoding="utf-8", errors="replace") as f:
            f.write(text)
        try:
            done = subprocess.run([self.contact, scene], cwd=self.folder,
                                  capture_output=True, timeout=self.timeout,
                                  env=self.environment)
        except subprocess.TimeoutExpired:
            self.counts["timeout"] += 1
            return
        output = (done.stdout + done.stderr).decode("utf-8", errors="replace")
        errors = sum(1 for l in output.splitlines() if l.startswith("Error: "))
        report = re.search(r"AddressSanitizer|runtime error:|LeakSanitizer|"
                           r"[Ss]tack ?trace|terminate called|Aborted|"
                           r"Segmentation fault", output)
        if done.returncode == 0 and not report:
            self.counts["ran"] += 1
        elif done.returncode in (1, 2) and errors == 1 and not report:
            self.counts["clear error"] += 1
        else:
            self.counts["crash"] += 1
            print(f"CRASH in {name} ({what}), exit code {done.returncode}:\n"
                  f"--- input:\n{text}\n--- output:\n{output[-3000:]}")
            if self.keep_failures:
                os.makedirs(self.keep_failures, exist_ok=True)
                shutil.copy(scene, self.keep_failures)


def mesh_cases(runner, parameters, count, rng):
    """The scenes that read a mesh file, each with a damaged copy of it."""
    scenes = [p for p in sorted(glob.glob(os.path.join(parameters, "*.prm")))
              if "Mesh file" in open(p, encoding="utf-8").read()]
    for case in range(count if scenes else 0):
        scene = rng.choice(scenes)
        text = open(scene, encoding="utf-8").read()
        mesh = re.search(r"set Mesh file\s*=\s*(\S+)", text).group(1)
        # The mesh file is relative to the scene; the damaged copy goes
        # into the runner's folder, next to the scene it runs.
        source = os.path.join(os.path.dirname(scene), mesh)
        damaged_name = "damaged-" + os.path.basename(mesh)
        with open(source, "rb") as f:
            damaged = corrupt(f.read(), rng)
        with open(os.path.join(runner.folder, damaged_name), "wb") as f:
            f.write(damaged)
        text = re.sub(r"(set Mesh file\s*=\s*)\S+", r"\g<1>" + damaged_name, text)
        runner.run(f"mesh{case}", "set Output directory = out\n" +
                   re.sub(r"(?m)^set Output directory.*$", "", text),
                   f"{os.path.basename(scene)} with a damaged {mesh}")
        shutil.rmtree(os.path.join(runner.folder, "out"), ignore_errors=True)


def checkpoint_cases(runner, parameters, count, rng):
    """Resumes from a checkpoint with one damaged file (the manifest too)."""
    scene = ("include " + os.path.join(parameters, "example1.prm") + "\n"
             "set Output directory = made\nsubsection Loading\n"
             "  set Number of increments = 2\nend\nsubsection Contact solver\n"
             "  set Method = semismooth Newton\nend\n")
    runner.run("checkpoint", scene, "the run that writes the checkpoint")
    made = os.path.join(runner.folder, "made")
    if count == 0 or not os.path.isdir(os.path.join(made, "checkpoint")):
        return
    resume = scene.replace("made", "out") + "set Resume computation = true\n"
    for case in range(count):
        out = os.path.join(runner.folder, "out")
        shutil.rmtree(out, ignore_errors=True)
        shutil.copytree(made, out)
        files = sorted(glob.glob(os.path.join(out, "checkpoint", "*")))
        damaged = rng.choice(files)
        with open(damaged, "rb") as f:
            data = corrupt(f.read(), rng)
        with open(damaged, "wb") as f:
            f.write(data)
        runner.run(f"resume{case}", resume,
                   f"resume with a damaged {os.path.basename(damaged)}")
    shutil.rmtree(os.path.join(runner.folder, "out"), ignore_errors=True)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("contact")
    parser.add_argument("parameters")
    parser.add_argument("--count", type=int, default=200)
    parser.add_argument("--mesh-count", type=int, default=0,
                        help="damaged mesh files, in the scenes that read one")
    parser.add_argument("--checkpoint-count", type=int, default=0,
                        help="resumes from a checkpoint with a damaged file")
    parser.add_argument("--seed", type=int, default=int(time.time() // 86400))
    parser.add_argument("--timeout", type=float, default=20)
    parser.add_argument("--keep-failures", default=None)
    args = parser.parse_args()
    args.contact = os.path.abspath(args.contact)
    args.parameters = os.path.abspath(args.parameters)

    print(f"fuzz: seed {args.seed} (repeat with --seed {args.seed})", flush=True)
    seeds = sorted(glob.glob(os.path.join(args.parameters, "*.prm")))
    rng = random.Random(args.seed)
    with tempfile.TemporaryDirectory() as folder:
        runner = Runner(args.contact, folder, args.timeout, args.keep_failures)
        for case in range(args.count):
            seed_file = rng.choice(seeds)
            lines = open(seed_file, encoding="utf-8").readlines()
            lines = [l for l in lines if not l.startswith("set Output directory")]
            # The case runs from another folder: its mesh file by full path.
            lines = [re.sub(r"(set Mesh file\s*=\s*)(\S+)",
                            lambda m: m.group(1) + os.path.join(
                                os.path.dirname(seed_file), m.group(2)), l)
                     for l in lines]
            for _ in range(rng.randrange(1, 4)):
                lines = mutate(lines, rng)
            runner.run(f"case{case}", "set Output directory = out\n" + "".join(lines),
                       f"from {os.path.basename(seed_file)}")
            shutil.rmtree(os.path.join(folder, "out"), ignore_errors=True)
        mesh_cases(runner, args.parameters, args.mesh_count, rng)
        checkpoint_cases(runner, args.parameters, args.checkpoint_count, rng)
        counts = runner.counts
    total = args.count + args.mesh_count + args.checkpoint_count + \
        (1 if args.checkpoint_count else 0)
    print(f"fuzz: {total} runs ({args.count} mutated parameter files, "
          f"{args.mesh_count} damaged mesh files, {args.checkpoint_count} damaged "
          f"checkpoints{' and the run that writes it' if args.checkpoint_count else ''}): "
          f"{counts['ran']} ran, {counts['clear error']} stopped with "
          f"a clear error, {counts['timeout']} still running after {args.timeout:g} s "
          f"(stopped), {counts['crash']} crashed")
    return 1 if counts["crash"] else 0


if __name__ == "__main__":
    sys.exit(main())
