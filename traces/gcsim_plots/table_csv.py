"""Reads the CSVs of gcsim's table commands (calibrate/validate, accuracy network/media/render --csv):
rows as dicts, with the expected columns checked and bad cells reported as PlotError. A first row
'# gcsim COMMAND; machine M; nodes N; model X' names what wrote the file (csv_machine_line)."""

import csv
import math
import textwrap

from gcsim_plots.errors import PlotError, reads_file


def _data_lines(f):
    """The file's lines without its '#' comment rows, each with its line number."""
    for number_, line in enumerate(f, start=1):
        if not line.startswith("#"):
            yield number_, line


def first_data_line(path):
    """The header: the first line that is not a '#' comment."""
    with open(path, newline="") as f:
        return next((line for _, line in _data_lines(f)), "")


def csv_machine_line(path, width_inches=None):
    """The subtitle naming the machine, node count and network model, from the comment row; wrapped
    to a figure width_inches wide (at a 9-point font) when given."""
    line = _machine_line(path)
    return line if width_inches is None else "\n".join(textwrap.wrap(line, max(30, int(width_inches * 13))))


def _machine_line(path):
    fields = {}
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                if line.startswith("# gcsim "):
                    for part in line[1:].strip().split(";")[1:]:
                        key, _, value = part.strip().partition(" ")
                        fields[key] = value.strip()
                    break
    except OSError:
        pass
    if "machine" not in fields:
        return "machine, node count and network model not recorded in this CSV (written before gcsim named them)"
    return f"{fields['machine']}; nodes {fields.get('nodes', '?')}; network model {fields.get('model', '?')}"


@reads_file("table CSV")
def read_rows(path, columns):
    try:
        with open(path, newline="") as f:
            numbered = list(_data_lines(f))
            rows = list(csv.DictReader(line for _, line in numbered))
            for row, (line_number, _) in zip(rows, numbered[1:]):
                row["_line"] = line_number
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
    line = row.get("_line", line)  # the file's own line, comment rows counted
    try:
        value = float(row[key])
    except (TypeError, ValueError, KeyError):
        raise PlotError(f"{path}:{line}: column {key!r} is {str(row.get(key))[:40]!r}, not a number") from None
    if not math.isfinite(value) or abs(value) > 1e100:
        raise PlotError(f"{path}:{line}: column {key!r} is {row[key][:40]!r}, not a finite number of plausible size")
    return value
