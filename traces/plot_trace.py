#!/usr/bin/env python3
"""gcsim plot: PNG plots of a gcsim trace or of a node-count sweep. Normally run through
`gcsim plot` (which finds this script and Debian's python3); see traces/README.md.

  plot_trace.py TRACE --out DIR [--from-ms A] [--to-ms B] [--procs 0-7,12] [--title T]
      writes DIR/gantt.png, DIR/mesh_heatmap.png, DIR/message_matrix.png, DIR/utilization.png
      (and DIR/utilization.json: the mean busy / communicating / waiting / idle shares)
  plot_trace.py --sweep CSV --out DIR [--title T]
      writes DIR/sweep_<name of CSV>.png
  plot_trace.py --calibration CSV --out DIR     (gcsim calibrate/validate --csv)
      writes DIR/calibration_<name of CSV>.png: measured against predicted, per table
  plot_trace.py --accuracy CSV --out DIR        (gcsim accuracy network --csv)
      writes DIR/accuracy_<name of CSV>.png: error against host time, per network model

Bad input ends with one line 'gcsim plot: error: ...' naming the file and what was expected, and
exit status 2; never a Python traceback (set GCSIM_PLOT_DEBUG=1 to get one)."""

import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from gcsim_plots.errors import PlotError, UsageError  # noqa: E402

PLOTS = ("gantt", "mesh_heatmap", "message_matrix", "utilization")


class Parser(argparse.ArgumentParser):
    def error(self, message):
        raise UsageError(message)


def parse_args(argv):
    p = Parser(prog="gcsim plot", description="Plots of a gcsim trace, or of a sweep CSV.")
    p.add_argument("trace", nargs="?", help="trace written by --trace: FILE.json (with FILE.csv beside it) or FILE.csv")
    p.add_argument("--out", default="plots", help="directory for the PNGs (created if needed)")
    p.add_argument("--from-ms", type=float, default=None, help="start of the time window, simulated ms")
    p.add_argument("--to-ms", type=float, default=None, help="end of the time window, simulated ms")
    p.add_argument("--procs", default=None, help="processors to show, e.g. 0-7,12")
    p.add_argument("--sweep", default=None, help="a sweep CSV (nodes, simulated_s, comm_s, ...) instead of a trace")
    p.add_argument("--calibration", default=None, help="a CSV of gcsim calibrate/validate --csv instead of a trace")
    p.add_argument("--accuracy", default=None, help="a CSV of gcsim accuracy network --csv instead of a trace")
    p.add_argument("--title", default=None, help="title line of every plot")
    p.add_argument("--only", default=None, help="comma-separated subset of: " + ", ".join(PLOTS))
    args = p.parse_args(argv)
    inputs = [x for x in (args.trace, args.sweep, args.calibration, args.accuracy) if x]
    if len(inputs) > 1:
        raise UsageError("give one input: a TRACE, --sweep CSV, --calibration CSV or --accuracy CSV")
    if not inputs:
        raise UsageError("no input: give a TRACE (FILE.json or FILE.csv written by --trace), --sweep CSV, "
                        "--calibration CSV or --accuracy CSV")
    return args


def load_matplotlib():
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import numpy  # noqa: F401
    except ImportError as e:
        raise PlotError(f"{sys.executable} cannot import {e.name}: install Debian's python3-matplotlib and "
                        "python3-numpy (or point GCSIM_PYTHON at a python3 that has them)")
    plt.rcParams.update({"font.size": 10, "axes.titlesize": 10, "figure.autolayout": False})
    return plt


def make_out_dir(out):
    try:
        os.makedirs(out, exist_ok=True)
    except OSError as e:
        raise PlotError(f"--out {out}: cannot create the directory: {e.strerror}")


