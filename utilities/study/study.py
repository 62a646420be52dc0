#!/usr/bin/python3
"""Error against run time over a sweep of a case's settings.

Usage: utilities/study/study.py STUDYDICT [--jobs N] [--output DIR] [--threads T]

STUDYDICT (OpenFOAM syntax; the case is the directory that holds its system/):
    error       velocityError;     // the function object whose errors the case reports
    quantity    U;                 // which of its quantities (default: its first)
    norm        L1;                // L1, L2 or Linf (default L1)
    resolution  spacing;           // the parameter that is the resolution (its order is measured)
    parameters
    {
        spacing { file system/generateParticlesDict; entry spacing; values (0.04 0.02 0.01); }
        kernel
        {
            file    system/sphSchemes;
            entry   kernel;                                  // a path: equationOfState/c0
            values  ("{ type wendlandC2; hdx 2; }" "{ type quinticSpline; hdx 1; }");
            labels  (wendlandC2 quinticSpline);              // optional names for the plot
        }
        walls                          // several edits taken together: one sub-dictionary each
        {
            model  { file constant/boundaryProperties; entry tank; values ("{ type dummyParticles; }" "{ type dynamicBoundary; }"); }
            layers { file system/generateParticlesDict; entry boundaries/tank/layers; values (4 3); }
        }
    }
    set { endTime { file system/controlDict; entry endTime; value 0.1; } }   // optional, for every run
A value may use another parameter's value, scaled: "r0 ${spacing*0.5};".

Every combination of the parameters' values is a point. Before any run, each point's case is
prepared and checked (generateParticles, then wcsph -rates): an unknown model, a missing entry, a
bad reference file or a probe outside the domain stops the study there, naming the point. Then
the points run, JOBS at a time (default: the cores over THREADS, 1 thread per run), each in
DIR/<point>/ (default DIR: study-<case> in the current directory). A point whose results are
already in DIR/study.csv is not run again (a failed one is): a stopped study resumes. Writes DIR/study.csv,
DIR/study.md (the table, the Pareto front, the cheapest point under each error level and the
observed order in the resolution) and DIR/study.png (error against wall time, log-log, one
series per configuration, the Pareto front marked).
Binaries: $SPHKIT_BIN or build/bin of this repository.
"""
import argparse
import concurrent.futures
import csv
import itertools
import math
import os
import re
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import foamDictionary  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin"))
NORMS = ("L1", "L2", "Linf")
COLUMNS = ["point", "status", "error", "wallTime_s", "fluidParticles", "steps", "particleSteps_per_s", "threads", "message"]


class StudyError(Exception):
    pass


