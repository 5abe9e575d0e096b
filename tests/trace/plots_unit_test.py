#!/usr/bin/env python3
"""Properties of the plotting package (traces/gcsim_plots) that a user reads off the PNGs: the
speedup panel's ideal line is straight and every series stays in the frame, overlays look unlike
gcsim's series, the utilization's shares add up to 100 %, waiting is told apart from moving bytes,
a long timeline picks seconds and zooms in. Run by CTest (trace_plots_unit); plain unittest."""

import os
import re
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "traces"))

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from gcsim_plots import activity_split, gantt, style, sweep, sweep_plot, utilization  # noqa: E402
from gcsim_plots.trace_data import KIND_CODE, Trace, Window  # noqa: E402

PS = 1e9  # picoseconds per millisecond

RAYTRACE_CSV = """nodes,simulated_s,speedup,efficiency,comm_s_mean,compute_s_mean,wall_s
1,10.0,1.0,1.0,0.0,10.0,5.0
2,5.05,1.98,0.99,2.5,2.5,5.1
4,2.6,3.85,0.96,0.8,2.0,5.1
8,1.35,7.4,0.93,0.4,1.1,5.1
16,0.72,13.9,0.87,0.2,0.6,5.1
"""
RADIOSITY_CSV = """# gcsim sweep radiosity; scene CORNELL; machine Parsytec GC-PowerPlus 64 nodes (as published); model analytic
nodes,simulated_s,speedup,comm_s,wall_s,loops,thesis_s,thesis_speedup,thesis_comm_s
1,250.5,1.0,0.0,3.2,151,289,1.0000,
2,210.1,1.19,21.0,2.1,151,236,1.2246,25
4,170.2,1.47,41.0,1.5,151,180,1.6056,40
8,140.2,1.78,61.0,1.5,151,150,1.9,66
"""