def plot_trace(args, plt):
    from gcsim_plots.trace_data import load_trace, Window
    from gcsim_plots.gantt import plot_gantt
    from gcsim_plots.mesh_heatmap import plot_mesh_heatmap
    from gcsim_plots.message_matrix import plot_message_matrix
    from gcsim_plots.utilization import plot_utilization

    started = time.monotonic()
    trace = load_trace(args.trace)
    window = Window(trace, args.from_ms, args.to_ms, args.procs)
    loaded = time.monotonic()
    from gcsim_plots.style import machine_line
    # Every plot's title block: the user's title (or the trace's name), then the machine, nodes and model.
    title = args.title or f"{os.path.basename(trace.path)}: trace level {trace.level}, {len(trace)} records"
    title = f"{title}\n{machine_line(trace, len(window.procs))}"
    wanted = PLOTS if not args.only else [p.strip() for p in args.only.split(",")]
    for name in wanted:
        if name not in PLOTS:
            raise UsageError(f"--only {args.only!r}: unknown plot {name!r} (expected some of {', '.join(PLOTS)})")
    make_out_dir(args.out)
    draw = {"gantt": plot_gantt, "mesh_heatmap": plot_mesh_heatmap, "message_matrix": plot_message_matrix,
            "utilization": plot_utilization}
    for name in wanted:
        path = os.path.join(args.out, name + ".png")
        began = time.monotonic()
        try:
            drawn = draw[name](plt, trace, window, title, path)
            if name == "utilization":
                write_shares(args.out, *drawn)
        except OSError as e:
            raise PlotError(f"cannot write {path}: {e.strerror}")
        print(f"wrote {path} ({time.monotonic() - began:.2f} s)")
    print(f"plotted {len(trace)} records in {time.monotonic() - started:.2f} s "
          f"(reading the trace {loaded - started:.2f} s)")


def write_shares(out, means, idle):
    """DIR/utilization.json: the mean shares of the utilization plot, for gcsim report's headline."""
    import json
    from gcsim_plots.activity_split import SHARES
    shares = {name: round(float(m), 3) for name, m in zip(SHARES, means)}
    shares["idle"] = round(float(idle), 3)
    shares["definition"] = "traces/README.md, Busy, communicating, waiting"
    with open(os.path.join(out, "utilization.json"), "w") as f:
        json.dump(shares, f, indent=1)


def plot_sweep(args, plt):
    from gcsim_plots.sweep_plot import plot_sweep as draw
    make_out_dir(args.out)
    stem = os.path.splitext(os.path.basename(args.sweep))[0]
    path = os.path.join(args.out, f"sweep_{stem}.png")
    try:
        draw(plt, args.sweep, path, args.title)
    except OSError as e:
        raise PlotError(f"cannot write {path}: {e.strerror}")
    print(f"wrote {path}")


def plot_table_csv(args, plt):
    from gcsim_plots.calibration import plot_accuracy, plot_calibration
    make_out_dir(args.out)
    source, kind, draw = ((args.calibration, "calibration", plot_calibration) if args.calibration
                          else (args.accuracy, "accuracy", plot_accuracy))
    stem = os.path.splitext(os.path.basename(source))[0]
    path = os.path.join(args.out, f"{kind}_{stem}.png")
    try:
        draw(plt, source, path, args.title)
    except OSError as e:
        raise PlotError(f"cannot write {path}: {e.strerror}")
    print(f"wrote {path}")


def main(argv):
    try:
        args = parse_args(argv)
        plt = load_matplotlib()
        if args.sweep:
            plot_sweep(args, plt)
        elif args.calibration or args.accuracy:
            plot_table_csv(args, plt)
        else:
            plot_trace(args, plt)
        return 0
    except UsageError as e:
        print(f"gcsim plot: error: {e}", file=sys.stderr)
        return 2
    except PlotError as e:  # an input file that cannot be read or is malformed, an output that cannot be written
        print(f"gcsim plot: error: {e}", file=sys.stderr)
        return 3
    except MemoryError:
        print("gcsim plot: error: out of memory reading the trace; plot a window (--from-ms/--to-ms) of a smaller "
              "trace, or rerun with --trace-level messages", file=sys.stderr)
        return 4
    except Exception as e:  # a bug: one line for the user, the traceback on request
        if os.environ.get("GCSIM_PLOT_DEBUG"):
            raise
        print(f"gcsim plot: internal error: {type(e).__name__}: {e} (GCSIM_PLOT_DEBUG=1 shows where)", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