def read_study(path):
    """The study's settings, checked against the case's files before anything runs."""
    text = open(path).read()
    try:
        study = foamDictionary.parse(text, path)
    except foamDictionary.DictionaryError as e:
        raise StudyError(str(e))
    case = os.path.dirname(os.path.dirname(os.path.abspath(path)))
    if not os.path.isdir(os.path.join(case, "system")):
        raise StudyError("%s: the study dictionary must lie in a case's system/ directory" % path)

    def word(keyword, default=None, valid=None):
        entry = study.get(keyword)
        if entry is None:
            if default is None:
                raise StudyError("%s: keyword '%s' is missing" % (path, keyword))
            return default
        value = " ".join(entry.value).strip('"')
        if valid and value not in valid:
            raise StudyError("%s:%d: keyword '%s': found '%s'; valid: %s" % (path, entry.line, keyword, value, ", ".join(valid)))
        return value

    def target(name, entry, many):
        """One edit: (file relative to the case, entry path, values)."""
        for keyword in ("file", "entry", "values" if many else "value"):
            if keyword not in entry.value:
                raise StudyError("%s:%d: '%s' has no '%s'" % (path, entry.line, name, keyword))
        file = os.path.join(case, " ".join(entry.value["file"].value).strip('"'))
        entry_path = " ".join(entry.value["entry"].value).strip('"')
        if not os.path.isfile(file):
            raise StudyError("%s:%d: '%s': file '%s' does not exist" % (path, entry.line, name, file))
        if foamDictionary.find(foamDictionary.parse(open(file).read(), file), entry_path) is None:
            raise StudyError("%s:%d: '%s': '%s' has no entry '%s'" % (path, entry.line, name, file, entry_path))
        values = foamDictionary.words(entry.value["values"]) if many else [" ".join(entry.value["value"].value).strip('"')]
        if not values:
            raise StudyError("%s:%d: '%s' lists no value" % (path, entry.line, name))
        return os.path.relpath(file, case), entry_path, values

    def edit(name, entry, many):
        """A parameter: one target (file, entry, values), or several sub-dictionaries each with
        one, their values taken together (a boundary model and the wall layers it needs)."""
        if not isinstance(entry.value, dict):
            raise StudyError("%s:%d: '%s' must be a sub-dictionary { file ...; entry ...; %s ...; }" % (path, entry.line, name, "values" if many else "value"))
        if "file" in entry.value:
            targets = [target(name, entry, many)]
        else:
            targets = [target(name + "/" + key, sub, many) for key, sub in entry.value.items() if isinstance(sub.value, dict)]
            if not targets:
                raise StudyError("%s:%d: '%s' has no 'file' and no sub-dictionary with one" % (path, entry.line, name))
        count = len(targets[0][2])
        if any(len(values) != count for _, _, values in targets):
            raise StudyError("%s:%d: the targets of '%s' list different numbers of values" % (path, entry.line, name))
        values = [[(file, entry_path, vals[k]) for file, entry_path, vals in targets] for k in range(count)]
        first = targets[0][2]
        labels = foamDictionary.words(entry.value["labels"]) if "labels" in entry.value else [re.sub(r"[^\w.+-]+", "_", v).strip("_") for v in first]
        if len(labels) != count:
            raise StudyError("%s:%d: '%s' has %d labels for %d values" % (path, entry.line, name, len(labels), count))
        return {"name": name, "values": values, "labels": labels, "first": first}

    parameters = study.get("parameters")
    if parameters is None or not isinstance(parameters.value, dict) or not parameters.value:
        raise StudyError("%s: 'parameters' must be a sub-dictionary with at least one parameter" % path)
    settings = {
        "case": case,
        "error": word("error"),
        "quantity": word("quantity", ""),
        "norm": word("norm", "L1", NORMS),
        "parameters": [edit(name, entry, True) for name, entry in parameters.value.items()],
        "fixed": [edit(name, entry, False) for name, entry in (study["set"].value.items() if "set" in study else [])],
    }
    settings["resolution"] = word("resolution", "")
    names = [p["name"] for p in settings["parameters"]]
    for p in settings["parameters"] + settings["fixed"]:
        for edits in p["values"]:
            for _, _, value in edits:
                for reference in REFERENCE.finditer(value):
                    if reference.group(1) not in names:
                        raise StudyError("%s: '%s' uses ${%s}, which is not a parameter (%s)" % (path, p["name"], reference.group(1), ", ".join(names)))
    if settings["resolution"] and settings["resolution"] not in names:
        raise StudyError("%s: resolution '%s' is not one of the parameters (%s)" % (path, settings["resolution"], ", ".join(names)))
    control = foamDictionary.parse(open(os.path.join(case, "system", "controlDict")).read(), "controlDict")
    if foamDictionary.find(control, "functions/" + settings["error"]) is None:
        raise StudyError("%s: error '%s' is not a function object of %s/system/controlDict" % (path, settings["error"], case))
    return settings


REFERENCE = re.compile(r"\$\{(\w+)(?:\*([0-9.eE+-]+))?\}")


def points_of(settings):
    """Every combination: (name, {parameter: label}, [(file, entry, value)]). A value may use
    another parameter's (first) value, scaled: ${spacing*0.5}."""
    parameters = settings["parameters"]
    for choice in itertools.product(*[range(len(p["values"])) for p in parameters]):
        labels = {p["name"]: p["labels"][k] for p, k in zip(parameters, choice)}
        chosen = {p["name"]: p["first"][k] for p, k in zip(parameters, choice)}
        edits = [edit for p, k in zip(parameters, choice) for edit in p["values"][k]]
        edits += [edit for f in settings["fixed"] for edit in f["values"][0]]
        substitute = lambda m: "%g" % (float(chosen[m.group(1)]) * float(m.group(2) or 1))
        yield "_".join("%s-%s" % item for item in labels.items()), labels, [(f, e, REFERENCE.sub(substitute, v)) for f, e, v in edits]


