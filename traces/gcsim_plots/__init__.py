"""Plots of gcsim traces and sweeps (gcsim plot, gcsim report). See traces/README.md."""
