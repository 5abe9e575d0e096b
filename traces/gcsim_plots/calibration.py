"""Measured against predicted (gcsim calibrate/validate --csv) and error against host time per
network model (gcsim accuracy network --csv)."""

import os

from gcsim_plots.errors import PlotError
from gcsim_plots.media_accuracy import is_media_accuracy, plot_media_accuracy
from gcsim_plots.render_accuracy import is_render_accuracy, plot_render_accuracy
from gcsim_plots.style import DPI
from gcsim_plots.table_csv import csv_machine_line, number, read_rows

CALIBRATION_COLUMNS = ("table", "nodes", "case", "measured", "predicted", "error", "fitted")
ACCURACY_COLUMNS = ("model", "table", "median_error", "max_error", "within_15", "cells", "wall_s")


def plot_calibration(plt, path, out, title):
    """One panel per table: predicted against measured on log axes, the diagonal and 15 %/25 % bands;
    fitted cells hollow, validation cells filled."""
    rows = read_rows(path, CALIBRATION_COLUMNS)
    tables = []
    for r in rows:
        if r["table"] not in tables:
            tables.append(r["table"])
    fig, axes = plt.subplots(1, len(tables), figsize=(4.2 * len(tables), 4.4), squeeze=False)
    for ax, table in zip(axes[0], tables):
        cells = [(i + 2, r) for i, r in enumerate(rows) if r["table"] == table]
        m = [number(r, "measured", path, i) for i, r in cells]
        p = [number(r, "predicted", path, i) for i, r in cells]
        if min(m + p) <= 0:
            raise PlotError(f"{path}: table {table} has a figure <= 0; measured and predicted must be positive")
        lo, hi = min(m + p) / 1.3, max(m + p) * 1.3
        xs = [lo, hi]
        ax.fill_between(xs, [x / 1.25 for x in xs], [x * 1.25 for x in xs], color="#eeeeee", label="within 25 %")
        ax.fill_between(xs, [x / 1.15 for x in xs], [x * 1.15 for x in xs], color="#d9d9d9", label="within 15 %")
        ax.plot(xs, xs, color="#555555", lw=0.8)
        fitted = [r["fitted"] in ("1", "true") for _, r in cells]
        for flag, marker, label in ((False, "o", "predicted"), (True, "o", "fitted")):
            sel = [k for k in range(len(cells)) if fitted[k] == flag]
            if sel:
                ax.scatter([m[k] for k in sel], [p[k] for k in sel], s=22, marker=marker, label=label,
                           facecolors="none" if flag else "#377eb8", edgecolors="#377eb8")
        within = sum(1 for k in range(len(cells)) if abs(p[k] / m[k] - 1) <= 0.15)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlim(lo, hi)
        ax.set_ylim(lo, hi)
        ax.set_xlabel("measured")
        ax.set_ylabel("predicted (simulated)")
        ax.set_title(f"table {table}: {within}/{len(cells)} within 15 %")
        ax.legend(loc="upper left", fontsize=8)
    heading = title or f"{os.path.basename(path)}: measured against predicted"
    fig.suptitle(f"{heading}\n{csv_machine_line(path, fig.get_figwidth())}", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=DPI)
    plt.close(fig)


def plot_accuracy(plt, path, out, title):
    """Median error against host seconds, one point per (model, table), a line per table; a CSV of
    gcsim accuracy media or gcsim accuracy render goes to its own plot."""
    try:
        if is_media_accuracy(path):
            return plot_media_accuracy(plt, path, out, title)
        if is_render_accuracy(path):
            return plot_render_accuracy(plt, path, out, title)
    except OSError:
        pass  # read_rows below reports the file
    rows = read_rows(path, ACCURACY_COLUMNS)
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    tables = sorted({r["table"] for r in rows})
    for table in tables:
        pts = sorted(((number(r, "wall_s", path, i + 2), 100 * number(r, "median_error", path, i + 2), r["model"])
                      for i, r in enumerate(rows) if r["table"] == table))
        ax.plot([x for x, _, _ in pts], [y for _, y, _ in pts], marker="o", label=f"table {table}")
        for x, y, model in pts:
            ax.annotate(model, (x, y), textcoords="offset points", xytext=(4, 4), fontsize=8)
    ax.set_xlabel("host wall time to predict the tables (s)")
    ax.set_ylabel("median |error| against the thesis (%)")
    heading = title or "What each network model's fidelity buys and costs"
    ax.set_title(f"{heading}\n{csv_machine_line(path, fig.get_figwidth())}", fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=DPI)
    plt.close(fig)
