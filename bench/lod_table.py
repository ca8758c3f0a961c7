"""Table of scripts/bench-lod.sh: per mesh the efficiency of each LOD level and of the cut at 1 pixel,
and over the meshes how much of level 0's culling each level keeps (the mean of level l's efficiency
over level 0's, meshes where level 0 culls), with one cone per cluster and with four (`lod --cones 4`,
granularity's cones-4 record)."""
import csv
import json
import math
import sys

rows_path, csv_path, md_path, seconds = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
rows = [json.loads(line) for line in open(rows_path) if line.strip()]
measured = [r for r in rows if "error" not in r]
failed = [r for r in rows if "error" in r]
SHOWN = 5  # levels in the table's columns

with open(csv_path, "w", newline="") as out:
    writer = csv.writer(out)
    writer.writerow(["mesh", "level", "clusters", "triangles", "mean_half_angle_deg", "efficiency", "expected_efficiency", "false_culls",
                     "efficiency_4_cones", "false_culls_4_cones", "levels_used", "build_seconds"])
    for r in measured:
        for level in r["levels"]:
            writer.writerow([r["mesh"], level["level"], level["clusters"], level["triangles"], f'{level["mean_half_angle_deg"]:.2f}',
                             f'{level["efficiency"]:.4f}', f'{level["expected_efficiency"]:.4f}', level["false_culls"],
                             f'{level["multi_cone"]["efficiency"]:.4f}', level["multi_cone"]["false_culls"], "", f'{r["build_seconds"]:.3f}'])
        cut = r["cut"]
        writer.writerow([r["mesh"], "cut", f'{cut["clusters"]:.1f}', f'{cut["triangles"]:.1f}', "", f'{cut["efficiency"]:.4f}', "",
                         cut["false_culls"], f'{cut["multi_cone"]["efficiency"]:.4f}', cut["multi_cone"]["false_culls"],
                         " ".join(str(l) for l in cut["levels_used"]), ""])


def mean(values):
    return sum(values) / len(values) if values else math.nan


def row(name, rows_of):
    """One line of the summary: over the meshes where rows_of(r) exists and level 0 culls with one cone,
    the mean efficiency with one cone and with four, and each over level 0's with the same record."""
    meshes = [r for r in measured if rows_of(r) is not None and r["levels"][0]["efficiency"] > 0]
    if not meshes:
        return None
    one = [rows_of(r)["efficiency"] for r in meshes]
    four = [rows_of(r)["multi_cone"]["efficiency"] for r in meshes]
    kept_one = [rows_of(r)["efficiency"] / r["levels"][0]["efficiency"] for r in meshes]
    kept_four = [rows_of(r)["multi_cone"]["efficiency"] / r["levels"][0]["multi_cone"]["efficiency"] for r in meshes
                 if r["levels"][0]["multi_cone"]["efficiency"] > 0]
    return (f"| {name} | {len(meshes)} | {mean(one):.3f} | {mean(kept_one):.2f} | {mean(four):.3f} | {mean(kept_four):.2f} | "
            f"{mean(four) / mean(one) if mean(one) > 0 else math.inf:.2f} |")


lines = [f"{len(measured)} meshes measured, {len(failed)} not read, in {seconds} s; 64 views at distance 3, the default "
         "builder, chosen cone and octagon test at every level, and four cones per cluster (granularity's cones-4 record); "
         "the cut at 1 pixel (1080 pixels high, 60 degrees). Means over the meshes where level 0 culls with one cone.", ""]
lines.append("| level | meshes | 1 cone: efficiency | 1 cone: kept of level 0's | 4 cones: efficiency | 4 cones: kept of level 0's | "
             "4 cones / 1 cone |")
lines.append("| --- | --- | --- | --- | --- | --- | --- |")
for level in range(0, 8):
    line = row(str(level), lambda r, level=level: r["levels"][level] if len(r["levels"]) > level else None)
    if line:
        lines.append(line)
line = row("the cut at 1 px", lambda r: r["cut"])
if line:
    lines.append(line)
false_culls = sum(r["cut"]["false_culls"] + sum(l["false_culls"] for l in r["levels"]) for r in measured)
false_culls_four = sum(r["cut"]["multi_cone"]["false_culls"] + sum(l["multi_cone"]["false_culls"] for l in r["levels"]) for r in measured)
lines += ["", f"False culls over every level and cut: {false_culls} with one cone, {false_culls_four} with four.", ""]
header = ("| mesh | triangles | levels | " + " | ".join(f"level {l}" for l in range(SHOWN)) +
          " | cut: triangles drawn | cut: levels | cut | level 0, 4 cones | level 2, 4 cones | cut, 4 cones |")
lines.append(header)
lines.append("|" + " --- |" * (SHOWN + 9))
for r in sorted(measured, key=lambda r: r["levels"][0]["triangles"], reverse=True):
    levels = r["levels"]
    cells = [f'{levels[l]["efficiency"]:.3f}' if l < len(levels) else "" for l in range(SHOWN)]
    cut = r["cut"]
    level_two = f'{levels[2]["multi_cone"]["efficiency"]:.3f}' if len(levels) > 2 else ""
    lines.append(f'| {r["mesh"]} | {levels[0]["triangles"]} | {len(levels)} | ' + " | ".join(cells) +
                 f' | {cut["triangles"]:.0f} | {" ".join(str(l) for l in cut["levels_used"])} | {cut["efficiency"]:.3f} | '
                 f'{levels[0]["multi_cone"]["efficiency"]:.3f} | {level_two} | {cut["multi_cone"]["efficiency"]:.3f} |')
if failed:
    lines += ["", "Not read: " + ", ".join(f'{r["mesh"]} ({r["error"]})' for r in failed)]
open(md_path, "w").write("\n".join(lines) + "\n")