def prepare(settings, directory, edits):
    """A copy of the case (dictionaries and reference data: .csv files opening with a '#' header) with the point's edits."""
    if os.path.exists(directory):
        shutil.rmtree(directory)
    os.makedirs(directory)
    case = settings["case"]
    for item in os.listdir(case):
        source = os.path.join(case, item)
        if item in ("system", "constant"):
            shutil.copytree(source, os.path.join(directory, item))
        elif os.path.isfile(source) and item.endswith(".csv") and open(source).read(1) == "#":  # reference data, not a script's output
            shutil.copy(source, directory)
    for file, entry, value in edits:
        target = os.path.join(directory, file)
        text = foamDictionary.set_entry(open(target).read(), entry, value, target)
        with open(target, "w") as f:
            f.write(text)


def solver(arguments, directory, threads, log):
    environment = dict(os.environ, OMP_NUM_THREADS=str(threads))
    with open(os.path.join(directory, log), "w") as out:
        return subprocess.run([os.path.join(BIN, arguments[0])] + arguments[1:] + ["-case", directory], stdout=out, stderr=subprocess.STDOUT,
                              env=environment).returncode


def last_error_line(directory, log):
    """The solver's error message (its first line and the indented lines under it)."""
    lines = [line.rstrip() for line in open(os.path.join(directory, log)) if line.strip()]
    first = next((k for k, line in enumerate(lines) if "error" in line.lower()), None)
    if first is None:
        return lines[-1].strip() if lines else "no output"
    end = first + 1
    while end < len(lines) and lines[end].startswith(" "):
        end += 1
    return " ".join(line.strip() for line in lines[first:end])


def preflight(settings, directory, edits):
    """Prepares a point and checks it reads: None, or the solver's error."""
    prepare(settings, directory, edits)
    for arguments, log in ((["generateParticles", "-overwrite"], "log.generateParticles"), (["wcsph", "-rates"], "log.check")):
        if solver(arguments, directory, 1, log) != 0:
            return last_error_line(directory, log)
    shutil.rmtree(os.path.join(directory, "postProcessing"), ignore_errors=True)
    return None


def run_point(settings, name, directory, threads):
    """Runs a prepared point and returns its row."""
    row = {"point": name, "threads": threads, "message": ""}
    if solver(["wcsph"], directory, threads, "log.wcsph") != 0:
        row.update(status="failed", message=last_error_line(directory, "log.wcsph"))
        return row
    summary = os.path.join(directory, "postProcessing", "summary", "0", "summary.csv")
    if not os.path.isfile(summary):
        row.update(status="failed", message="the run wrote no summary (no function object with a reference)")
        return row
    with open(summary) as f:
        reported = [r for r in csv.DictReader(f) if r["functionObject"] == settings["error"]]
    chosen = [r for r in reported if not settings["quantity"] or r["quantity"] == settings["quantity"]]
    if not chosen:
        row.update(status="failed", message="'%s' reported no quantity '%s'" % (settings["error"], settings["quantity"]))
        return row
    r = chosen[0]
    row.update(status="ok", error=r[settings["norm"]], wallTime_s=r["wallTime_s"], fluidParticles=r["fluidParticles"], steps=r["steps"],
               particleSteps_per_s=r["particleSteps_per_s"])
    return row


def write_atomically(path, text):
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def write_csv(path, rows, parameter_names):
    lines = [",".join(parameter_names + COLUMNS)]
    for row in rows:
        lines.append(",".join([row["labels"][n] for n in parameter_names] + ['"%s"' % str(row.get(c, "")).replace('"', "'") for c in COLUMNS]))
    write_atomically(path, "\n".join(lines) + "\n")


def read_csv(path, parameter_names):
    if not os.path.isfile(path):
        return {}
    with open(path) as f:
        rows = list(csv.DictReader(f))
    done = {}
    for r in rows:
        if r.get("status") == "ok":  # a failed point runs again: the study or the case may have been mended
            r["labels"] = {n: r[n] for n in parameter_names}
            done[r["point"]] = r
    return done