def write(directory, name, text):
    path = os.path.join(directory, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def make_trace(path, records, processors=2, width=2, height=1):
    """records: (kind, proc, peer, start_ms, end_ms, bytes, thread)."""
    kind = np.array([KIND_CODE[r[0]] for r in records], dtype=np.int8)
    col = lambda i, t: np.array([r[i] for r in records], dtype=t)  # noqa: E731
    return Trace(path, "messages", processors, width, height, kind, col(1, np.int32), col(2, np.int32),
                 col(3, np.float64) * PS, col(4, np.float64) * PS, col(5, np.int64),
                 np.arange(len(records), dtype=np.int64), col(6, np.int32))


def lines_of(ax):
    return [(line.get_label(), np.asarray(line.get_xdata(), float), np.asarray(line.get_ydata(), float), line)
            for line in ax.get_lines()]


class SweepPlot(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()
        plt.close("all")

    def speedup_axes(self, name, text):
        fig, _ = sweep_plot.draw_sweep(plt, write(self.tmp.name, name, text))
        return fig, fig.axes[1]

    def test_ideal_is_straight_in_the_speedup_panel(self):
        _, ax = self.speedup_axes("ray.csv", RAYTRACE_CSV)
        self.assertEqual(ax.get_xscale(), "log")
        self.assertEqual(ax.get_yscale(), "log")
        (_, x, y, _), = [entry for entry in lines_of(ax) if entry[0].startswith("ideal")]
        slopes = np.diff(np.log(y)) / np.diff(np.log(x))
        self.assertTrue(np.allclose(slopes, slopes[0]), f"ideal bends: slopes {slopes}")

    def test_every_series_stays_inside_every_panel(self):
        for name, text in (("ray.csv", RAYTRACE_CSV), ("cornell.csv", RADIOSITY_CSV)):
            fig, _ = self.speedup_axes(name, text)
            for ax in fig.axes:
                x0, x1 = sorted(ax.get_xlim())
                y0, y1 = sorted(ax.get_ylim())
                for label, x, y, _ in lines_of(ax):
                    ok = np.isfinite(y)
                    self.assertTrue(((x[ok] >= x0) & (x[ok] <= x1)).all(), f"{name}: {label} leaves {ax.get_title()!r} in x")
                    self.assertTrue(((y[ok] >= y0) & (y[ok] <= y1)).all(),
                                    f"{name}: {label} leaves {ax.get_title()!r} in y: {y} outside {y0}..{y1}")

    def test_thesis_overlay_differs_in_colour_and_marker(self):
        _, ax = self.speedup_axes("cornell.csv", RADIOSITY_CSV)
        by_label = {label: line for label, _, _, line in lines_of(ax)}
        ours, thesis = by_label["gcsim simulated"], by_label["thesis measured"]
        self.assertNotEqual(matplotlib.colors.to_hex(ours.get_color()), matplotlib.colors.to_hex(thesis.get_color()))
        self.assertNotEqual(ours.get_marker(), thesis.get_marker())

    def test_title_names_app_scene_and_machine(self):
        fig, _ = self.speedup_axes("cornell.csv", RADIOSITY_CSV)
        title = fig._suptitle.get_text()
        for word in ("radiosity", "CORNELL", "GC-PowerPlus", "analytic"):
            self.assertIn(word, title)
        self.assertNotIn("cornell.csv", title)

    def test_old_csv_without_comment_rows_still_reads(self):
        path = write(self.tmp.name, "old.csv", RADIOSITY_CSV.split("\n", 1)[1])
        self.assertEqual(sweep.read_meta(path), {})
        self.assertEqual(len(sweep.read_sweep(path)["nodes"]), 4)
        fig, _ = sweep_plot.draw_sweep(plt, path)
        self.assertIn("old.csv", fig._suptitle.get_text())
        self.assertIn("not recorded", fig._suptitle.get_text())


class Split(unittest.TestCase):
    """P0 serves: blocked in recv from P1 over [0, 10] ms while P1 computes until 8 ms and then sends
    (the message arrives at 10). P0 has a thread that computes over [0, 10] beside it."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        path = os.path.join(self.tmp.name, "t.csv")
        self.records = [("recv", 0, 1, 0, 10, 64, 0), ("compute", 1, -1, 0, 8, 0, 0), ("send", 1, 0, 8, 10, 0, 0),
                        ("message", 1, 0, 8, 10, 64, 0), ("compute", 1, -1, 10, 20, 0, 0)]
        self.trace = make_trace(path, self.records)

    def tearDown(self):
        self.tmp.cleanup()
        plt.close("all")

    def test_waiting_for_the_sender_is_not_communication(self):
        proc, start, end, share = activity_split.split_intervals(self.trace)
        length = lambda p, s: float(((end - start) * ((proc == p) & (share == s))).sum())  # noqa: E731
        self.assertAlmostEqual(length(0, activity_split.WAITING), 8.0)
        self.assertAlmostEqual(length(0, activity_split.COMMUNICATING), 2.0)
        self.assertAlmostEqual(length(1, activity_split.BUSY), 18.0)
        self.assertAlmostEqual(length(1, activity_split.COMMUNICATING), 2.0)

    def test_shares_add_up_to_100_with_overlapping_threads(self):
        trace = make_trace(self.trace.path, self.records + [("compute", 0, -1, 0, 10, 0, 1)])
        window = Window(trace, None, None, None)
        path = os.path.join(self.tmp.name, "u.png")
        means, idle = utilization.plot_utilization(plt, trace, window, "test", path)
        self.assertAlmostEqual(float(means.sum() + idle), 100.0, delta=0.5)
        self.assertGreaterEqual(idle, -1e-9)
        _, share, _, _ = utilization.utilization_shares(trace, window)
        self.assertLessEqual(float(share.sum(axis=0).max()), 100.0 + 1e-6)

    def test_title_shares_sum_to_100(self):
        window = Window(self.trace, None, None, None)
        means, idle = utilization.utilization_shares(self.trace, window)[2:]
        text = utilization.summary_text(means, idle)
        shown = [float(v) for v in re.findall(r"(\d+(?:\.\d+)?)%", text)]
        self.assertEqual(len(shown), 4, text)
        self.assertAlmostEqual(sum(shown), 100.0, delta=0.5)
        # P0 waits 8 of its 20 ms, so waiting is 8 / 40 of all processor time.
        self.assertAlmostEqual(float(means[activity_split.WAITING]), 20.0, delta=100.0 / utilization.BINS)


class LongTimeline(unittest.TestCase):
    def test_time_unit_follows_the_span(self):
        self.assertEqual(style.time_unit(0.5)[1], "\u00b5s")
        self.assertEqual(style.time_unit(500.0)[1], "ms")
        self.assertEqual(style.time_unit(80000.0)[1], "s")

    def test_80_seconds_of_short_events_draw_as_density_with_a_zoom(self):
        with tempfile.TemporaryDirectory() as tmp:
            n, period = 40000, 2.0  # 40,000 intervals of 0.5 ms every 2 ms on each of 2 processors: 80 s
            starts = np.arange(n) * period
            records = [("compute", p, -1, s, s + 0.5, 0, 0) for p in (0, 1) for s in starts]
            trace = make_trace(os.path.join(tmp, "t.csv"), records)
            window = Window(trace, None, None, None)
            drawn = gantt.plot_gantt(plt, trace, window, "test", os.path.join(tmp, "g.png"))
            self.assertTrue(drawn["dense"])
            self.assertEqual(drawn["unit"], "s")
            z0, z1 = drawn["zoom"]
            self.assertTrue(window.t0 <= z0 < z1 <= window.t1)
            self.assertLess(z1 - z0, window.length / 10 + 1e-9)
            self.assertGreater(z1 - z0, 10 * period)  # several events, not a sliver of one

    def test_a_short_trace_draws_every_interval(self):
        with tempfile.TemporaryDirectory() as tmp:
            trace = make_trace(os.path.join(tmp, "t.csv"), [("compute", 0, -1, 0, 1, 0, 0), ("compute", 1, -1, 0, 2, 0, 0)])
            drawn = gantt.plot_gantt(plt, trace, Window(trace, None, None, None), "test", os.path.join(tmp, "g.png"))
            self.assertFalse(drawn["dense"])
            self.assertEqual(drawn["unit"], "ms")


class MachineLine(unittest.TestCase):
    def test_machine_and_model_come_from_the_chrome_json(self):
        with tempfile.TemporaryDirectory() as tmp:
            write(tmp, "t.json", '[\n{"ph":"M","pid":0,"name":"process_name","args":{"name":"processors"}},\n'
                                 '{"ph":"M","pid":0,"name":"process_labels","args":{"labels":"GC, network model flow"}},\n')
            trace = make_trace(os.path.join(tmp, "t.csv"), [("compute", 0, -1, 0, 1, 0, 0)])
            self.assertEqual(trace.machine, "GC, network model flow")
            line = style.machine_line(trace)
            self.assertIn("network model flow", line)
            self.assertIn("2 nodes", line)
            bare = make_trace(os.path.join(tmp, "other.csv"), [("compute", 0, -1, 0, 1, 0, 0)])
            self.assertIn("not recorded", style.machine_line(bare))


class NodePositions(unittest.TestCase):
    def test_positions_come_from_the_trace_else_row_major(self):
        with tempfile.TemporaryDirectory() as tmp:
            # An interconnect whose coordinates are not row-major: node 1 sits below node 0.
            write(tmp, "t.json", '[\n{"ph":"M","pid":0,"name":"process_name","args":{"name":"processors"}}'
                                 ',\n{"ph":"M","pid":0,"tid":0,"name":"thread_name","args":{"name":"P0 node (0,0)"}}'
                                 ',\n{"ph":"M","pid":0,"tid":1,"name":"thread_name","args":{"name":"P1 node (0,1)"}}'
                                 ',\n{"ph":"X","pid":0,"tid":1,"name":"thread_name","args":{"name":"P2 node (5,5)"}}\n')
            trace = make_trace(os.path.join(tmp, "t.csv"), [("compute", 0, -1, 0, 1, 0, 0)], width=2, height=2)
            self.assertEqual(trace.node_xy(1), (0, 1))
            self.assertEqual(gantt.row_labels(trace, [0, 1]), ["P0 (0,0)", "P1 (0,1)"])
            self.assertEqual(trace.node_xy(2), (0, 1))  # a record, not metadata: not read; row-major
            old = make_trace(os.path.join(tmp, "old.csv"), [("compute", 0, -1, 0, 1, 0, 0)], width=2, height=2)
            self.assertEqual(old.node_xy(1), (1, 0))
            self.assertEqual(old.node_xy(3), (1, 1))


if __name__ == "__main__":
    unittest.main(verbosity=2)
