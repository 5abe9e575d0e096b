"""Error against simulated time across a whole render (gcsim accuracy render --csv): one line per
varied control, and the Pareto front of all renders (no other render is both faster and closer)."""

from gcsim_plots.style import DPI
from gcsim_plots.table_csv import csv_machine_line, first_data_line, number, read_rows

RENDER_ACCURACY_COLUMNS = ("pass", "control", "value", "relative_rmse", "simulated_s", "wall_s")


def is_render_accuracy(path):
    header = first_data_line(path).strip().split(",")
    return "control" in header and "relative_rmse" in header


def pareto_front(points):
    """The points (time, error, ...) that no other point beats on both, by increasing time."""
    front, best = [], float("inf")
    for p in sorted(points):
        if p[1] < best:
            front.append(p)
            best = p[1]
    return front


def plot_render_accuracy(plt, path, out, title):
    rows = read_rows(path, RENDER_ACCURACY_COLUMNS)
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    points = []
    for control in dict.fromkeys(f'{r["pass"]} {r["control"]}' for r in rows):
        pts = sorted((number(r, "simulated_s", path, i + 2), 100 * number(r, "relative_rmse", path, i + 2), r["value"])
                     for i, r in enumerate(rows) if f'{r["pass"]} {r["control"]}' == control)
        points += pts
        ax.plot([x for x, _, _ in pts], [y for _, y, _ in pts], marker="o", label=control)
    # Each control's line passes through the render with every default (the same time and error):
    # that point is labelled once, not with every control's value written over one another.
    labels = {}
    for x, y, value in points:
        labels.setdefault((x, y), []).append(value)
    for (x, y), values in labels.items():
        ax.annotate(values[0] if len(values) == 1 else "all defaults", (x, y), textcoords="offset points",
                    xytext=(4, 4), fontsize=8)
    front = pareto_front(points)
    ax.plot([x for x, _, _ in front], [y for _, y, _ in front], color="black", linestyle=":", label="Pareto front")
    ax.set_xlabel("simulated seconds of the render")
    ax.set_ylabel("relative RMSE against the reference (%)")
    ax.set_title(f"{title or 'What accuracy costs across a render'}\n{csv_machine_line(path, fig.get_figwidth())}", fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=DPI)
    plt.close(fig)
