"""Reading a run's statistics file: its rows of numbers and the column
number of each name in its header ("# 6: Contact solver iterations")."""


def table(path):
    return [[float(x) for x in l.split()] for l in open(path) if not l.startswith("#")]


def names(path):
    return {l[1:].split(":", 1)[1].strip(): int(l[1:].split(":", 1)[0])
            for l in open(path) if l.startswith("#") and ":" in l}
