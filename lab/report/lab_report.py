#!/usr/bin/env python3
"""The lab's charts and report, from a sweep's results.json (planet lab run).

    python3 lab/report/lab_report.py OUT

Writes OUT/pareto_overall.{png,svg} and OUT/pareto_<scene>.{png,svg}: time
per frame on a log x axis, error on a log y axis, a marker per (technique,
quality), the Pareto front as a line; and OUT/report.html, one page with
everything in it (the charts and images inline, no network): the charts,
a sentence per scene naming the cheapest technique within 1, 2 and 5 %, the
table of cells, and the technique / ground truth / error images of every
point on a front; points whose times tie (their frames' spreads, centred on
them, overlap) are said to tie, never ranked; and OUT/orders.{png,svg}: each (technique, quality)'s
error split into its first order and the orders above it. Where
OUT/stability holds planet lab stability's report, the page links it and
shows its line plots; where OUT/measured holds planet lab measured's, the
same.
"""
import base64
import html
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from report_table import load_table  # noqa: E402
from matplotlib.ticker import FuncFormatter  # noqa: E402

MARKERS = "osD^v<>ph*"
FLOOR = 1e-4  # errors below this are drawn at it (a log axis has no 0)


def load(out):
    return load_table(out, "results.json", ("cells", "overall"), "lab_report",
                      "the results of planet lab run")


def styles(points):
    """A colour per technique, a marker per quality point within it."""
    techniques = sorted({p["technique"] for p in points})
    colours = plt.get_cmap("tab10")
    style = {}
    for t_index, technique in enumerate(techniques):
        qualities = [p["quality"] for p in points if p["technique"] == technique]
        for q_index, quality in enumerate(dict.fromkeys(qualities)):
            style[(technique, quality)] = (colours(t_index % 10), MARKERS[q_index % len(MARKERS)])
    return style


def finish(fig, ax, stem):
    """A grid, the legend beside the axes, and the chart as PNG and SVG."""
    ax.grid(True, which="both", linewidth=0.3, alpha=0.5)
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5), frameon=False)
    fig.tight_layout()
    for ext in ("png", "svg"):
        # Whole or absent: a sweep killed while charting leaves no half chart.
        fig.savefig(stem + ".part", format=ext)
        os.replace(stem + ".part", f"{stem}.{ext}")
    plt.close(fig)


def name(p):
    return f'{p["technique"]}:{p["quality"]}'


def chart(points, title, stem, style):
    fig, ax = plt.subplots(figsize=(7.5, 4.8), dpi=100)
    for p in points:
        colour, marker = style[(p["technique"], p["quality"])]
        spread = p.get("wall_spread_ms", 0)
        if spread > 0:
            # The frames' spread as a bar through the point: points whose
            # bars reach each other's tie in time.
            half = spread / 2
            ax.errorbar(p["wall_ms"], max(p["error"], FLOOR),
                        xerr=[[min(half, 0.9 * p["wall_ms"])], [half]], fmt="none",
                        ecolor=colour, elinewidth=0.9, alpha=0.7, capsize=2, zorder=2)
        ax.scatter(p["wall_ms"], max(p["error"], FLOOR), color=colour, marker=marker, s=46,
                   label=f'{p["technique"]}:{p["quality"]}', zorder=3,
                   edgecolors="black" if p["on_front"] else "none")
    front = sorted((p for p in points if p["on_front"]), key=lambda p: p["wall_ms"])
    if front:
        # A staircase: from each point on the front, its error holds until
        # a dearer point does better.
        ax.plot([p["wall_ms"] for p in front], [max(p["error"], FLOOR) for p in front],
                color="black", linewidth=1.2, zorder=2, drawstyle="steps-post",
                label="Pareto front")
    ax.set_xscale("log")
    ax.set_yscale("log")
    # Plain numbers (ms, %) on the ticks; the minor ones labelled too where
    # the points span less than a decade (no major tick in the range).
    label_ms = FuncFormatter(lambda v, _: f"{v:.4g}")
    label_error = FuncFormatter(lambda v, _: f"{100 * v:.3g} %")
    blank = FuncFormatter(lambda v, _: "")
    ms = [p["wall_ms"] for p in points]
    errors = [max(p["error"], FLOOR) for p in points]
    ax.xaxis.set_major_formatter(label_ms)
    ax.yaxis.set_major_formatter(label_error)
    ax.xaxis.set_minor_formatter(label_ms if max(ms) < 10 * min(ms) else blank)
    ax.yaxis.set_minor_formatter(label_error if max(errors) < 10 * min(errors) else blank)
    ax.tick_params(axis="both", which="minor", labelsize=7)
    ax.set_xlabel("time per frame, ms (the atmosphere's passes; bars: the frames' spread)")
    ax.set_ylabel("error (worst channel's relative RMSE)")
    ax.set_title(title)
    finish(fig, ax, stem)


