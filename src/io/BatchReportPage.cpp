// The page of report.html: markup, style and the script that draws the totals, the plots (SVG) and the
// tables from the rows the writer puts where @DATA@ is. Nothing is loaded from anywhere else.
#include "io/BatchReport.h"

namespace conescope {

namespace {

const char* const pageHead = R"HTML(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>ConeScope batch report</title>
<style>
body { font: 14px/1.4 system-ui, sans-serif; margin: 24px; color: #222; background: #fff; }
h1 { font-size: 22px; margin: 0 0 4px; }
h2 { font-size: 17px; margin: 28px 0 8px; }
.muted { color: #666; }
#totals { display: flex; flex-wrap: wrap; gap: 10px; margin-top: 14px; }
.total { border: 1px solid #ddd; border-radius: 6px; padding: 8px 12px; min-width: 120px; }
.total b { display: block; font-size: 19px; }
#plots { display: flex; flex-wrap: wrap; gap: 18px; }
figure { margin: 0; border: 1px solid #ddd; border-radius: 6px; padding: 8px; }
figcaption { font-weight: 600; margin-bottom: 4px; max-width: 480px; }
svg text { font: 11px system-ui, sans-serif; fill: #444; }
svg .axis { stroke: #888; }
svg .grid { stroke: #eee; }
svg .point { fill: #2f6fb0; fill-opacity: 0.7; stroke: #fff; stroke-width: 0.5; }
svg .point:hover { fill: #d9480f; }
svg .diagonal { stroke: #aaa; stroke-dasharray: 4 3; }
.culled { fill: #2f9e44; } .test-loss { fill: #f08c00; } .partition-loss { fill: #c92a2a; }
.legend span { display: inline-block; width: 10px; height: 10px; margin: 0 4px 0 10px; }
table { border-collapse: collapse; font-size: 13px; }
th, td { padding: 3px 8px; border-bottom: 1px solid #eee; text-align: right; white-space: nowrap; }
th { position: sticky; top: 0; background: #f6f6f6; cursor: pointer; user-select: none; }
th.sorted-up::after { content: " \25B2"; } th.sorted-down::after { content: " \25BC"; }
td.text, th.text { text-align: left; }
td.message { white-space: normal; text-align: left; max-width: 700px; }
td.wrap { white-space: normal; word-break: break-all; max-width: 360px; }
#errors, #table { overflow-x: auto; }
tr.selected td { background: #fff3bf; }
</style>
</head>
<body>
<h1 id="title">ConeScope batch report</h1>
<div id="subtitle" class="muted"></div>
<noscript><p>This page draws its plots and tables with a script; results.csv holds the same rows.</p></noscript>
<div id="totals"></div>
<p id="uncullable-note" class="muted"></p>
<h2>Plots</h2>
<div id="plots"></div>
<h2 id="errors-title">Errors</h2>
<div id="errors"></div>
<h2>Meshes <span class="muted" id="table-note"></span></h2>
<div id="table"></div>
<script type="application/json" id="batch-data">)HTML";

const char* const pageScript = R"HTML(</script>
<script>
"use strict";
const data = JSON.parse(document.getElementById("batch-data").textContent);
const NS = "http://www.w3.org/2000/svg";
const numeric = new Set(["triangles", "clusters", "efficiency", "back_facing_triangles", "triangles_culled",
  "test_loss_triangles", "partition_loss_triangles", "false_culls", "cull_fraction", "oracle_fraction",
  "mean_sphere_radius", "seconds", "a_clusters", "a_efficiency", "triangles_culled_only_a", "triangles_culled_only_b",
  "uncullable_clusters", "uncullable_share", "bytes_per_cluster", "culled_share"]);
// The finer records of `batch --granularity`, as their columns' prefixes.
const granularityRecords = ["cones_2", "cones_2_compact", "cones_4", "cones_4_compact", "cones_8", "cones_8_compact", "triangle"];
for (const record of granularityRecords)
  for (const key of ["efficiency", "culled_share", "bytes_per_cluster", "tests_per_view"]) numeric.add(`${record}_${key}`);
// batch --lod's columns: every one a number.
for (const column of data.columns) if (column.startsWith("lod_")) numeric.add(column);
const rows = data.rows.map((cells) => {
  const row = {};
  data.columns.forEach((column, k) => { row[column] = numeric.has(column) && cells[k] !== "" ? Number(cells[k]) : cells[k]; });
  row.name = row.file.split("/").pop();
  return row;
});
const ok = rows.filter((row) => row.status === "ok");
const failed = rows.filter((row) => row.status !== "ok");
const compared = ok.some((row) => row.a_efficiency !== "");
const MAX_POINTS = 5000, MAX_TABLE_ROWS = 1000;

function element(tag, attributes, text) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes || {})) node.setAttribute(key, value);
  if (text !== undefined) node.textContent = text;
  return node;
}
function svgElement(tag, attributes, text) {
  const node = document.createElementNS(NS, tag);
  for (const [key, value] of Object.entries(attributes || {})) node.setAttribute(key, value);
  if (text !== undefined) node.textContent = text;
  return node;
}
const percent = (value) => (value === "" || !isFinite(value) ? "" : (100 * value).toFixed(1) + "%");
const count = (value) => (value === "" ? "" : Number(value).toLocaleString("en-US"));
const href = (path) => path.split("/").map(encodeURIComponent).join("/");
const sum = (list, key) => list.reduce((total, row) => total + (Number(row[key]) || 0), 0);
// Evenly spaced rows when there are more than a plot can draw.
const sample = (list, most) => (list.length <= most ? list : list.filter((_, k) => k % Math.ceil(list.length / most) === 0));

function drawHeader() {
  document.title = "ConeScope batch: " + data.title;
  document.getElementById("title").textContent = "ConeScope batch: " + data.title;
  const settings = Object.entries(data.settings).filter(([, value]) => value !== "").map(([key, value]) => key + "=" + value);
  let text = settings.join(", ");
  if (data.compare) text += " | compared with A: " + data.compare;
  document.getElementById("subtitle").textContent = text;
}

function drawTotals() {
  const back = sum(ok, "back_facing_triangles");
  // Nothing facing away culls everything (efficiency 1), as the statistics count it; no mesh, nothing.
  const share = (key) => (back > 0 ? sum(ok, key) / back : ok.length > 0 && key === "triangles_culled" ? 1 : ok.length > 0 ? 0 : NaN);
  const totals = [
    ["meshes", count(rows.length) + (data.meshes > rows.length ? " of " + count(data.meshes) : "")],
    ["ok", count(ok.length)], ["errors", count(failed.length)], ["triangles", count(sum(ok, "triangles"))],
    ["clusters", count(sum(ok, "clusters"))], ["efficiency (all back faces)", percent(share("triangles_culled"))],
    ["lost to the test", percent(share("test_loss_triangles"))],
    ["lost to the partition", percent(share("partition_loss_triangles"))],
    ["false culls", count(sum(ok, "false_culls"))],
    ["meshes most of whose clusters can never be culled", count(ok.filter((row) => row.note !== "").length)]];
  if (compared) {
    const culledA = sum(ok, "triangles_culled_only_a") + sum(ok, "triangles_culled") - sum(ok, "triangles_culled_only_b");
    totals.push(["A's efficiency", percent(back > 0 ? culledA / back : 1)]);
    totals.push(["meshes where A culls more", count(ok.filter((row) => row.a_efficiency > row.efficiency).length)]);
  }
  // Why many meshes cull little or nothing: say it once, above the plots.
  const mostly = ok.filter((row) => row.note !== "");
  document.getElementById("uncullable-note").textContent = mostly.length === 0 ? "" :
    `${count(mostly.length)} of ${count(ok.length)} meshes cull little or nothing because most of their clusters can never be culled: ` +
    "each such cluster holds face normals over more than a hemisphere, so no cone narrower than a hemisphere holds them and no test " +
    "culls it from any eye (the column \u201cuncullable clusters\u201d and each mesh's note say how many).";
  const box = document.getElementById("totals");
  for (const [label, value] of totals) {
    const total = element("div", {class: "total", "data-total": label});
    total.append(element("b", {}, value), element("span", {class: "muted"}, label));
    box.append(total);
  }
}

// A scatter plot of rows: x and y read by the functions given, x on a log scale when asked.
function scatter(id, caption, points, x, y, options) {
  const width = 480, height = 320, left = 66, right = 34, top = 12, bottom = 40;
  const figure = element("figure", {id: id});
  figure.append(element("figcaption", {}, caption));
  const svg = svgElement("svg", {width: width, height: height, viewBox: `0 0 ${width} ${height}`});
  const xs = points.map(x), xMin = options.log ? Math.min(...xs) : 0, xMax = options.log ? Math.max(...xs) : 1;
  const toX = options.log
    ? (v) => left + (xMax > xMin ? (Math.log10(v) - Math.log10(xMin)) / (Math.log10(xMax) - Math.log10(xMin)) : 0.5) * (width - left - right)
    : (v) => left + v * (width - left - right);
  const toY = (v) => height - bottom - v * (height - top - bottom);
  for (let k = 0; k <= 4; ++k) {
    const v = k / 4;
    svg.append(svgElement("line", {class: "grid", x1: left, x2: width - right, y1: toY(v), y2: toY(v)}));
    svg.append(svgElement("text", {x: left - 6, y: toY(v) + 4, "text-anchor": "end"}, percent(v)));
    const xv = options.log ? Math.pow(10, Math.log10(xMin) + v * (Math.log10(xMax) - Math.log10(xMin))) : v;
    svg.append(svgElement("text", {x: toX(xv), y: height - bottom + 16, "text-anchor": "middle"}, options.log ? count(Math.round(xv)) : percent(xv)));
  }
  svg.append(svgElement("line", {class: "axis", x1: left, x2: left, y1: top, y2: height - bottom}));
  svg.append(svgElement("line", {class: "axis", x1: left, x2: width - right, y1: height - bottom, y2: height - bottom}));
  if (options.diagonal) svg.append(svgElement("line", {class: "diagonal", x1: toX(0), y1: toY(0), x2: toX(1), y2: toY(1)}));
  svg.append(svgElement("text", {x: (left + width - right) / 2, y: height - 6, "text-anchor": "middle"}, options.xLabel));
  svg.append(svgElement("text", {x: 12, y: (top + height - bottom) / 2, "text-anchor": "middle",
    transform: `rotate(-90 12 ${(top + height - bottom) / 2})`}, options.yLabel));
  for (const row of sample(points, MAX_POINTS)) {
    const point = svgElement("circle", {class: "point", r: 4, cx: toX(x(row)), cy: toY(y(row)), "data-file": row.file});
    point.append(svgElement("title", {}, `${row.file}\n${options.xLabel}: ${options.log ? count(x(row)) : percent(x(row))}\n${options.yLabel}: ${percent(y(row))}`));
    point.addEventListener("click", () => select(row));
    svg.append(point);
    // A label near the right edge goes to the left of its point, so the plot never clips it.
    const leftOfPoint = toX(x(row)) > width - right - 90;
    if (options.labels) svg.append(svgElement("text", {x: toX(x(row)) + (leftOfPoint ? -7 : 7), y: toY(y(row)) + 4,
      "text-anchor": leftOfPoint ? "end" : "start"}, row.name));
  }
  figure.append(svg);
  if (points.length > MAX_POINTS) figure.append(element("div", {class: "muted"}, `${count(MAX_POINTS)} of ${count(points.length)} meshes drawn`));
  return figure;
}

// Where the back faces went: culled, lost to the test, lost to the partition; the whole library first,
// then the meshes that lose the most back faces.
function lossBars(rowsShown) {
  const width = 480, barHeight = 14, left = 150, right = 34, top = 8;
  const figure = element("figure", {id: "plot-losses"});
  figure.append(element("figcaption", {}, `Where the back faces went (all meshes, then the ${rowsShown.length} that lose the most)`));
  const legend = element("div", {class: "legend muted"});
  legend.innerHTML = '<span style="background:#2f9e44"></span>culled' +
    '<span style="background:#f08c00"></span>lost to the test<span style="background:#c92a2a"></span>lost to the partition';
  figure.append(legend);
  const library = {name: "all meshes", file: "all meshes", back_facing_triangles: sum(ok, "back_facing_triangles"),
    triangles_culled: sum(ok, "triangles_culled"), test_loss_triangles: sum(ok, "test_loss_triangles"),
    partition_loss_triangles: sum(ok, "partition_loss_triangles")};
  const bars = [library, ...rowsShown];
  const height = top + bars.length * (barHeight + 4) + 14;
  const svg = svgElement("svg", {width: width, height: height, viewBox: `0 0 ${width} ${height}`});
  bars.forEach((row, k) => {
    const y = top + k * (barHeight + 4) + (k > 0 ? 6 : 0);
    svg.append(svgElement("text", {x: left - 6, y: y + barHeight - 3, "text-anchor": "end", "font-weight": k === 0 ? "bold" : "normal"},
      row.name.slice(0, 24)));
    let x = left;
    for (const [key, css] of [["triangles_culled", "culled"], ["test_loss_triangles", "test-loss"], ["partition_loss_triangles", "partition-loss"]]) {
      const share = row.back_facing_triangles > 0 ? row[key] / row.back_facing_triangles : 0;
      const bar = svgElement("rect", {class: "bar " + css + (k === 0 ? " library" : ""), x: x, y: y, height: barHeight,
        width: share * (width - left - right)});
      bar.append(svgElement("title", {}, `${row.file}: ${css.replace("-", " ")} ${percent(share)} (${count(row[key])} triangles)`));
      svg.append(bar);
      x += share * (width - left - right);
    }
  });
  figure.append(svg);
  return figure;
}

// With --granularity: the library's culled share of all triangles against bytes per cluster, one
// point per record: the batch's own (one cone), 2, 4 and 8 cones per cluster (float and compact) and
// per-triangle culling after the cluster test.
function granularityPlot() {
  const measured = ok.filter((row) => row.cones_4_culled_share !== "" && row.cones_4_culled_share !== undefined);
  if (measured.length === 0) return null;
  const triangles = sum(measured, "triangles");
  const share = (key) => triangles > 0 ? measured.reduce((total, row) => total + row[key] * row.triangles, 0) / triangles : 0;
  const bytes = (key) => sum(measured, key) / measured.length;
  const points = [{file: "one cone (the batch's test)", name: "1 cone", bytes: bytes("bytes_per_cluster"), share: share("culled_share")}];
  for (const record of granularityRecords)
    points.push({file: record, name: record.replace("cones_", "").replace("_compact", " compact").replace("triangle", "per triangle"),
      bytes: bytes(`${record}_bytes_per_cluster`), share: share(`${record}_culled_share`)});
  return scatter("plot-granularity", `Culled share of all triangles against bytes per cluster (${count(measured.length)} meshes): 1, 2, 4 and 8 cones per cluster, per triangle`,
    points, (point) => point.bytes, (point) => point.share, {log: true, labels: true, xLabel: "bytes per cluster", yLabel: "culled share"});
}

// With --lod: each level's efficiency and the cut's, averaged over the meshes that have the level
// (each mesh weighs the same), as bars: how much cone culling each level of the hierarchy keeps.
function lodBars() {
  const measured = ok.filter((row) => row.lod_levels !== "" && row.lod_levels !== undefined && row.lod_levels > 0);
  if (measured.length === 0) return null;
  const bars = [];
  for (let level = 0; data.columns.includes(`lod_level_${level}_efficiency`); ++level) {
    const having = measured.filter((row) => row[`lod_level_${level}_efficiency`] !== "");
    if (having.length === 0) break;
    bars.push({label: `level ${level} (${count(having.length)})`, value: sum(having, `lod_level_${level}_efficiency`) / having.length});
  }
  bars.push({label: "the cut at 1 px", value: sum(measured, "lod_cut_efficiency") / measured.length});
  const width = 480, barHeight = 14, left = 150, right = 60, top = 8;
  const figure = element("figure", {id: "plot-lod"});
  figure.append(element("figcaption", {}, `Efficiency by LOD level (mean over ${count(measured.length)} meshes; meshes with the level in brackets)`));
  const height = top + bars.length * (barHeight + 4) + 14;
  const svg = svgElement("svg", {width: width, height: height, viewBox: `0 0 ${width} ${height}`});
  bars.forEach((bar, k) => {
    const y = top + k * (barHeight + 4);
    svg.append(svgElement("text", {x: left - 6, y: y + barHeight - 3, "text-anchor": "end"}, bar.label));
    const rect = svgElement("rect", {class: "bar culled", x: left, y: y, height: barHeight, width: bar.value * (width - left - right)});
    rect.append(svgElement("title", {}, `${bar.label}: ${percent(bar.value)}`));
    svg.append(rect);
    svg.append(svgElement("text", {x: left + bar.value * (width - left - right) + 4, y: y + barHeight - 3}, percent(bar.value)));
  });
  figure.append(svg);
  return figure;
}

function drawPlots() {
  const plots = document.getElementById("plots");
  if (ok.length === 0) { plots.append(element("p", {class: "muted"}, "No mesh ran.")); return; }
  plots.append(scatter("plot-triangles", "Efficiency against triangles", ok.filter((row) => row.triangles > 0),
    (row) => row.triangles, (row) => row.efficiency, {log: true, xLabel: "triangles", yLabel: "efficiency"}));
  if (compared)
    plots.append(scatter("plot-compare", "Efficiency against A (" + data.compare + ")", ok.filter((row) => row.a_efficiency !== ""),
      (row) => row.a_efficiency, (row) => row.efficiency, {diagonal: true, xLabel: "A's efficiency", yLabel: "efficiency"}));
  else
    plots.append(element("p", {class: "muted", id: "plot-compare-missing"}, "Run the batch with --compare-meshopt to plot against meshoptimizer's pipeline."));
  const granularity = granularityPlot();
  if (granularity) plots.append(granularity);
  const lod = lodBars();
  if (lod) plots.append(lod);
  const lost = (row) => row.test_loss_triangles + row.partition_loss_triangles;
  plots.append(lossBars(ok.slice().sort((a, b) => lost(b) - lost(a)).slice(0, 30)));
}

function drawErrors() {
  const box = document.getElementById("errors");
  document.getElementById("errors-title").textContent = `Errors (${failed.length})`;
  if (failed.length === 0) { box.append(element("p", {class: "muted"}, "None.")); return; }
  const table = element("table", {id: "error-table"});
  table.append(headerRow([["file", "text"], ["kind", "text"], ["message", "text"]]));
  for (const row of failed) {
    const line = element("tr", {class: "error-row"});
    line.append(element("td", {class: "text wrap"}, row.file), element("td", {class: "text"}, row.error_kind), element("td", {class: "message"}, row.error));
    table.append(line);
  }
  box.append(table);
}

function headerRow(columns) {
  const line = element("tr");
  for (const [label, css] of columns) line.append(element("th", {class: css || ""}, label));
  return line;
}

// The meshes' table: every column sorts on a click, the least efficient first to start with.
const tableColumns = [
  ["file", "file", "text"], ["triangles", "triangles", ""], ["clusters", "clusters", ""], ["efficiency", "efficiency", "percent"],
  ...(compared ? [["A's efficiency", "a_efficiency", "percent"], ["A's clusters", "a_clusters", ""]] : []),
  ["test loss", "test_loss_share", "percent"], ["partition loss", "partition_loss_share", "percent"],
  ["cull fraction", "cull_fraction", "percent"], ["oracle fraction", "oracle_fraction", "percent"],
  ["uncullable clusters", "uncullable_share", "percent"],
  ["false culls", "false_culls", ""], ["seconds", "seconds", "seconds"], ["warnings", "warnings", "text"], ["note", "note", "text"]];
for (const row of ok) {
  row.test_loss_share = row.back_facing_triangles > 0 ? row.test_loss_triangles / row.back_facing_triangles : 0;
  row.partition_loss_share = row.back_facing_triangles > 0 ? row.partition_loss_triangles / row.back_facing_triangles : 0;
}
let sortKey = "efficiency", sortUp = true;

function cell(row, key, kind) {
  if (key === "file") {
    const td = element("td", {class: "text"});
    td.append(element("a", {href: href(row.json)}, row.file));
    if (row.compare_json) td.append(" ", element("a", {href: href(row.compare_json), class: "muted"}, "(compare)"));
    return td;
  }
  const value = row[key];
  const text = kind === "percent" ? percent(value) : kind === "seconds" ? (value === "" ? "" : value.toFixed(2)) : kind === "text" ? value : count(value);
  return element("td", {class: kind === "text" ? "text" : ""}, text);
}

function drawTable() {
  const sorted = ok.slice().sort((a, b) => {
    const x = a[sortKey], y = b[sortKey];
    const order = typeof x === "string" ? String(x).localeCompare(String(y)) : x - y;
    return sortUp ? order : -order;
  });
  const table = element("table", {id: "mesh-table"});
  const header = element("tr");
  for (const [label, key, kind] of tableColumns) {
    const th = element("th", {class: (kind === "text" ? "text " : "") + (key === sortKey ? (sortUp ? "sorted-up" : "sorted-down") : ""), "data-key": key}, label);
    th.addEventListener("click", () => { sortUp = key === sortKey ? !sortUp : true; sortKey = key; drawTable(); });
    header.append(th);
  }
  table.append(header);
  for (const row of sorted.slice(0, MAX_TABLE_ROWS)) {
    const line = element("tr", {class: "mesh-row", "data-file": row.file});
    for (const [, key, kind] of tableColumns) line.append(cell(row, key, kind));
    row.line = line;
    table.append(line);
  }
  document.getElementById("table-note").textContent = sorted.length > MAX_TABLE_ROWS
    ? `(the first ${count(MAX_TABLE_ROWS)} of ${count(sorted.length)}; results.csv has them all)` : `(${count(sorted.length)})`;
  document.getElementById("table").replaceChildren(table);
}

function select(row) {
  for (const line of document.querySelectorAll("tr.selected")) line.classList.remove("selected");
  if (row.line) { row.line.classList.add("selected"); row.line.scrollIntoView({block: "center"}); }
}

drawHeader();
drawTotals();
drawPlots();
drawErrors();
drawTable();
document.body.setAttribute("data-rendered", "yes");
</script>
</body>
</html>
)HTML";

}  // namespace

const std::string& batchReportPage() {
    static const std::string page = std::string(pageHead) + "@DATA@" + pageScript;
    return page;
}

}  // namespace conescope
