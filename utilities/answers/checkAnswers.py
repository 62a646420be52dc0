#!/usr/bin/python3
"""Checks the figures a case's README quotes against what its Allrun prints, to the digits the
README prints them with, so that documented results cannot drift.

Each case that quotes figures keeps them in `answers` beside its README, one per line:
    FILE "PATTERN" QUOTED [scale=S] [doc=PATH]
FILE is what Allrun writes (a log, a CSV) relative to the case; PATTERN a Python regular
expression whose first group is the figure (the first match in FILE); QUOTED the figure as the
README prints it, which must appear there (or, with doc=PATH, in that document of the
repository, such as doc/userGuide.md); S (default 1) multiplies the figure first (100 for a
percentage). The figure passes when, rounded to QUOTED's digits (its decimals, or its
mantissa's in e-notation), it equals QUOTED (allowing for the figure's own rounding in FILE). Lines starting with // are comments.

Usage: checkAnswers.py [--run] CASE ...
  --run  copies each case to a temporary directory and runs its Allrun there first (one thread,
         the programs in SPHKIT_BIN, by default build/bin); without it the case's own outputs are read.
Exit status 1 when any figure differs, is missing from its file, or is not quoted in the README."""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
OUTPUTS = shutil.ignore_patterns("[0-9]*", "postProcessing", "log.*", "*.pvd", "*.png", "variants", "*Comparison.csv")


def read_answers(case):
    answers = []
    with open(os.path.join(case, "answers")) as f:
        for number, line in enumerate(f, 1):
            if not line.strip() or line.lstrip().startswith("//"):
                continue
            fields = shlex.split(line)
            options = dict(field.split("=", 1) for field in fields[3:] if "=" in field)
            if len(fields) < 3 or len(options) != len(fields) - 3 or not set(options) <= {"scale", "doc"}:
                sys.exit("%s/answers:%d: expected FILE \"PATTERN\" QUOTED [scale=S] [doc=PATH], found: %s" % (case, number, line.strip()))
            document = os.path.join(ROOT, options["doc"]) if "doc" in options else os.path.join(case, "README.md")
            answers.append((number, fields[0], fields[1], fields[2], float(options.get("scale", 1.0)), document))
    return answers


def last_digit(text):
    """The value of one unit in the last digit of a number as printed ("3.06e-4": 1e-6)."""
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 10.0 ** (int(exponent or 0) - decimals)


def agrees(printed, scale, quoted):
    """Whether the printed figure, times scale, rounds to the quoted one: within half a unit of
    the quote's last digit, widened by half a unit of the printed figure's own last digit (it
    was rounded once already: 0.0003055 may be 3.0553e-4, quoted 3.06e-4)."""
    own = 0.0 if re.fullmatch(r"[-+]?\d+", printed) else 0.5 * last_digit(printed) * abs(scale)  # a count is exact
    return abs(float(printed) * scale - float(quoted)) <= 0.5 * last_digit(quoted) + own + 1e-12 * abs(float(quoted))


def quoted_in(text, quoted):
    return re.search(r"(?<![\d.])" + re.escape(quoted) + r"(?![\d])", text) is not None


def check(case, outputs):
    failures = []
    for number, name, pattern, quoted, scale, document in read_answers(case):
        where = "%s/answers:%d" % (os.path.basename(os.path.abspath(case)), number)
        with open(document) as f:
            if not quoted_in(f.read(), quoted):
                failures.append("%s: %s is not quoted in %s" % (where, quoted, os.path.relpath(document, ROOT)))
        try:
            with open(os.path.join(outputs, name)) as f:
                match = re.search(pattern, f.read())
        except OSError:
            failures.append("%s: %s was not written" % (where, name))
            continue
        if not match:
            failures.append("%s: no match for \"%s\" in %s" % (where, pattern, name))
            continue
        if not agrees(match.group(1), scale, quoted):
            failures.append("%s: %s prints %s, %s quotes %s" % (where, name, match.group(1), os.path.relpath(document, ROOT), quoted))
    return failures


def main():
    arguments = sys.argv[1:]
    run = "--run" in arguments
    cases = [a for a in arguments if a != "--run"]
    if not cases:
        sys.exit(__doc__)
    failures = []
    for case in cases:
        if not run:
            failures += check(case, case)
            continue
        with tempfile.TemporaryDirectory() as work:
            copy = os.path.join(work, os.path.basename(os.path.abspath(case)))
            shutil.copytree(case, copy, ignore=OUTPUTS)
            env = dict(os.environ, OMP_NUM_THREADS="1", SPHKIT_BIN=os.path.abspath(os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin"))))
            result = subprocess.run([os.path.join(copy, "Allrun")], capture_output=True, text=True, env=env)
            if result.returncode != 0:
                failures.append("%s: Allrun failed (%d): %s" % (case, result.returncode, (result.stderr or result.stdout)[-500:]))
                continue
            failures += check(case, copy)
    for failure in failures:
        print(failure)
    count = sum(len(read_answers(case)) for case in cases)
    print("%d figures in %d cases: %d differ" % (count, len(cases), len(failures)))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
