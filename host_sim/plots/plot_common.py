# SPDX-License-Identifier: Apache-2.0
"""What every kestrel-sim plot script shares: matplotlib without a display."""
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
