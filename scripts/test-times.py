#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The seconds of every test of the builds scripts/test.sh ran, in one table
(slowest first), and the check of each test against its label's budget.

    scripts/test-times.py --out build/test-times.md --budgets Testing/budgets.json \\
        NAME=BUILD_DIR=JUNIT_XML [NAME=BUILD_DIR=JUNIT_XML ...]

Each NAME=BUILD_DIR=JUNIT_XML is one ctest run: its build's name in the
table, its build folder (where `ctest --show-only=json-v1` gives each
test's labels) and the JUnit file its `ctest --output-junit` wrote (ctest's
own time for each test). A test's budget is the largest budget of its
labels in its build (Testing/budgets.json: {build: {label: seconds}};
"other" for a test with none of them); a test that ran longer than 1.5
times its budget is named with its time, and the script exits 1. The table
also sums each label's seconds.
"""
import argparse
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

OVER = 1.5  # a test may run this many times its budget before the check fails


def labels_of(build_dir):
    """{test: [labels]} of the build's tests, as ctest lists them."""
    listing = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build_dir, capture_output=True, text=True,
                             check=True)
    labels = {}
    for test in json.loads(listing.stdout).get("tests", []):
        found = [p["value"] for p in test.get("properties", []) if p["name"] == "LABELS"]
        labels[test["name"]] = found[0] if found else []
    return labels


def times_of(junit):
    """[(test, seconds, status)] of a ctest JUnit file."""
    rows = []
    for case in ElementTree.parse(junit).getroot().iter("testcase"):
        status = case.get("status", "run")
        if case.find("failure") is not None:
            status = "failed"
        elif case.find("skipped") is not None or status == "notrun":
            status = "skipped"
        else:
            status = "passed"
        rows.append((case.get("name"), float(case.get("time", "0")), status))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, help="the Markdown table to write")
    parser.add_argument("--budgets", required=True, help="{label: seconds} (JSON)")
    parser.add_argument("runs", nargs="+", help="NAME=BUILD_DIR=JUNIT_XML")
    args = parser.parse_args()
    with open(args.budgets) as f:
        budgets = {k: v for k, v in json.load(f).items() if not k.startswith("_")}
    for run in args.runs:
        if run.split("=", 1)[0] not in budgets:
            sys.exit("test-times: no budgets for the build %r in %s" % (run.split("=", 1)[0], args.budgets))
    rows = []
    for run in args.runs:
        name, build_dir, junit = run.split("=", 2)
        if not os.path.exists(junit):
            print("test-times: %s: no %s (its ctest did not run)" % (name, junit))
            continue
        labels = labels_of(build_dir)
        for test, seconds, status in times_of(junit):
            own = labels.get(test, [])
            mine = budgets[name]
            budget = max([mine[label] for label in own if label in mine] or [mine["other"]])
            rows.append((seconds, name, test, own, budget, status))
    rows.sort(key=lambda row: -row[0])
    over = [row for row in rows if row[5] == "passed" and row[0] > OVER * row[4]]
    lines = ["# Test times", "",
             "ctest's seconds for each test of the last `scripts/test.sh` (written by `scripts/test-times.py`), "
             "slowest first. A test may take up to %.1f times the budget of its labels in its build "
             "(`Testing/budgets.json`, the largest of its labels')." % OVER, "",
             "| seconds | build | test | labels | budget | |", "|---|---|---|---|---|---|"]
    for seconds, name, test, own, budget, status in rows:
        mark = "OVER" if (seconds, name, test, own, budget, status) in over else status
        lines.append("| %.1f | %s | %s | %s | %g | %s |" % (seconds, name, test, ", ".join(own), budget, mark))
    totals = {}
    for seconds, name, _, own, _, _ in rows:
        for label in own or ["(none)"]:
            totals[(name, label)] = totals.get((name, label), 0.0) + seconds
    lines += ["", "| build | label | tests' seconds |", "|---|---|---|"]
    lines += ["| %s | %s | %.0f |" % (name, label, total) for (name, label), total in sorted(totals.items())]
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("test-times: %d tests, %.0f s of ctest in all; the slowest ten (table: %s):" % (
        len(rows), sum(row[0] for row in rows), args.out))
    for seconds, name, test, _, budget, _ in rows[:10]:
        print("  %7.1f s  %-24s %s (budget %g s)" % (seconds, test, name, budget))
    for seconds, name, test, own, budget, _ in over:
        print("test-times: OVER BUDGET: %s (%s) took %.1f s, more than %.1f x %g s, the budget of %s" % (
            test, name, seconds, OVER, budget, ", ".join(own) or "other"))
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