def worst(values):
    return max(values) if values else 0.0


def geometric_mean(values):
    values = [max(v, FLOOR) for v in values]
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else FLOOR


def order_split(cells, style):
    """Per (technique, quality), over the scenes whose cells carry the split:
    the geometric means of the worst channel's error in single scattering
    and in the orders above it."""
    points = {}
    for c in cells:
        if c.get("single_error") is None:
            continue
        key = (c["technique"], c["quality"])
        points.setdefault(key, ([], []))
        points[key][0].append(worst(c["single_error"]))
        points[key][1].append(worst(c["higher_error"]))
    return [{"technique": t, "quality": q, "single": geometric_mean(s),
             "higher": geometric_mean(h), "scenes": len(s)}
            for (t, q), (s, h) in points.items() if (t, q) in style]


def orders_chart(split, stem, style):
    fig, ax = plt.subplots(figsize=(7.5, 4.8), dpi=100)
    for p in split:
        colour, marker = style[(p["technique"], p["quality"])]
        ax.scatter(p["single"], p["higher"], color=colour, marker=marker, s=46, zorder=3,
                   label=f'{p["technique"]}:{p["quality"]}')
    values = [v for p in split for v in (p["single"], p["higher"])]
    low, high = min(values) / 1.5, max(values) * 1.5
    ax.plot([low, high], [low, high], color="grey", linewidth=0.8, linestyle="--",
            label="equal parts", zorder=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    label_error = FuncFormatter(lambda v, _: f"{100 * v:.3g} %")
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_formatter(label_error)
    ax.set_xlabel("error in single scattering (against the first order)")
    ax.set_ylabel("error in the orders above the first")
    ax.set_title("Where the error comes from (geometric means over the scenes)")
    finish(fig, ax, stem)


def inline_png(path):
    try:
        with open(path, "rb") as f:
            data = base64.b64encode(f.read()).decode("ascii")
    except OSError:
        return '<span class="missing">missing</span>'
    return f'<img src="data:image/png;base64,{data}" alt="{html.escape(os.path.basename(path))}">'


def cheapest_within(cells, budget):
    """The cheapest cell within the budget, and the others within it whose
    time ties with its own: no one of them is the cheapest."""
    fitting = [c for c in cells if c["error"] <= budget]
    if not fitting:
        return None, []
    best = min(fitting, key=lambda c: c["wall_ms"])
    ties = set(best.get("time_ties", []))
    return best, sorted((c for c in fitting if name(c) in ties), key=lambda c: c["wall_ms"])


def tie_groups(points):
    """Points sorted by time, in groups of those whose times tie with one of
    the group's."""
    groups = []
    for p in sorted(points, key=lambda p: p["wall_ms"]):
        if groups and any(name(q) in p.get("time_ties", []) for q in groups[-1]):
            groups[-1].append(p)
        else:
            groups.append([p])
    return groups


def figures(p):
    return f'{html.escape(name(p))} ({p["wall_ms"]:.3g} ms, {percent(p["error"])} %)'


def said_in_order(points):
    """The points from the cheapest, those whose times tie said to tie."""
    parts = []
    for group in tie_groups(points):
        if len(group) == 1:
            parts.append(figures(group[0]))
        else:
            parts.append(", ".join(figures(p) for p in group[:-1]) + " and " +
                         figures(group[-1]) + ", which tie in time")
    return "; then ".join(parts)


def percent(x):
    return f"{100 * x:.2f}"


def by_order(cell, key):
    values = cell.get(key)
    return "-" if values is None else " / ".join(percent(v) for v in values)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: lab_report.py OUT (the folder of planet lab run's results.json)")
    out = sys.argv[1]
    results = load(out)
    cells = results["cells"]
    scenes = list(dict.fromkeys(c["scene"] for c in cells))
    style = styles(cells)
    chart(results["overall"], "All scenes (geometric means)", os.path.join(out, "pareto_overall"),
          style)
    for scene in scenes:
        chart([c for c in cells if c["scene"] == scene], scene,
              os.path.join(out, f"pareto_{scene}"), style)

    split = order_split(cells, style)
    if split:
        orders_chart(split, os.path.join(out, "orders"), style)

    e = html.escape
    parts = [
        "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\">",
        "<title>planet lab: speed against accuracy</title><style>",
        "body{font-family:sans-serif;margin:1.5em;max-width:1200px}",
        "table{border-collapse:collapse;font-size:12px}td,th{border:1px solid #ccc;",
        "padding:2px 6px;text-align:right}td.l,th.l{text-align:left}tr.front{background:#eef6ff}",
        ".triplet img{width:256px;image-rendering:pixelated;margin-right:4px}",
        ".chart img{max-width:100%}.missing{color:#a00}</style></head><body>",
        "<h1>Speed against accuracy</h1>",
        f"<p>planet {e(str(results.get('planet', '')))}, commit {e(str(results.get('commit', '')))}, "
        f"on {e(str(results.get('renderer', '')))}. Cells timed at "
        f"{e('x'.join(map(str, results.get('time_size', []))))} ({results.get('frames', '')} "
        f"frames after one untimed; {e(str(results.get('cost', '')))}), measured at "
        f"{e('x'.join(map(str, results.get('accuracy_size', []))))} against the path-traced "
        f"ground truth ({e(str(results.get('error', '')))}).</p>",
        "<h2>All scenes</h2>",
        f'<div class="chart" id="chart-overall">{inline_png(os.path.join(out, "pareto_overall.png"))}</div>',
    ]
    front = [p for p in results["overall"] if p["on_front"]]
    parts.append(f'<p id="front-overall">On the overall front, from the cheapest: '
                 f'{said_in_order(front)}.</p>'
                 "<p>Two points tie in time where their frames' spreads, each centred on its "
                 "time, overlap (the bars on the charts); a point is off a front only where "
                 "another is as fast and as accurate within that noise (and the errors' 95 % "
                 "intervals), and better beyond it in one.</p>")
    if split:
        parts.append("<h2>Where the error comes from</h2><p>Each point's error split by order "
                     "(the worst channel's debiased relative RMSE, geometric means over the "
                     "scenes): the technique confined to single scattering against the ground "
                     "truth's first order, and what the orders above the first add, the "
                     "technique's against the ground truth's. A point far above the dashed line "
                     "is held back by its multiple scattering; one far to its right by its "
                     "single scattering.</p>")
        parts.append(f'<div class="chart" id="chart-orders">'
                     f'{inline_png(os.path.join(out, "orders.png"))}</div>')
        parts.append("<p>" + "; ".join(
            f'{e(p["technique"])}:{e(p["quality"])} {percent(p["single"])} % and '
            f'{percent(p["higher"])} %' for p in split) + ".</p>")
    stability = os.path.join(out, "stability")
    if os.path.exists(os.path.join(stability, "report.html")):
        parts.append("<h2>Where each technique breaks</h2><p>The stability map "
                     "(<code>planet lab stability</code>, its own report in "
                     "<a href=\"stability/report.html\">stability/report.html</a>, its tables "
                     "in stability/stability.csv and .json): each technique's error along "
                     "each axis around each body.</p>")
        for body in ("earth", "mars", "asteroid"):
            lines = os.path.join(stability, f"lines_{body}.png")
            if os.path.exists(lines):
                parts.append(f'<div class="chart">{inline_png(lines)}</div>')
    measured = os.path.join(out, "measured")
    if os.path.exists(os.path.join(measured, "report.html")):
        parts.append("<h2>Against measured skies</h2><p>The ground truth and each technique "
                     "against Kider et al.'s measurements of 2013-05-27 "
                     "(<code>planet lab measured</code>, its own report in "
                     "<a href=\"measured/report.html\">measured/report.html</a>, its tables in "
                     "measured/measured.csv and .json): spectral RMSE per capture and in total "
                     "beside Bruneton's 2016 evaluation of the same day, zenith luminance, and "
                     "the sky's radiance over the hemisphere.</p>")
        for plot in ("rmse.png", "measured_vs_modelled.png", "zenith_luminance.png"):
            path = os.path.join(measured, plot)
            if os.path.exists(path):
                parts.append(f'<div class="chart">{inline_png(path)}</div>')
    for scene in scenes:
        here = [c for c in cells if c["scene"] == scene]
        parts.append(f"<h2>{e(scene)}</h2>")
        sentences = []
        for budget in (0.01, 0.02, 0.05):
            c, ties = cheapest_within(here, budget)
            tied = (", tied in time with " + " and ".join(figures(t) for t in ties)) if ties else ""
            sentences.append(f"within {100 * budget:g} %: {figures(c)}{tied}" if c else
                             f"within {100 * budget:g} %: none")
        parts.append(f'<p id="cheapest-{e(scene)}">Cheapest ' + "; ".join(sentences) + ".</p>")
        parts.append(f'<div class="chart">{inline_png(os.path.join(out, f"pareto_{scene}.png"))}</div>')
        for c in sorted((c for c in here if c["on_front"]), key=lambda c: c["wall_ms"]):
            stem = os.path.join(out, "cells", scene, f'{c["technique"]}-{c["quality"]}')
            tied = c.get("time_ties", [])
            tied = f' (ties in time with {e(", ".join(tied))})' if tied else ""
            parts.append(
                f'<p class="triplet">{e(c["technique"])}:{e(c["quality"])}, '
                f'{c["wall_ms"]:.3g} ms, {percent(c["error"])} %{tied}<br>'
                f'{inline_png(stem + "_technique.png")}'
                f'{inline_png(os.path.join(out, "cells", scene, "reference.png"))}'
                f'{inline_png(stem + "_error.png")}</p>')
    parts.append("<h2>Every cell</h2><p>Relative RMSE per channel in %, R / G / B: plain (the "
                 "reference's noise in it) and debiased with its 95 % interval; the debiased "
                 "error of its single scattering and of the orders above; the worst "
                 "pixel's relative error; the mean CIEDE2000 of the tone-mapped images; the "
                 "points of its scene whose time ties with its own. Rows on their scene's "
                 "front are shaded.</p>")
    parts.append('<table id="cells"><thead><tr><th class="l">scene</th><th class="l">technique'
                 '</th><th class="l">quality</th><th>ms</th><th>spread ms</th><th>plain %</th>'
                 '<th>debiased % [95 %]</th><th>single %</th><th>higher orders %</th>'
                 '<th>worst pixel %</th><th>CIEDE2000</th><th class="l">ties in time with</th>'
                 '</tr></thead>'
                 '<tbody>')
    for c in cells:
        debiased = " / ".join(
            f"{percent(v)} [{percent(lo)}, {percent(hi)}]"
            for v, lo, hi in zip(c["debiased_relative_rmse"], c["debiased_low"],
                                 c["debiased_high"]))
        parts.append(
            f'<tr class="{"front" if c["on_front"] else ""}"><td class="l">{e(c["scene"])}</td>'
            f'<td class="l">{e(c["technique"])}</td><td class="l">{e(c["quality"])}</td>'
            f'<td>{c["wall_ms"]:.3g}</td><td>{c["wall_spread_ms"]:.2g}</td>'
            f'<td>{" / ".join(percent(v) for v in c["relative_rmse"])}</td><td>{debiased}</td>'
            f'<td>{by_order(c, "single_error")}</td><td>{by_order(c, "higher_error")}</td>'
            f'<td>{percent(c["worst_pixel"])}</td><td>{c["ciede2000"]:.2f}</td>'
            f'<td class="l">{e(", ".join(c.get("time_ties", [])))}</td></tr>')
    parts.append("</tbody></table></body></html>")
    path = os.path.join(out, "report.html")
    with open(path + ".part", "w", encoding="utf-8") as f:
        f.write("\n".join(parts))
    os.replace(path + ".part", path)
    orders = " and the split by order (orders.png, .svg)" if split else ""
    print(f"lab: wrote {path}, {len(scenes) + 1} charts (pareto_*.png, .svg){orders}")


if __name__ == "__main__":
    main()
