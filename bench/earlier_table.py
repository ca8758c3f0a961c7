"""The table of scripts/bench-earlier.sh: the default (balanced) and the best effort of this build
against an earlier build's default and meshoptimizer's pipeline, through `conescope-cli compare`
(A: builder=meshopt,cone=meshopt,test=apex; B: the optimized builder at an effort) at 64 orbit
views, distance 3, limits 64/124, on every mesh of a list, two at a time. Partitions are compared
at equal counts only (within 5%). Writes PREFIX.csv (one row per mesh) and PREFIX.md.

    python3 bench/earlier_table.py CLI EARLIER LIST PREFIX TITLE

EARLIER is the earlier build's conescope-cli, or a CSV this script wrote, whose earlier columns are
taken for the meshes it lists (the earlier build's results do not change). With --default-only the
best effort is not run (its columns repeat the default's): for quick runs while changing the builder.
"""
import csv
import math
import os
import subprocess
import sys
import json
import time
from concurrent.futures import ThreadPoolExecutor

from props_table import setsOf  # the same sets as the props table (all, polygon, many-part, small prop, ...)

ARGS = ["--a", "builder=meshopt,cone=meshopt,test=apex", "--views", "64", "--distance", "3",
        "--no-per-view", "--no-per-cluster", "--format", "json", "-q"]
SETS = ["all", "polygon", "many-part", "small prop"]
EQUAL_COUNTS = 0.05  # counts within 5% of each other compare
BELOW = 0.8          # a mesh culling less than this share of the earlier build's is listed


def compare(cli, mesh, effort):
    """(clusters of meshoptimizer, efficiency of meshoptimizer, clusters, efficiency, mesh, seconds) or an error."""
    start = time.monotonic()
    run = subprocess.run([cli, "compare", mesh, "--b", f"effort={effort}"] + ARGS,
                         capture_output=True, text=True, timeout=1200)
    seconds = time.monotonic() - start
    if run.returncode:
        return {"error": (run.stderr.strip().splitlines() or ["failed"])[-1]}
    result = json.loads(run.stdout)
    diff = result["diff"]
    return {"mesh": result["b"]["mesh"], "clusters_meshopt": diff["clusters_a"], "efficiency_meshopt": diff["efficiency_a"],
            "clusters": diff["clusters_b"], "efficiency": diff["efficiency_b"], "seconds": seconds}


def measure(cli, earlier, mesh, withBest):
    row = {"mesh": mesh}
    runs = {"balanced": compare(cli, mesh, "balanced")}
    runs["best"] = compare(cli, mesh, "best") if withBest else runs["balanced"]
    runs["earlier"] = earlier[mesh] if isinstance(earlier, dict) else compare(earlier, mesh, "balanced")
    errors = [f"{name}: {run['error']}" for name, run in runs.items() if "error" in run]
    if "error" not in runs["earlier"]:  # kept for a later run that reads this table (EARLIER as a CSV)
        row.update({"clusters_earlier": runs["earlier"]["clusters"], "efficiency_earlier": runs["earlier"]["efficiency"],
                    "seconds_earlier": round(runs["earlier"]["seconds"], 3)})
    if errors:
        row["error"] = "; ".join(errors)
        return row
    info = runs["balanced"]["mesh"]
    row.update({"faces": info["faces"], "triangles": info["triangles"], "components": info["report"]["components"],
                "double_sided_faces": info["report"]["double_sided_faces"],
                "clusters_meshopt": runs["balanced"]["clusters_meshopt"],
                "efficiency_meshopt": runs["balanced"]["efficiency_meshopt"]})
    for name, run in runs.items():
        row[f"clusters_{name}"] = run["clusters"]
        row[f"efficiency_{name}"] = run["efficiency"]
        row[f"seconds_{name}"] = round(run["seconds"], 3)
    return row


def equalCounts(a, b):
    return abs(a - b) <= EQUAL_COUNTS * max(a, b)


def ratio(row):
    """Balanced over the earlier build where both cull (1 where neither does); None otherwise."""
    now, before = row["efficiency_balanced"], row["efficiency_earlier"]
    if now > 0 and before > 0:
        return now / before
    return 1.0 if now == before == 0 else None


def below(row):
    now, before = row["efficiency_balanced"], row["efficiency_earlier"]
    return now < BELOW * before


def lostToMeshopt(row, name):
    return (row[f"clusters_{name}"] > row["clusters_meshopt"] or
            row[f"efficiency_{name}"] < row["efficiency_meshopt"] - 1e-12)


def bestBelowBalanced(row):
    return row["efficiency_best"] < row["efficiency_balanced"] - 1e-12 or row["clusters_best"] > row["clusters_meshopt"]


