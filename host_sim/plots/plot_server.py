#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Draws the figures of one kestrel-sim command in one Python process.

kestrel-sim (plots/plot_runner.cpp) starts this once and sends one job per
line on stdin: a JSON array, the script's path and then its arguments. The
script runs as its own __main__, as from a shell; its exit status (0 when it
returns normally) goes back as one line on file descriptor 3. matplotlib's
import, about a second, is paid once per command instead of once per figure.
"""
import json
import os
import runpy
import sys
import traceback

from plot_common import load_matplotlib


def run(job):
    sys.argv = list(job)
    sys.path[0] = os.path.dirname(os.path.abspath(job[0]))  # as when run from a shell
    try:
        runpy.run_path(job[0], run_name="__main__")
        return 0
    except SystemExit as e:
        if e.code is None:
            return 0
        return e.code if isinstance(e.code, int) else 1
    except Exception:  # a script's bug fails its own figure, not the others
        traceback.print_exc()
        return 1


def main():
    replies = os.fdopen(3, "w", buffering=1)
    plt = load_matplotlib()
    for line in sys.stdin:
        status = run(json.loads(line))
        plt.close("all")
        sys.stdout.flush()
        sys.stderr.flush()
        replies.write(f"{status}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
