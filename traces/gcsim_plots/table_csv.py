"""Reads the CSVs of gcsim's table commands (calibrate/validate, accuracy network/media/render --csv):
rows as dicts, with the expected columns checked and bad cells reported as PlotError."""

import csv

from gcsim_plots.errors import PlotError


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
        return float(row[key])
    except (TypeError, ValueError):
        raise PlotError(f"{path}:{line}: column {key!r} is {row[key]!r}, not a number")
