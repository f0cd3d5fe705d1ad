#!/usr/bin/env python3
"""The measured skies' plots and report, from planet lab measured's measured.json.

    python3 lab/report/measured_report.py OUT

Writes
  OUT/measured_vs_modelled.png: every direction of every capture, modelled
      radiance against measured at 450, 550 and 650 nm, a panel per source
      (the ground truth, then each technique), the diagonal dashed;
  OUT/radiance_<HHMM>.png per capture: the sky's radiance over the
      hemisphere (zenith at the centre, north up, east right) at 450, 550
      and 650 nm, measured and from each source, with the sun's place;
  OUT/zenith_spectrum.png: the zenith's measured spectrum (every nm) and
      each source's, for each capture;
  OUT/spectra_<HHMM>.png per capture: every direction's spectrum over the
      compared range, measured and from each source, a panel a direction;
  OUT/rmse.png: each source's total spectral RMSE beside the published
      figures of Bruneton's 2016 evaluation of the same day;
  OUT/zenith_luminance.png: zenith luminance through the morning;
and OUT/report.html, one page with the tables and every plot inline.
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

BANDS = [450.0, 550.0, 650.0]
BAND_COLOURS = {450.0: "#1f5fbf", 550.0: "#2a9d3a", 650.0: "#c0392b"}


def load(out):
    return load_table(out, "measured.json", ("captures", "totals", "wavelengths_nm"), "measured_report",
                      "the output of planet lab measured")


def sources(doc):
    names = list(doc["totals"].keys())
    return ["ground_truth"] + [n for n in names if n != "ground_truth"]


def band_index(doc, nm):
    w = doc["wavelengths_nm"]
    return min(range(len(w)), key=lambda i: abs(w[i] - nm))


def save(fig, out, name):
    path = os.path.join(out, name)
    # Whole or absent: a run killed while charting leaves no half chart.
    fig.savefig(path + ".part", format=os.path.splitext(path)[1][1:], dpi=110, bbox_inches="tight")
    os.replace(path + ".part", path)
    plt.close(fig)
    return path


def scatter_plot(doc, out):
    names = sources(doc)
    cols = min(4, len(names))
    rows = math.ceil(len(names) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(3.4 * cols, 3.3 * rows), squeeze=False)
    top = 0.0
    for c in doc["captures"]:
        for k in BANDS:
            i = band_index(doc, k)
            top = max(top, max(m[i] for m in c["measured"]))
    top *= 1e3 * 1.08
    for n, name in enumerate(names):
        ax = axes[n // cols][n % cols]
        for k in BANDS:
            i = band_index(doc, k)
            xs, ys = [], []
            for c in doc["captures"]:
                for d, m in enumerate(c["measured"]):
                    xs.append(1e3 * m[i])
                    ys.append(1e3 * c["sources"][name]["radiance"][d][i])
            ax.scatter(xs, ys, s=5, color=BAND_COLOURS[k], alpha=0.6, label=f"{k:.0f} nm")
        ax.plot([0, top], [0, top], "k--", lw=0.8)
        ax.set_xlim(0, top)
        ax.set_ylim(0, top)
        total = doc["totals"][name]["debiased_rmse"]
        ax.set_title(f"{name}: RMSE {total:.1f}", fontsize=9)
        ax.set_xlabel("measured (mW m⁻² sr⁻¹ nm⁻¹)", fontsize=8)
        ax.set_ylabel("modelled", fontsize=8)
        ax.tick_params(labelsize=7)
        if n == 0:
            ax.legend(fontsize=7, loc="upper left")
    for n in range(len(names), rows * cols):
        axes[n // cols][n % cols].axis("off")
    fig.subplots_adjust(hspace=0.45, wspace=0.3)
    fig.suptitle("Modelled against measured radiance, every direction of every capture", fontsize=10)
    return save(fig, out, "measured_vs_modelled.png")


def polar_xy(azimuth_deg, elevation_deg):
    """Zenith at the centre, the horizon at radius 1, north up, east right."""
    r = (90.0 - elevation_deg) / 90.0
    a = math.radians(azimuth_deg)
    return r * math.sin(a), r * math.cos(a)


def radiance_maps(doc, out, capture):
    names = ["measured"] + sources(doc)
    fig, axes = plt.subplots(len(BANDS), len(names), figsize=(2.3 * len(names), 2.3 * len(BANDS)),
                             squeeze=False)
    pts = [polar_xy(d["azimuth_deg"], d["elevation_deg"]) for d in capture["directions"]]
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    sun = polar_xy(capture["sun"]["azimuth_deg"], capture["sun"]["elevation_deg"])
    for b, k in enumerate(BANDS):
        i = band_index(doc, k)
        measured = [1e3 * m[i] for m in capture["measured"]]
        lo, hi = min(measured), max(measured)
        for n, name in enumerate(names):
            ax = axes[b][n]
            if name == "measured":
                values = measured
            else:
                values = [1e3 * r[i] for r in capture["sources"][name]["radiance"]]
            if len(xs) >= 3:
                im = ax.tricontourf(xs, ys, values, levels=16, vmin=lo, vmax=hi, cmap="viridis")
            ax.scatter(xs, ys, s=3, c="white", alpha=0.5)
            ax.plot(*sun, marker="*", color="yellow", markersize=10, markeredgecolor="black")
            ax.add_patch(plt.Circle((0, 0), 1.0, fill=False, color="grey", lw=0.5))
            ax.set_xlim(-1.05, 1.05)
            ax.set_ylim(-1.05, 1.05)
            ax.set_aspect("equal")
            ax.axis("off")
            if b == 0:
                ax.set_title(name, fontsize=9)
            if n == 0:
                ax.text(-1.25, 0, f"{k:.0f} nm", rotation=90, va="center", fontsize=9)
        if len(xs) >= 3:
            fig.colorbar(im, ax=axes[b].tolist(), shrink=0.8, label="mW m⁻² sr⁻¹ nm⁻¹")
    fig.suptitle(f"Sky radiance at {capture['local']} local ({capture['utc']}); zenith at the "
                 "centre, north up, east right; the sun a star", fontsize=10)
    return save(fig, out, f"radiance_{capture['local'].replace(':', '')}.png")


def zenith_spectra(doc, out):
    caps = doc["captures"]
    cols = min(4, len(caps))
    rows = math.ceil(len(caps) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(3.6 * cols, 2.8 * rows), squeeze=False)
    w = doc["wavelengths_nm"]
    for n, c in enumerate(caps):
        ax = axes[n // cols][n % cols]
        z = len(c["directions"]) - 1
        ax.plot(w, [1e3 * v for v in c["measured"][z]], "k-", lw=2, label="measured (10 nm bins)")
        for name in sources(doc):
            ax.plot(w, [1e3 * v for v in c["sources"][name]["radiance"][z]], lw=1, label=name)
        ax.set_xlim(360, 830)
        ax.set_title(f"zenith, {c['local']}", fontsize=9)
        ax.tick_params(labelsize=7)
        if n == 0:
            ax.legend(fontsize=6)
    for n in range(len(caps), rows * cols):
        axes[n // cols][n % cols].axis("off")
    fig.suptitle("Zenith spectral radiance (mW m⁻² sr⁻¹ nm⁻¹) against wavelength (nm)", fontsize=10)
    return save(fig, out, "zenith_spectrum.png")


def direction_spectra(doc, out, capture):
    """Every direction's spectrum, measured and from each source: a panel
    per direction, by ring (elevation) and then azimuth."""
    order = sorted(range(len(capture["directions"])),
                   key=lambda i: (capture["directions"][i]["elevation_deg"],
                                  capture["directions"][i]["azimuth_deg"]))
    cols = math.ceil(math.sqrt(len(order)))
    rows = math.ceil(len(order) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(1.9 * cols, 1.5 * rows), squeeze=False,
                             sharex=True)
    w = doc["wavelengths_nm"]
    keep = [k for k, l in enumerate(w) if doc["compare_nm"][0] <= l <= doc["compare_nm"][1]]
    xs = [w[k] for k in keep]
    for n, i in enumerate(order):
        ax = axes[n // cols][n % cols]
        d = capture["directions"][i]
        ax.plot(xs, [1e3 * capture["measured"][i][k] for k in keep], "k-", lw=1.6,
                label="measured")
        for name in sources(doc):
            ax.plot(xs, [1e3 * capture["sources"][name]["radiance"][i][k] for k in keep], lw=0.8,
                    label=name)
        ax.set_title(f"el {d['elevation_deg']:.0f} az {d['azimuth_deg']:.0f}", fontsize=6, pad=2)
        ax.tick_params(labelsize=5, pad=1)
        ax.set_ylim(bottom=0)
    for n in range(len(order), rows * cols):
        axes[n // cols][n % cols].axis("off")
    axes[0][0].legend(fontsize=4, loc="upper right")
    fig.suptitle(f"Spectral radiance per direction at {capture['local']} local "
                 "(mW m⁻² sr⁻¹ nm⁻¹ against nm); sun at elevation "
                 f"{capture['sun']['elevation_deg']:.1f}, azimuth {capture['sun']['azimuth_deg']:.1f}",
                 fontsize=9)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    return save(fig, out, f"spectra_{capture['local'].replace(':', '')}.png")


def rmse_chart(doc, out):
    names = sources(doc)
    values = [doc["totals"][n]["debiased_rmse"] for n in names]
    published = doc.get("published", [])
    labels = names + [p["model"] + " (published)" for p in published]
    bars = values + [p["rmse"] for p in published]
    colours = ["#2a6fb0"] * len(names) + ["#9e9e9e"] * len(published)
    fig, ax = plt.subplots(figsize=(7.5, 0.32 * len(labels) + 1.2))
    ax.barh(range(len(labels)), bars, color=colours)
    ax.set_yticks(range(len(labels)))
    ax.set_yticklabels(labels, fontsize=8)
    ax.invert_yaxis()
    for i, v in enumerate(bars):
        ax.text(v, i, f" {v:.1f}", va="center", fontsize=7)
    ax.set_xlabel("total spectral RMSE, 360-720 nm (mW m⁻² sr⁻¹ nm⁻¹)")
    ax.set_title("Against Kider et al.'s measurements of 2013-05-27: ours (blue) and the "
                 "published evaluation (grey)", fontsize=9)
    return save(fig, out, "rmse.png")


def luminance_chart(doc, out):
    caps = doc["captures"]
    x = list(range(len(caps)))
    fig, ax = plt.subplots(figsize=(7, 3.4))
    measured = [c["sources"]["ground_truth"]["score"]["measured_zenith_luminance"] for c in caps]
    ax.plot(x, measured, "k-o", lw=2, label="measured")
    ax.fill_between(x, [0.9 * m for m in measured], [1.1 * m for m in measured], color="#dddddd",
                    label="measured ± 10 %")
    for name in sources(doc):
        ax.plot(x, [c["sources"][name]["score"]["zenith_luminance"] for c in caps], "-", marker=".",
                label=name)
    ax.set_xticks(x)
    ax.set_xticklabels([c["local"] for c in caps], fontsize=8)
    ax.set_ylabel("zenith luminance (cd/m²)")
    ax.legend(fontsize=7, ncol=2)
    ax.grid(alpha=0.3)
    return save(fig, out, "zenith_luminance.png")


def inline_png(path):
    with open(path, "rb") as f:
        data = base64.b64encode(f.read()).decode()
    return f'<img src="data:image/png;base64,{data}" style="max-width:100%">'


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: measured_report.py OUT")
    out = sys.argv[1]
    doc = load(out)
    plots = [scatter_plot(doc, out), rmse_chart(doc, out), luminance_chart(doc, out),
             zenith_spectra(doc, out)]
    maps = [radiance_maps(doc, out, c) for c in doc["captures"]]
    spectra = [direction_spectra(doc, out, c) for c in doc["captures"]]
    names = sources(doc)
    caps = doc["captures"]
    rows = []
    for name in names:
        cells = "".join(
            f"<td>{c['sources'][name]['score']['debiased_rmse']:.1f}<br>"
            f"<small>{c['sources'][name]['score']['zenith_luminance']:.0f} / "
            f"{c['sources'][name]['score']['measured_zenith_luminance']:.0f}</small></td>"
            for c in caps)
        rows.append(f"<tr><th>{html.escape(name)}</th>{cells}"
                    f"<td><b>{doc['totals'][name]['debiased_rmse']:.1f}</b></td></tr>")
    published = "".join(f"<tr><td>{html.escape(p['model'])}</td><td>{p['rmse']}</td></tr>"
                        for p in doc.get("published", []))
    suns = "".join(
        f"<tr><td>{c['local']}</td><td>{c['utc']}</td><td>{c['sun']['elevation_deg']:.2f}</td>"
        f"<td>{c['sun']['azimuth_deg']:.2f}</td><td>{c['sun']['symmetry_azimuth_deg']:.1f}</td>"
        f"<td>{c['sun']['azimuth_turn_deg']:.1f}</td></tr>" for c in caps)
    page = f"""<!doctype html><html><head><meta charset="utf-8"><title>Measured skies</title>