def geometricMean(values):
    return math.exp(sum(map(math.log, values)) / len(values)) if values else float("nan")


def main():
    withBest = "--default-only" not in sys.argv
    cli, earlier, listing, prefix, title = [a for a in sys.argv[1:] if a != "--default-only"][:5]
    meshes = [line.strip() for line in open(listing) if line.strip()]
    if earlier.endswith(".csv"):
        earlier = {r["mesh"]: ({"error": "not read"} if not r["clusters_earlier"] else
                               {"clusters": int(r["clusters_earlier"]), "efficiency": float(r["efficiency_earlier"]),
                                "seconds": float(r["seconds_earlier"])}) for r in csv.DictReader(open(earlier))}
    with ThreadPoolExecutor(2) as pool:
        rows = list(pool.map(lambda mesh: measure(cli, earlier, mesh, withBest), meshes))
    good = [r for r in rows if "error" not in r]
    for r in good:
        r["sets"] = "; ".join(setsOf(r))
        r["equal_counts"] = equalCounts(r["clusters_balanced"], r["clusters_earlier"])
    fields = ["mesh", "sets", "faces", "triangles", "components", "clusters_meshopt", "efficiency_meshopt",
              "clusters_earlier", "efficiency_earlier", "clusters_balanced", "efficiency_balanced",
              "clusters_best", "efficiency_best", "equal_counts", "seconds_earlier", "seconds_balanced", "seconds_best", "error"]
    with open(prefix + ".csv", "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=fields, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    lines = [f"# {title}: the default against an earlier build's", "",
             f"{len(rows)} meshes, {len(rows) - len(good)} that do not read in one of the builds; `conescope-cli compare` "
             "at 64 views, distance 3, limits 64/124, the default record (chosen cone, octagon test) against "
             "meshoptimizer's pipeline (its builder at cone weight 1, its cone, apex test). Ratio: the default's "
             "efficiency over the earlier build's default, at equal counts (within 5%), where both cull (1 where "
             "neither does). Below 0.8x: culls less than 0.8 times the earlier build's. Losses: less culled than "
             "meshoptimizer, or more clusters. Best below balanced: `--effort best` culls less than the default, "
             "or makes more clusters than meshoptimizer.", "",
             "| set | meshes | at equal counts | geometric mean ratio | below 0.8x | losses to meshoptimizer (default) "
             "| losses to meshoptimizer (best) | best below balanced | time: default / earlier (sum) |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for name in SETS:
        members = [r for r in good if name in r["sets"].split("; ")]
        equal = [r for r in members if r["equal_counts"]]
        ratios = [x for x in map(ratio, equal) if x is not None]
        count = lambda test, among=members: sum(1 for r in among if test(r))
        seconds = sum(r["seconds_balanced"] for r in members) / max(1e-9, sum(r["seconds_earlier"] for r in members))
        lines.append(f"| {name} | {len(members)} | {len(equal)} | {geometricMean(ratios):.3f} | {count(below, equal)} | "
                     f"{count(lambda r: lostToMeshopt(r, 'balanced'))} | {count(lambda r: lostToMeshopt(r, 'best'))} | "
                     f"{count(bestBelowBalanced)} | {seconds:.2f}x |")
    listed = [("Below 0.8x of the earlier build", [r for r in good if r["equal_counts"] and below(r)]),
              ("Counts not equal", [r for r in good if not r["equal_counts"]]),
              ("Losses to meshoptimizer", [r for r in good if lostToMeshopt(r, "balanced") or lostToMeshopt(r, "best")]),
              ("Best below balanced", [r for r in good if bestBelowBalanced(r)])]
    for heading, members in listed:
        lines += ["", f"{heading} ({len(members)}):", ""]
        lines += [f"- {os.path.basename(r['mesh'])}: meshoptimizer {r['clusters_meshopt']} clusters "
                  f"{r['efficiency_meshopt']:.4f}, earlier {r['clusters_earlier']} {r['efficiency_earlier']:.4f}, "
                  f"default {r['clusters_balanced']} {r['efficiency_balanced']:.4f}, best {r['clusters_best']} "
                  f"{r['efficiency_best']:.4f}" for r in members]
    lines += ["", "Not read:", ""] + [f"- {os.path.basename(r['mesh'])}: {r['error']}" for r in rows if "error" in r]
    with open(prefix + ".md", "w") as out:
        out.write("\n".join(lines) + "\n")
    print("\n".join(lines[4:4 + 2 + len(SETS)]))


if __name__ == "__main__":
    main()
