"""The exceptions the plotting code raises for bad input; plot_trace.py prints them without a traceback.

PlotError: an input file cannot be read or is malformed (gcsim's exit status 3). UsageError: an
option is wrong (status 2). `reads_file` makes a reader's unexpected exceptions on malformed data
(a bad encoding, a short row, a huge field or number) a PlotError naming the file."""
import csv
import functools
import os
import re


def shorten_long_words(text, longest=120, kept=80):
    """Messages echo what they read; a field of megabytes would be echoed whole. Words longer than
    `longest` keep their first `kept` characters and say how long they were (as gcsim's errors do)."""
    return re.sub(r"\S{%d,}" % (longest + 1), lambda m: f"{m.group(0)[:kept]}... ({len(m.group(0))} characters)", text)


class PlotError(Exception):
    """Bad input file: the message names the file (and the line where known) and says what was expected."""

    def __init__(self, message):
        super().__init__(shorten_long_words(str(message)))


class UsageError(PlotError):
    """A bad option value or combination: the message names the option."""


# What malformed data makes Python's csv, float() and numpy raise; a bug raises something else.
MALFORMED = (UnicodeError, ValueError, IndexError, KeyError, TypeError, OverflowError, ArithmeticError, csv.Error)


def reads_file(what):
    """Decorates a reader whose first argument is the path: malformed data becomes one PlotError
    '{path}: not a valid {what} (...)' instead of a traceback."""
    def decorate(reader):
        @functools.wraps(reader)
        def wrapped(path, *args, **kwargs):
            if os.path.exists(path) and not os.path.isfile(path):  # a FIFO would block, a device never end
                raise PlotError(f"{path}: is not a regular file (a directory, a device or a FIFO)")
            try:
                return reader(path, *args, **kwargs)
            except PlotError:
                raise
            except MALFORMED as e:
                detail = str(e).splitlines()[0][:120] if str(e) else type(e).__name__
                raise PlotError(f"{path}: not a valid {what} ({detail})") from None
        return wrapped
    return decorate


def checked_csv_rows(path, lines):
    """csv.reader over `lines` that names the line of a csv error (e.g. a field over the limit)."""
    reader = csv.reader(lines)
    rows = []
    try:
        for row in reader:
            rows.append(row)
    except csv.Error as e:
        raise PlotError(f"{path}:{reader.line_num}: not a CSV line ({e})") from None
    return rows
