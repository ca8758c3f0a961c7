"""The table of scripts/bench-props.sh: `conescope-cli compare` of meshoptimizer's pipeline (A)
against the defaults (B) on every mesh of a list, two at a time; each mesh is put in the sets it
belongs to, and per set the wins, losses and counts are summed. Writes PREFIX.csv and PREFIX.md."""
import csv
import json
import math
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

ARGS = ["--a", "builder=meshopt,cone=meshopt,test=apex", "--views", "64", "--distance", "3",
        "--no-per-view", "--no-per-cluster", "--format", "json", "-q"]
SETS = ["all", "polygon", "many-part", "small prop", "double-sided"]


def compare(cli, mesh):
    run = subprocess.run([cli, "compare", mesh] + ARGS, capture_output=True, text=True, timeout=600)
    row = {"mesh": mesh}
    if run.returncode:
        row["error"] = (run.stderr.strip().splitlines() or ["failed"])[-1]
        return row
    result = json.loads(run.stdout)
    diff, info = result["diff"], result["b"]["mesh"]
    row.update({"faces": info["faces"], "triangles": info["triangles"], "components": info["report"]["components"],
                "double_sided_faces": info["report"]["double_sided_faces"], "clusters_meshopt": diff["clusters_a"],
                "clusters_default": diff["clusters_b"], "efficiency_meshopt": diff["efficiency_a"],
                "efficiency_default": diff["efficiency_b"]})
    return row


def setsOf(row):
    found = ["all"]
    if row["triangles"] > row["faces"]:
        found.append("polygon")
    if row["components"] >= 100:
        found.append("many-part")
    if row["clusters_meshopt"] <= 35:
        found.append("small prop")
    if row["double_sided_faces"] > 0:
        found.append("double-sided")
    return found


def outcome(row):
    a, b = row["efficiency_meshopt"], row["efficiency_default"]
    if row["clusters_default"] > row["clusters_meshopt"] or b < a - 1e-12:
        return "loss"
    return "win" if b > a + 1e-12 else "tie"


def main():
    cli, listing, prefix = sys.argv[1:4]
    meshes = [line.strip() for line in open(listing) if line.strip()]
    with ThreadPoolExecutor(2) as pool:
        rows = list(pool.map(lambda mesh: compare(cli, mesh), meshes))
    good = [r for r in rows if "error" not in r]
    for r in good:
        r["sets"] = "; ".join(setsOf(r))
        r["outcome"] = outcome(r)
    fields = ["mesh", "sets", "outcome", "faces", "triangles", "components", "double_sided_faces", "clusters_meshopt",
              "clusters_default", "efficiency_meshopt", "efficiency_default", "error"]
    with open(prefix + ".csv", "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=fields, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    lines = ["# The defaults against meshoptimizer's pipeline on props and double-sided meshes", "",
             f"{len(rows)} meshes, {len(rows) - len(good)} that do not read; 64 views, distance 3, limits 64/124. "
             "A loss: less culled, or more clusters. Ratio: default / meshoptimizer efficiency where both cull.", "",
             "| set | meshes | wins | ties | losses | more clusters | culls none where meshoptimizer culls | geometric mean ratio |",
             "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for name in SETS:
        members = [r for r in good if name in setsOf(r)]
        ratios = [r["efficiency_default"] / r["efficiency_meshopt"] for r in members
                  if r["efficiency_meshopt"] > 0 and r["efficiency_default"] > 0]
        mean = math.exp(sum(map(math.log, ratios)) / len(ratios)) if ratios else float("nan")
        count = lambda test: sum(1 for r in members if test(r))
        lines.append(f"| {name} | {len(members)} | {count(lambda r: r['outcome'] == 'win')} | "
                     f"{count(lambda r: r['outcome'] == 'tie')} | {count(lambda r: r['outcome'] == 'loss')} | "
                     f"{count(lambda r: r['clusters_default'] > r['clusters_meshopt'])} | "
                     f"{count(lambda r: r['efficiency_default'] == 0 < r['efficiency_meshopt'])} | {mean:.3f} |")
    losses = [r for r in good if r["outcome"] == "loss"]
    lines += ["", f"Losses ({len(losses)}):", ""]
    lines += [f"- {os.path.basename(r['mesh'])}: {r['clusters_default']} clusters against {r['clusters_meshopt']}, "
              f"efficiency {r['efficiency_default']:.4f} against {r['efficiency_meshopt']:.4f}" for r in losses]
    lines += [f"- {os.path.basename(r['mesh'])}: {r['error']}" for r in rows if "error" in r]
    with open(prefix + ".md", "w") as out:
        out.write("\n".join(lines) + "\n")
    print("\n".join(lines[4:4 + 2 + len(SETS)]))


if __name__ == "__main__":
    main()
