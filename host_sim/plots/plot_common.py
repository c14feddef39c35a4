# SPDX-License-Identifier: Apache-2.0
"""What every kestrel-sim plot script shares: matplotlib without a display,
the CSV files kestrel-sim writes, and how a figure is saved."""
import csv
import math
import os
import sys


def load_matplotlib():
    """pyplot on the Agg backend (files only). Without matplotlib the figures
    cannot be drawn: a warning and exit status 1, so that kestrel-sim never
    reports a figure it did not write (the numbers are in the CSV files)."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        return plt
    except ImportError as e:
        print(f"warning: matplotlib not available ({e}); no figures", file=sys.stderr)
        sys.exit(1)


def number(cell):
    """A float, or NaN for an empty cell."""
    return float(cell) if cell not in ("", None) else math.nan


def read_rows(path, missing_ok=False):
    """The rows of a CSV file as dicts by column name ([] for a missing file
    when missing_ok)."""
    if missing_ok and not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def save_figure(plt, fig, path, dpi=120):
    """Lay out, write and close `fig`."""
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
