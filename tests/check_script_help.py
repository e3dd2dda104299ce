#!/usr/bin/env python3
"""Every Python script of the project answers --help with exit code 0 and
without importing its heavy modules (matplotlib, numpy), so that the usage
shows where they are missing.

usage: check_script_help.py <project source folder>
"""
import glob
import os
import subprocess
import sys

HEAVY = ("matplotlib", "numpy", "paraview")


def main():
    if len(sys.argv) != 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(sys.argv) == 2 else 2
    root = sys.argv[1]
    scripts = sorted(glob.glob(os.path.join(root, "scripts", "*.py")) +
                     glob.glob(os.path.join(root, "bench", "*.py")) +
                     glob.glob(os.path.join(root, "tests", "*.py")))
    failed = []
    for script in scripts:
        done = subprocess.run([sys.executable, "-X", "importtime", script,
                               "--help"], capture_output=True, text=True)
        imported = {line.split("|")[-1].strip().split(".")[0]
                    for line in done.stderr.splitlines() if "|" in line}
        heavy = sorted(imported.intersection(HEAVY))
        ok = done.returncode == 0 and not heavy
        print(f"{os.path.relpath(script, root)}: exit {done.returncode}"
              + (f", imports {', '.join(heavy)}" if heavy else "")
              + ("" if ok else "  FAILED"))
        if not ok:
            failed.append(script)
    print(f"{len(scripts) - len(failed)} of {len(scripts)} scripts pass")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