<style>body{{font-family:sans-serif;max-width:1200px;margin:auto}} td,th{{padding:2px 8px;
text-align:right}} table{{border-collapse:collapse}} tr:nth-child(even){{background:#f4f4f4}}</style>
</head><body><h1>The sky against measurements</h1>
<p>Data: {html.escape(doc['data'])}; body {html.escape(doc['body'])}; ground truth
{doc['paths']} paths per direction and spectral sample. Spectral RMSE over every measured
direction and every spectral sample from {doc['compare_nm'][0]:.0f} to
{doc['compare_nm'][1]:.0f} nm, in mW m<sup>-2</sup> sr<sup>-1</sup> nm<sup>-1</sup> (the
ground truth's own noise taken out); below it, zenith luminance modelled / measured in
cd/m<sup>2</sup>.</p>
<table><tr><th>source</th>{''.join(f'<th>{c["local"]}</th>' for c in caps)}<th>total</th></tr>
{''.join(rows)}</table>
<h2>Published on the same measurements (Bruneton 2016, total spectral RMSE)</h2>
<table>{published}</table>
{inline_png(plots[1])}
<h2>Modelled against measured</h2>{inline_png(plots[0])}
<h2>Zenith luminance</h2>{inline_png(plots[2])}
<h2>Zenith spectra</h2>{inline_png(plots[3])}
<h2>The sun</h2><p>Our ephemeris's sun at each capture's UTC, against the axis about which
the measured sky is mirror-symmetric, and the turn given to the scan's azimuths.</p>
<table><tr><th>local</th><th>UTC</th><th>elevation</th><th>azimuth</th><th>sky's axis</th>
<th>turn</th></tr>{suns}</table>
<h2>Radiance over the sky</h2>{''.join(inline_png(m) for m in maps)}
<h2>Spectra, direction by direction</h2>{''.join(inline_png(m) for m in spectra)}
</body></html>"""
    with open(os.path.join(out, "report.html"), "w", encoding="utf-8") as f:
        f.write(page)


if __name__ == "__main__":
    main()
