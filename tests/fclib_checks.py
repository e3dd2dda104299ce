"""What the FCLIB test scripts share: running the program and reading the
numbers it prints, and printing verdicts against limits."""
import re
import subprocess
import sys


def run(command, ranks=0):
    """The command's standard output; exits the test if the command fails."""
    if ranks > 0:
        command = ["mpirun", "-np", str(ranks)] + command
    print("$", " ".join(command), flush=True)
    result = subprocess.run(command, capture_output=True, text=True)
    print(result.stdout + result.stderr, flush=True)
    if result.returncode != 0:
        sys.exit(f"*** exit code {result.returncode}")
    return result.stdout


def numbers(pattern, text):
    """The groups of the first match of @p pattern in @p text, as floats."""
    match = re.search(pattern, text)
    if not match:
        sys.exit(f"*** no line matching {pattern!r}")
    return [float(group) for group in match.groups()]


DIFFERENCE = r"Relative difference to the solution in \S+: v ([^,\s]+), r (\S+)"


def verdict(checks):
    """Prints each (name, value, limit); exits 1 if any value exceeds its limit."""
    failed = False
    for name, value, limit in checks:
        ok = value <= limit
        failed |= not ok
        print(f"{name}: {value:.3e} (limit {limit:g}) {'ok' if ok else 'FAILED'}")
    sys.exit(1 if failed else 0)
