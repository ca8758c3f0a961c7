"""Table of scripts/bench-lod.sh: per mesh the efficiency of each LOD level and of the cut at 1 pixel,
and over the meshes how much of level 0's culling each level keeps (the mean of level l's efficiency
over level 0's, meshes where level 0 culls)."""
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
                     "levels_used", "build_seconds"])
    for r in measured:
        for level in r["levels"]:
            writer.writerow([r["mesh"], level["level"], level["clusters"], level["triangles"], f'{level["mean_half_angle_deg"]:.2f}',
                             f'{level["efficiency"]:.4f}', f'{level["expected_efficiency"]:.4f}', level["false_culls"], "", f'{r["build_seconds"]:.3f}'])
        cut = r["cut"]
        writer.writerow([r["mesh"], "cut", f'{cut["clusters"]:.1f}', f'{cut["triangles"]:.1f}', "", f'{cut["efficiency"]:.4f}', "",
                         cut["false_culls"], " ".join(str(l) for l in cut["levels_used"]), ""])


def kept(level):
    """Level `level`'s efficiency over level 0's, on the meshes with that level whose level 0 culls."""
    shares = [r["levels"][level]["efficiency"] / r["levels"][0]["efficiency"]
              for r in measured if len(r["levels"]) > level and r["levels"][0]["efficiency"] > 0]
    return (sum(shares) / len(shares), len(shares)) if shares else (math.nan, 0)


lines = [f"{len(measured)} meshes measured, {len(failed)} not read, in {seconds} s; 64 views at distance 3, the default "
         "builder, minimal cone and octagon test at every level; the cut at 1 pixel (1080 pixels high, 60 degrees).", ""]
lines.append("| level | meshes | efficiency kept of level 0's (mean) |")
lines.append("| --- | --- | --- |")
for level in range(1, 8):
    share, count = kept(level)
    if count:
        lines.append(f"| {level} | {count} | {share:.2f} |")
cut_shares = [r["cut"]["efficiency"] / r["levels"][0]["efficiency"] for r in measured if r["levels"][0]["efficiency"] > 0]
if cut_shares:
    lines.append(f"| the cut at 1 px | {len(cut_shares)} | {sum(cut_shares) / len(cut_shares):.2f} |")
false_culls = sum(r["cut"]["false_culls"] + sum(l["false_culls"] for l in r["levels"]) for r in measured)
lines += ["", f"False culls over every level and cut: {false_culls}.", ""]
header = "| mesh | triangles | levels | " + " | ".join(f"level {l}" for l in range(SHOWN)) + " | cut: triangles drawn | cut: levels | cut |"
lines.append(header)
lines.append("|" + " --- |" * (SHOWN + 6))
for r in sorted(measured, key=lambda r: r["levels"][0]["triangles"], reverse=True):
    levels = r["levels"]
    cells = [f'{levels[l]["efficiency"]:.3f}' if l < len(levels) else "" for l in range(SHOWN)]
    cut = r["cut"]
    lines.append(f'| {r["mesh"]} | {levels[0]["triangles"]} | {len(levels)} | ' + " | ".join(cells) +
                 f' | {cut["triangles"]:.0f} | {" ".join(str(l) for l in cut["levels_used"])} | {cut["efficiency"]:.3f} |')
if failed:
    lines += ["", "Not read: " + ", ".join(f'{r["mesh"]} ({r["error"]})' for r in failed)]
open(md_path, "w").write("\n".join(lines) + "\n")
