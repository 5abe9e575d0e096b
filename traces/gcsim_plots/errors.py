"""The one exception the plotting code raises for bad input; plot_trace.py prints it without a traceback."""


class PlotError(Exception):
    """Bad input: the message names the file and says what was expected."""
