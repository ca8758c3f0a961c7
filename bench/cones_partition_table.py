"""Whether a partition built for K cones (`--cones-per-cluster K`: the optimized builder's faces moved while the
K sub-groups' expected culling rises) beats the default partition split into K sub-groups afterwards.
Runs `conescope-cli granularity` on every mesh of a list ("set path" per line) with the default
partition and with the partition built for 2 and for 4 cones, and writes OUT.csv (one row per mesh
and K) and OUT.md (per set and K: clusters equal, back faces culled by the cones-K record on each
partition, their geometric mean ratio, meshes better and worse, and false culls)."""
import csv
import json
import math
import subprocess
import sys
import time

cli, list_path, out, root = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
CONES = (2, 4)


def granularity(path, cones):
    start = time.monotonic()
    done = subprocess.run([cli, "granularity", path, "--views", "64", "--distance", "3", "--test", "octagon", "--cones-per-cluster", str(cones),
                           "--format", "json", "-q"], capture_output=True, text=True)
    if done.returncode != 0:
        return None, 0.0
    return json.loads(done.stdout), time.monotonic() - start


rows, failed = [], []
for line in open(list_path):
    group, path = line.split(" ", 1)
    path = path.strip()
    name = path.replace(root + "/datasets/", "")
    split_after, split_seconds = granularity(path, 1)
    if split_after is None:
        failed.append(name)
        continue
    for k in CONES:
        built_for, seconds = granularity(path, k)
        if built_for is None:
            failed.append(f"{name} (--cones {k})")
            continue
        record = f"cones-{k}"
        a = {row["record"]: row for row in split_after["rows"]}[record]
        b = {row["record"]: row for row in built_for["rows"]}[record]
        rows.append({"set": group, "mesh": name, "cones": k, "clusters": split_after["clusters"], "clusters_built_for_k": built_for["clusters"],
                     "split_after_culled": a["triangles_culled"], "built_for_k_culled": b["triangles_culled"],
                     "back_facing": a["back_facing_triangles"], "split_after_efficiency": a["efficiency"], "built_for_k_efficiency": b["efficiency"],
                     "false_culls": a["false_culls"] + b["false_culls"], "seconds_split_after": round(split_seconds, 3),
                     "seconds_built_for_k": round(seconds, 3)})

with open(out + ".csv", "w", newline="") as handle:
    writer = csv.DictWriter(handle, fieldnames=list(rows[0].keys()) if rows else ["set"])
    writer.writeheader()
    writer.writerows(rows)

text = ["64 orbit views at distance 3, limits 64/124. Split afterwards: the default partition, each cluster's faces split "
        "into K sub-groups; built for K: `--cones-per-cluster K`, the default partition with faces moved across cluster borders while the "
        "K sub-groups' expected culled share rises, then split the same way. Both have the same clusters (count); the cones-K "
        "record (float) culls the back faces below. Seconds: the whole `granularity` run, one core busy.", "",
        "| set | K | meshes | equal counts | × split afterwards (geometric mean) | better | worse | mean efficiency split afterwards | built for K | false culls | seconds (split afterwards → built for K) |",
        "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
for group, title in (("cgal", "CGAL"), ("props", "furniture")):
    for k in CONES:
        chosen = [r for r in rows if r["set"] == group and r["cones"] == k]
        if not chosen:
            continue
        culling = [r for r in chosen if r["split_after_culled"] > 0]
        ratio = math.exp(sum(math.log(max(r["built_for_k_culled"], 1) / r["split_after_culled"]) for r in culling) / len(culling)) if culling else math.nan
        mean = lambda key: sum(r[key] for r in chosen) / len(chosen)
        text.append(f"| {title} | {k} | {len(chosen)} | {sum(r['clusters'] == r['clusters_built_for_k'] for r in chosen)} | {ratio:.3f} "
                    f"| {sum(r['built_for_k_culled'] > r['split_after_culled'] for r in chosen)} | {sum(r['built_for_k_culled'] < r['split_after_culled'] for r in chosen)} "
                    f"| {mean('split_after_efficiency'):.3f} | {mean('built_for_k_efficiency'):.3f} | {sum(r['false_culls'] for r in chosen)} "
                    f"| {mean('seconds_split_after'):.2f} → {mean('seconds_built_for_k'):.2f} |")
text.append("")
if failed:
    text += ["Not read: " + ", ".join(failed), ""]
open(out + ".md", "w").write("\n".join(text))
