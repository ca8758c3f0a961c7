"""The table of scripts/bench-chosen-cone.sh: `conescope-cli stats --cone chosen,minimal,meshopt
--test octagon` on every mesh of a list ("set path" per line) at 128 and at 64 views, distance 3,
the default partition. Per set and view count: the geometric mean, least and most of chosen's
back faces culled over minimal's (meshes where minimal culls some), and on how many chosen culls
at least as much as both minimal and meshopt. Writes OUT.csv (one row per mesh and view count)
and OUT.md."""
import csv
import math
import json
import subprocess
import sys

cli, list_path, out, root = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
CONES = ["chosen", "minimal", "meshopt"]
VIEWS = [128, 64]
rows, failed = [], []
for line in open(list_path):
    group, path = line.split(" ", 1)
    path = path.strip()
    name = path.replace(root + "/", "")
    for views in VIEWS:
        done = subprocess.run([cli, "stats", path, "--cone", ",".join(CONES), "--test", "octagon", "--views", str(views),
                               "--distance", "3", "--no-per-view", "--no-per-cluster", "--format", "json", "-q"],
                              capture_output=True, text=True)
        if done.returncode != 0:
            failed.append((group, name, (done.stderr.strip().splitlines() or ["?"])[-1]))
            break
        document = json.loads(done.stdout)
        culled = {result["cone"]: result["efficiency"] for result in document["results"]}
        rows.append({"set": group, "mesh": name, "views": views, "clusters": document["clusters"],
                     **{"efficiency_" + cone: culled[cone] for cone in CONES}})

with open(out + ".csv", "w", newline="") as handle:
    writer = csv.DictWriter(handle, fieldnames=list(rows[0].keys()))
    writer.writeheader()
    writer.writerows(rows)

lines = ["# The chosen cone against the minimal one", "",
         "`scripts/bench-chosen-cone.sh`: `conescope-cli stats --cone chosen,minimal,meshopt --test octagon` at distance 3, "
         "the default partition (limits 64/124). Ratio: chosen's back faces culled over minimal's, where minimal culls some. "
         "At least as much: chosen culls no less than both minimal and meshopt.", "",
         "| meshes | views | meshes that cull | geometric mean | least | most | at least as much as minimal and meshopt |",
         "|---|---:|---:|---:|---:|---:|---:|"]
for group, title in (("cgal", "CGAL demo meshes"), ("props", "tests/data/props")):
    for views in VIEWS:
        chosen = [row for row in rows if row["set"] == group and row["views"] == views and row["efficiency_minimal"] > 0]
        if not chosen:
            continue
        ratios = [row["efficiency_chosen"] / row["efficiency_minimal"] for row in chosen]
        mean = math.exp(sum(math.log(r) for r in ratios) / len(ratios)) if all(r > 0 for r in ratios) else 0.0
        level = sum(row["efficiency_chosen"] >= max(row["efficiency_minimal"], row["efficiency_meshopt"]) - 1e-15 for row in chosen)
        lines.append(f"| {title} | {views} | {len(chosen)} | {mean:.3f}x | {min(ratios):.3f}x | {max(ratios):.3f}x | {level} |")
lines += ["", f"Not read: {len(failed)}"] + [f"- {name}: {why}" for _, name, why in failed]
open(out + ".md", "w").write("\n".join(lines) + "\n")
