#!/usr/bin/env python3
"""Feeds mutated parameter files to the program and checks that each one
either runs or stops with a clear error (exit code 1 or 2 and exactly one
line "Error: ..."), and that none crashes: no signal, no other exit code,
no sanitizer report, no stack trace. The mutations (deleted and duplicated
lines, swapped values, random bytes, huge and negative numbers, unknown
words) start from the shipped scenes. The seed changes every day (days
since 1970), so that successive runs of the suite try new cases; it is
printed first, and --seed repeats a run.

usage: fuzz.py <contact executable> <parameters folder> [--count 200]
               [--seed N] [--timeout 20] [--keep-failures DIR]
"""
import argparse
import glob
import os
import random
import re
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


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("contact")
    parser.add_argument("parameters")
    parser.add_argument("--count", type=int, default=200)
    parser.add_argument("--seed", type=int, default=int(time.time() // 86400))
    parser.add_argument("--timeout", type=float, default=20)
    parser.add_argument("--keep-failures", default=None)
    args = parser.parse_args()
    args.contact = os.path.abspath(args.contact)

    print(f"fuzz: seed {args.seed} (repeat with --seed {args.seed})", flush=True)
    seeds = sorted(glob.glob(os.path.join(args.parameters, "*.prm")))
    rng = random.Random(args.seed)
    counts = {"ran": 0, "clear error": 0, "timeout": 0, "crash": 0}
    environment = dict(os.environ,
                       ASAN_OPTIONS="detect_leaks=0:detect_container_overflow=0",
                       UBSAN_OPTIONS="print_stacktrace=1", OMP_NUM_THREADS="1")
    with tempfile.TemporaryDirectory() as folder:
        for case in range(args.count):
            seed_file = rng.choice(seeds)
            lines = open(seed_file, encoding="utf-8").readlines()
            lines = [l for l in lines if not l.startswith("set Output directory")]
            for _ in range(rng.randrange(1, 4)):
                lines = mutate(lines, rng)
            text = "set Output directory = out\n" + "".join(lines)
            scene = os.path.join(folder, f"case{case}.prm")
            with open(scene, "w", encoding="utf-8", errors="replace") as f:
                f.write(text)
            try:
                done = subprocess.run([args.contact, scene], cwd=folder,
                                      capture_output=True, timeout=args.timeout,
                                      env=environment)
            except subprocess.TimeoutExpired:
                counts["timeout"] += 1
                continue
            output = (done.stdout + done.stderr).decode("utf-8", errors="replace")
            errors = sum(1 for l in output.splitlines() if l.startswith("Error: "))
            report = re.search(r"AddressSanitizer|runtime error:|LeakSanitizer|"
                               r"[Ss]tack ?trace|terminate called|Aborted|"
                               r"Segmentation fault", output)
            if done.returncode == 0 and not report:
                counts["ran"] += 1
            elif done.returncode in (1, 2) and errors == 1 and not report:
                counts["clear error"] += 1
            else:
                counts["crash"] += 1
                print(f"CRASH in case {case} (from {os.path.basename(seed_file)}), "
                      f"exit code {done.returncode}:\n--- input:\n{text}\n--- output:\n"
                      f"{output[-3000:]}")
                if args.keep_failures:
                    os.makedirs(args.keep_failures, exist_ok=True)
                    with open(os.path.join(args.keep_failures, f"case{case}.prm"), "w",
                              encoding="utf-8", errors="replace") as f:
                        f.write(text)
            os.system(f"rm -rf {folder}/out")
    print(f"fuzz: {args.count} mutated parameter files: {counts['ran']} ran, "
          f"{counts['clear error']} stopped with a clear error, {counts['timeout']} "
          f"still running after {args.timeout:g} s (stopped), {counts['crash']} crashed")
    return 1 if counts["crash"] else 0


if __name__ == "__main__":
    sys.exit(main())
