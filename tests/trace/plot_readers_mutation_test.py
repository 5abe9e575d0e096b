#!/usr/bin/env python3
"""The plotting package's CSV readers on malformed input: valid files (a sweep CSV, a table CSV,
a trace CSV) mutated at random with a fixed seed (bytes flipped, lines cut, cut short, doubled,
fields made huge, numbers made infinite, negative or enormous, text that is not UTF-8). Each
reader must return or raise PlotError naming the file; any other exception is what gcsim plot
would have shown as a traceback (python3-hypothesis is not installed; this is its seeded
stand-in). Run by CTest (trace_plot_readers_mutation)."""

import os
import random
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "traces"))

from gcsim_plots import sweep, table_csv, trace_data  # noqa: E402
from gcsim_plots.calibration import CALIBRATION_COLUMNS  # noqa: E402
from gcsim_plots.errors import PlotError  # noqa: E402

SWEEP = (b"# gcsim sweep raytrace; scene CORNELL; machine GC; model analytic\n"
         b"nodes,simulated_s,speedup,comm_s,wall_s\n1,10.0,1.0,0.0,5.0\n2,5.05,1.98,2.5,5.1\n4,2.6,3.85,0.8,5.1\n")
TABLE = (b"table,nodes,case,measured,predicted,error,fitted\n4.6,2,1 KB,1.5,1.4,-0.06,yes\n"
         b"4.6,4,1 KB,2.5,2.6,0.04,no\n4.7,8,16 KB,9.0,8.1,-0.1,yes\n")
with open(os.path.join(HERE, "..", "..", "traces", "samples", "bcast16_tree.csv"), "rb") as f:
    TRACE = b"".join(f.readlines()[:40])

HOSTILE_FIELDS = [b"1e309", b"-1e309", b"nan", b"-1", b"99999999999999999999999999", b"", b"\xff\xfe",
                  b'"' + b"x" * 200000 + b'"', b"0x10", b"1,2,3,4,5,6,7,8,9", b"\x00"]


def mutate(data, rng):
    """One to four random edits of `data`."""
    data = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        kind = rng.randrange(7)
        lines = bytes(data).split(b"\n")
        if kind == 0 and data:  # flip a byte
            data[rng.randrange(len(data))] = rng.randrange(256)
        elif kind == 1:  # cut the file short
            del data[rng.randrange(len(data) + 1):]
        elif kind == 2 and len(lines) > 1:  # drop or double a line
            i = rng.randrange(len(lines))
            lines[i:i + 1] = [] if rng.random() < 0.5 else [lines[i], lines[i]]
            data = bytearray(b"\n".join(lines))
        elif kind in (3, 4) and lines:  # a field made hostile
            i = rng.randrange(len(lines))
            fields = lines[i].split(b",")
            fields[rng.randrange(len(fields))] = rng.choice(HOSTILE_FIELDS)
            lines[i] = b",".join(fields)
            data = bytearray(b"\n".join(lines))
        elif kind == 5 and lines:  # commas removed or added
            i = rng.randrange(len(lines))
            lines[i] = lines[i].replace(b",", b"") if rng.random() < 0.5 else lines[i] + b",,"
            data = bytearray(b"\n".join(lines))
        elif kind == 6:  # bytes that are not UTF-8
            at = rng.randrange(len(data) + 1)
            data[at:at] = bytes(rng.randrange(128, 256) for _ in range(rng.randint(1, 8)))
    return bytes(data)


class MutatedReaders(unittest.TestCase):
    def run_reader(self, seed_bytes, suffix, read, rounds=1500, seed=20261201):
        rng = random.Random(seed)
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "input" + suffix)
            for n in range(rounds):
                data = mutate(seed_bytes, rng)
                with open(path, "wb") as f:
                    f.write(data)
                try:
                    read(path)
                except PlotError as e:
                    self.assertIn(path, str(e), f"round {n}: the error does not name the file")
                    self.assertLess(len(str(e)), 600, f"round {n}: the error is {len(str(e))} characters")
                except Exception as e:  # noqa: BLE001 - the property: nothing else escapes
                    self.fail(f"round {n}: {type(e).__name__}: {e!s:.200} on input {data[:120]!r}")

    def test_the_unmutated_files_read(self):
        for data, suffix, read in ((SWEEP, ".csv", sweep.read_sweep), (TRACE, ".csv", trace_data.load_trace),
                                   (TABLE, ".csv", lambda p: table_csv.read_rows(p, CALIBRATION_COLUMNS))):
            with tempfile.TemporaryDirectory() as d:
                path = os.path.join(d, "input" + suffix)
                with open(path, "wb") as f:
                    f.write(data)
                read(path)  # raises on a reader that refuses good input

    def test_sweep_reader(self):
        self.run_reader(SWEEP, ".csv", lambda p: (sweep.read_sweep(p), sweep.read_meta(p)))

    def test_table_reader(self):
        def read(p):
            for line, row in enumerate(table_csv.read_rows(p, CALIBRATION_COLUMNS), start=2):
                for key in ("measured", "predicted"):
                    table_csv.number(row, key, p, line)
        self.run_reader(TABLE, ".csv", read)

    def test_trace_reader(self):
        self.run_reader(TRACE, ".csv", trace_data.load_trace)


if __name__ == "__main__":
    unittest.main()
