# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Two builds side by side in one run, on a machine others share: the cases of
table2.py (Narrow Band, with and without the volume) and the 1024^3 sphere,
each run in a fresh child process by each build in turn (A B A B ...), so
that both see the same load. Prints the medians, their ratio (A / B) and
the peak resident memory (the children's ru_maxrss, as /usr/bin/time -v).

    python3 benchmarks/compare_builds.py BUILD_A BUILD_B [--repeat 5] [--cases sphere ... sphere-1024]

BUILD_*: build folders (their lib/python3.*/dist-packages hold narrowvolume).
"""
import argparse
import glob
import os
import statistics
import sys

import clouds
import table2  # the children and the cases

CASES = dict(table2.CASES, **{"sphere-1024": ("sphere1024", 1024, 4, 2, 3)})


def site(build):
    found = glob.glob(os.path.join(build, "lib", "python3*", "*-packages"))
    if not found:
        sys.exit("no narrowvolume package under %s" % build)
    return found[0]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("builds", nargs=2)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--cases", nargs="+", default=list(CASES))
    parser.add_argument("--scans", default=clouds.SCANS_DIR)
    args = parser.parse_args()
    sites = [site(b) for b in args.builds]
    print("A = %s, B = %s; medians of %d alternating runs; load average at start: %s" % (
        args.builds[0], args.builds[1], args.repeat, " ".join(open("/proc/loadavg").read().split()[:3])))
    print("| case | volume | set-up A / B | evolution A / B | output A / B | total A / B | A ÷ B total | "
          "A ÷ B output | Update() A / B | A ÷ B Update() | peak MB A / B |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for name in args.cases:
        source, cells, lc, xi, steps = CASES[name][:5]
        task = dict(source=source, cells=cells, offset_cells=lc, xi=xi, steps=steps, kind="ours", domain=0)
        if source == "sphere":
            task["spacing"] = 0.01
        elif not source.startswith("sphere"):
            task["path"] = os.path.join(args.scans, source)
            if not os.path.exists(task["path"]):
                print("skipped %s: %s not found" % (name, task["path"]))
                continue
        for volume in ((False,) if name == "sphere-1024" else (True, False)):
            runs = [[], []]
            for _ in range(args.repeat):
                for b in (0, 1):
                    os.environ["PYTHONPATH"] = sites[b]
                    runs[b].append(table2.run(dict(task, volume=volume)))
            # total: the filter's three timed stages; Update(): the whole call,
            # which also measures the points' spacing.
            m = [{k: statistics.median(r[k] for r in rs) for k in ("setup", "evolution", "surface", "update")}
                 for rs in runs]
            for x in m:
                x["total"] = x["setup"] + x["evolution"] + x["surface"]
            peak = [max(r["maxrss_mb"] for r in rs) for rs in runs]
            print("| %s | %s | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | %.2f | %.2f | %.2f / %.2f "
                  "| %.2f | %.0f / %.0f |" % (
                      name, "on" if volume else "off", m[0]["setup"], m[1]["setup"], m[0]["evolution"],
                      m[1]["evolution"], m[0]["surface"], m[1]["surface"], m[0]["total"], m[1]["total"],
                      m[0]["total"] / m[1]["total"], m[0]["surface"] / m[1]["surface"], m[0]["update"], m[1]["update"],
                      m[0]["update"] / m[1]["update"], peak[0], peak[1]))
            sys.stdout.flush()
    print("load average at the end: %s" % " ".join(open("/proc/loadavg").read().split()[:3]))


if __name__ == "__main__":
    main()