def pareto(rows):
    """The points no other point beats in both error and wall time."""
    front = []
    for r in sorted(rows, key=lambda r: (float(r["wallTime_s"]), float(r["error"]))):
        if not front or float(r["error"]) < float(front[-1]["error"]):
            front.append(r)
    return front


def series_of(row, settings):
    return ", ".join(row["labels"][p["name"]] for p in settings["parameters"] if p["name"] != settings["resolution"]) or "all"


def observed_orders(rows, settings):
    """Per series: the least-squares slope of log(error) against log(resolution value)."""
    if not settings["resolution"]:
        return {}
    parameter = next(p for p in settings["parameters"] if p["name"] == settings["resolution"])
    value_of = dict(zip(parameter["labels"], parameter["first"]))
    orders = {}
    for series in sorted({series_of(r, settings) for r in rows}):
        pairs = []
        for r in rows:
            if series_of(r, settings) != series:
                continue
            try:
                pairs.append((math.log(float(value_of[r["labels"][parameter["name"]]])), math.log(float(r["error"]))))
            except (ValueError, KeyError):
                return {}
        if len(pairs) >= 2:
            mx = sum(p[0] for p in pairs) / len(pairs)
            my = sum(p[1] for p in pairs) / len(pairs)
            sxx = sum((p[0] - mx) ** 2 for p in pairs)
            if sxx > 0:
                orders[series] = (sum((p[0] - mx) * (p[1] - my) for p in pairs) / sxx, len(pairs))
    return orders


def report(settings, rows, output, command):
    ok = [r for r in rows if r["status"] == "ok"]
    names = [p["name"] for p in settings["parameters"]]
    quantity = settings["error"] + (" " + settings["quantity"] if settings["quantity"] else "")
    md = ["# Study: %s, %s %s against wall time" % (os.path.basename(settings["case"]), settings["norm"], quantity), "",
          "Regenerate: `%s`" % command, "",
          "| " + " | ".join(names) + " | %s | wall time [s] | fluid particles | steps | particle-steps/s | threads |" % settings["norm"],
          "|" + "---|" * (len(names) + 6)]
    front = pareto(ok)
    for r in rows:
        mark = " (Pareto)" if r in front else ""
        if r["status"] == "ok":
            md.append("| " + " | ".join(r["labels"][n] for n in names) + " | %.3e%s | %.3g | %s | %s | %.3g | %s |" % (
                float(r["error"]), mark, float(r["wallTime_s"]), r["fluidParticles"], r["steps"], float(r["particleSteps_per_s"]), r["threads"]))
        else:
            md.append("| " + " | ".join(r["labels"][n] for n in names) + " | failed: %s | | | | | |" % r["message"].replace("|", "/"))
    if ok:
        md += ["", "Pareto front (no other point has both a lower error and a shorter wall time): " +
               "; ".join("%s (%.2e in %.3g s)" % (", ".join(r["labels"][n] for n in names), float(r["error"]), float(r["wallTime_s"])) for r in front), ""]
        # Error levels 1, 2, 5 x 10^k from the smallest error reached to the largest.
        low, high = min(float(r["error"]) for r in ok), max(float(r["error"]) for r in ok)
        levels = [m * 10 ** k for k in range(math.floor(math.log10(low)), math.ceil(math.log10(high)) + 1) for m in (1, 2, 5)]
        ceiling = min(level for level in levels if level >= high)
        levels = [level for level in levels if low <= level <= ceiling]
        md += ["| error at most | cheapest configuration | its error | wall time [s] |", "|---|---|---|---|"]
        for level in levels:
            under = [r for r in ok if float(r["error"]) <= level]
            if under:
                best = min(under, key=lambda r: float(r["wallTime_s"]))
                md.append("| %.0e | %s | %.2e | %.3g |" % (level, ", ".join(best["labels"][n] for n in names), float(best["error"]), float(best["wallTime_s"])))
        orders = observed_orders(ok, settings)
        if orders:
            md += ["", "Observed order in %s (least-squares slope of log error against log %s):" % (settings["resolution"], settings["resolution"]), ""]
            md += ["- %s: %.2f (%d points)" % (series, order, n) for series, (order, n) in orders.items()]
    write_atomically(os.path.join(output, "study.md"), "\n".join(md) + "\n")
    if ok:
        plot(settings, ok, front, os.path.join(output, "study.png"), quantity)


