"""Runs `conescope-cli granularity` on every mesh of a list ("set path" per line) and writes
OUT.csv (one row per mesh and record) and OUT.md: per set and record the mean culled share of all
triangles, the geometric mean ratio of back faces culled to the default record's (meshes where the
default culls some), mean bytes per cluster, bits per triangle over all the set's triangles, tests per view per cluster, and
the false culls of the conservative records."""
import csv
import json
import math
import subprocess
import sys
from collections import defaultdict

cli, list_path, out, root = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
DEFAULT = "chosen/octagon"
ENGINE = {"meshopt-apex-f32", "meshopt-sphere-s8", "cadscene-box-s8"}
runs, failed = [], []
for line in open(list_path):
    group, path = line.split(" ", 1)
    path = path.strip()
    name = path.replace(root + "/datasets/", "")
    done = subprocess.run([cli, "granularity", path, "--views", "64", "--distance", "3", "--format", "json", "-q"],
                          capture_output=True, text=True)
    if done.returncode != 0:
        failed.append((group, name, [line.replace(root + "/", "") for line in done.stderr.strip().splitlines()[-1:]] or ["?"]))
        continue
    report = json.loads(done.stdout)
    runs.append((group, name, report))

with open(out + ".csv", "w", newline="") as handle:
    writer = csv.writer(handle)
    keys = ["record", "bytes_per_cluster", "bits_per_triangle", "efficiency", "culled_share", "tests_per_view", "false_culls",
            "triangles_culled", "back_facing_triangles"]
    writer.writerow(["set", "mesh", "clusters", "triangles"] + keys)
    for group, name, report in runs:
        for row in report["rows"]:
            writer.writerow([group, name, report["clusters"], report["triangles"]] + [row[k] for k in keys])


def summary(group):
    chosen = [r for g, _, r in runs if g == group]
    records = [row["record"] for row in chosen[0]["rows"]] if chosen else []
    lines = [f"| record | mean culled share | × default (geometric mean, {sum(1 for r in chosen if r['rows'][0]['triangles_culled'] > 0)} meshes) "
             "| bytes / cluster (mean) | bits / triangle (all meshes) | tests / view / cluster | false culls |",
             "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for record in records:
        shares, ratios, sizes, tests, false_culls, record_bits, triangles = [], [], [], [], 0, 0.0, 0
        for report in chosen:
            rows = {row["record"]: row for row in report["rows"]}
            row, base = rows[record], rows[DEFAULT]
            shares.append(row["culled_share"])
            sizes.append(row["bytes_per_cluster"])
            record_bits += row["bytes_per_cluster"] * 8.0 * report["clusters"]
            triangles += report["triangles"]
            tests.append(row["tests_per_view"] / max(report["clusters"], 1))
            false_culls += row["false_culls"]
            if base["triangles_culled"] > 0:
                ratios.append(max(row["triangles_culled"], 1) / base["triangles_culled"])
        mean = lambda values: sum(values) / len(values) if values else math.nan
        geometric = math.exp(mean([math.log(r) for r in ratios])) if ratios else math.nan
        name = record + (" (engine record as shipped)" if record in ENGINE else "")
        lines.append(f"| {name} | {mean(shares):.3f} | {geometric:.2f} | {mean(sizes):.0f} | {record_bits / max(triangles, 1):.2f} | {mean(tests):.2f} | {false_culls} |")
    return len(chosen), lines


text = ["64 orbit views at distance 3, the default partition (limits 64/124) of each mesh; one cone per cluster: "
        "each test with the default (chosen) cone; K cones: the cluster's faces in K sub-groups, a minimal cone and an apex on its axis "
        "each, the apex test per sub-group; triangle: every back face culled after the default cluster test. "
        "Culled share: of all triangles, per view. × default: back faces culled over the default record's (chosen/octagon).", ""]
for group, title in (("cgal", "CGAL demo meshes"), ("props", "Sweet Home 3D furniture")):
    count, lines = summary(group)
    text += [f"### {title} ({count} meshes)", ""] + lines + [""]
if failed:
    text += ["Not read: " + ", ".join(f"{name} ({message[0]})" for _, name, message in failed), ""]
open(out + ".md", "w").write("\n".join(text))
