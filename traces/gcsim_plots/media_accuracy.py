"""RMSE against simulated time per estimator, one panel per scene (gcsim accuracy media --csv)."""

from matplotlib.ticker import FormatStrFormatter, NullFormatter

from gcsim_plots.style import DPI
from gcsim_plots.table_csv import csv_machine_line, first_data_line, number, read_rows

LINESTYLES = ("-", "--", "-.", ":", (0, (5, 1, 1, 1)))

MEDIA_ACCURACY_COLUMNS = ("scene", "estimator", "budget", "sim_s", "wall_s", "rmse", "rel_rmse")


def is_media_accuracy(path):
    header = first_data_line(path).strip().split(",")
    return "estimator" in header and "rmse" in header


def plot_media_accuracy(plt, path, out, title):
    rows = read_rows(path, MEDIA_ACCURACY_COLUMNS)
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, axes = plt.subplots(1, len(scenes), figsize=(4.2 * len(scenes), 3.8), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        mine = [(i, r) for i, r in enumerate(rows) if r["scene"] == scene]
        by_budget = {}  # budget -> the times its renders took (within about 1 % of each other)
        for k, est in enumerate(dict.fromkeys(r["estimator"] for _, r in mine)):
            pts = sorted((number(r, "sim_s", path, i + 2), 100 * number(r, "rel_rmse", path, i + 2))
                         for i, r in mine if r["estimator"] == est)
            # Estimators that coincide (equiangular without a point light is transmittance) stay
            # visible: each has its own dash and a smaller marker than the one before.
            ax.plot([x for x, _ in pts], [y for _, y in pts], marker="o", markersize=7 - k, label=est,
                    linestyle=LINESTYLES[k % len(LINESTYLES)])
        ax.set_xscale("log")
        ax.set_yscale("log")
        # One tick per budget, at its renders' mean time, as a plain number (no crowded minor labels).
        for i, r in mine:
            by_budget.setdefault(r["budget"], []).append(number(r, "sim_s", path, i + 2))
        ax.set_xticks(sorted(sum(ts) / len(ts) for ts in by_budget.values()))
        ax.xaxis.set_major_formatter(FormatStrFormatter("%.3g"))
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_xlabel("simulated render time on one CPU (s)")
        ax.set_ylabel("RMSE / mean of the reference (%)")
        ax.set_title(scene)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    heading = title or "Media: error against time per distance estimator"
    fig.suptitle(f"{heading}\n{csv_machine_line(path, fig.get_figwidth())}", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=DPI)
    plt.close(fig)