def plot(settings, ok, front, path, quantity):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 5))
    for series in sorted({series_of(r, settings) for r in ok}):
        members = sorted((r for r in ok if series_of(r, settings) == series), key=lambda r: float(r["wallTime_s"]))
        ax.loglog([float(r["wallTime_s"]) for r in members], [float(r["error"]) for r in members], "o-", label=series)
        if settings["resolution"]:
            for r in members:
                ax.annotate(r["labels"][settings["resolution"]], (float(r["wallTime_s"]), float(r["error"])), fontsize=7, xytext=(3, 3),
                            textcoords="offset points")
    ax.loglog([float(r["wallTime_s"]) for r in front], [float(r["error"]) for r in front], "k--", lw=1)
    ax.scatter([float(r["wallTime_s"]) for r in front], [float(r["error"]) for r in front], s=120, facecolors="none", edgecolors="k",
               label="Pareto front")
    ax.set(xlabel="wall time [s]", ylabel="%s error (%s)" % (settings["norm"], quantity), title="%s: error against run time" % os.path.basename(settings["case"]))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description="Error against run time over a sweep of a case's settings.")
    parser.add_argument("study", help="the study dictionary, in the case's system/")
    parser.add_argument("--output", help="results directory (default: study-<case> here)")
    parser.add_argument("--threads", type=int, default=1, help="OpenMP threads per run (default 1)")
    parser.add_argument("--jobs", type=int, help="runs at a time (default: cores / threads)")
    args = parser.parse_args()
    if args.threads < 1 or (args.jobs is not None and args.jobs < 1):
        sys.exit("error: --threads and --jobs must be at least 1, found %s and %s" % (args.threads, args.jobs))
    try:
        settings = read_study(args.study)
    except (StudyError, foamDictionary.DictionaryError, OSError) as e:
        sys.exit("error: %s" % e)
    jobs = args.jobs or max(1, (os.cpu_count() or 1) // args.threads)
    output = os.path.abspath(args.output or "study-" + os.path.basename(settings["case"]))
    os.makedirs(output, exist_ok=True)
    names = [p["name"] for p in settings["parameters"]]
    results = os.path.join(output, "study.csv")
    done = read_csv(results, names)
    points = list(points_of(settings))
    todo = [(name, labels, edits) for name, labels, edits in points if name not in done]
    print("study of %s: %d points, %d already in %s, %d to run, %d at a time" % (settings["case"], len(points), len(points) - len(todo), results,
                                                                               len(todo), jobs), flush=True)
    for k, (name, labels, edits) in enumerate(todo):
        problem = preflight(settings, os.path.join(output, name), edits)
        print("  checked %d/%d %s%s" % (k + 1, len(todo), name, ": " + problem if problem else ""), flush=True)
        if problem:
            sys.exit("error: point %s (%s) does not run: %s\nNothing was run; fix the study or the case." % (
                name, ", ".join("%s = %s" % item for item in labels.items()), problem))
    rows = dict(done)
    started = time.time()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {pool.submit(run_point, settings, name, os.path.join(output, name), args.threads): (name, labels) for name, labels, _ in todo}
        for k, future in enumerate(concurrent.futures.as_completed(futures)):
            name, labels = futures[future]
            row = future.result()
            row["labels"] = labels
            rows[name] = row
            write_csv(results, [rows[n] for n, _, _ in points if n in rows], names)
            elapsed = time.time() - started
            figure = "%s %s in %.3g s" % (settings["norm"], row["error"], float(row["wallTime_s"])) if row["status"] == "ok" else "failed: " + row["message"]
            print("  [%d/%d, %.0f s, about %.0f s left] %s: %s" % (k + 1, len(todo), elapsed, elapsed / (k + 1) * (len(todo) - k - 1), name, figure),
                  flush=True)
    ordered = [rows[n] for n, _, _ in points]
    command = "utilities/study/study.py %s" % os.path.relpath(os.path.abspath(args.study), ROOT)
    report(settings, ordered, output, command)
    print("wrote %s, %s and %s" % (results, os.path.join(output, "study.md"), os.path.join(output, "study.png")))


if __name__ == "__main__":
    main()
