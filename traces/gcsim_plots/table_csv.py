"""Reads the CSVs of gcsim's table commands (calibrate/validate, accuracy network/media/render --csv):
rows as dicts, with the expected columns checked and bad cells reported as PlotError."""

import csv
import math

from gcsim_plots.errors import PlotError, reads_file


@reads_file("table CSV")
def read_rows(path, columns):
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        raise PlotError(f"{path}: cannot read: {e.strerror}")
    except (UnicodeDecodeError, csv.Error) as e:
        raise PlotError(f"{path}: not a CSV file ({e})")
    if not rows:
        raise PlotError(f"{path}: no rows (expected a header {','.join(columns)} and rows)")
    missing = [c for c in columns if c not in rows[0]]
    if missing:
        raise PlotError(f"{path}: missing column(s) {', '.join(missing)} (expected {','.join(columns)})")
    return rows


def number(row, key, path, line):
    try:
        value = float(row[key])
    except (TypeError, ValueError, KeyError):
        raise PlotError(f"{path}:{line}: column {key!r} is {str(row.get(key))[:40]!r}, not a number") from None
    if not math.isfinite(value) or abs(value) > 1e100:
        raise PlotError(f"{path}:{line}: column {key!r} is {row[key][:40]!r}, not a finite number of plausible size")
    return value
