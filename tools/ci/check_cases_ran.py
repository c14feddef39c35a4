#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""After a full ctest run: every Catch2 case each test binary lists ran.

Usage: check_cases_ran.py <build-dir>

<build-dir>/catch_cases/listed/<binary>.list holds what the binary's
--list-test-names-only printed at build time; <build-dir>/catch_cases/ran/
<binary>.log holds the name of every case a CTest run executed (the
listener in tests/support/catch_main.cpp). Exit 1, naming the cases, when a
listed case never ran or ran more than once; prints the counts otherwise.
"""
import collections
import pathlib
import sys


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    root = pathlib.Path(sys.argv[1]) / "catch_cases"
    lists = sorted((root / "listed").glob("*.list"))
    if not lists:
        print(f"check_cases_ran: no listings under {root / 'listed'}", file=sys.stderr)
        return 1
    ok = True
    total_listed = total_ran = 0
    for listing in lists:
        binary = listing.stem
        listed = [n for n in listing.read_text(encoding="utf-8").split("\n") if n]
        log = root / "ran" / f"{binary}.log"
        ran = [n for n in log.read_text(encoding="utf-8").split("\n") if n] if log.exists() else []
        counts = collections.Counter(ran)
        missing = [n for n in listed if n not in counts]
        repeated = sorted(n for n, c in counts.items() if c > 1)
        unknown = sorted(set(counts) - set(listed))
        total_listed += len(listed)
        total_ran += len(counts)
        print(f"{binary}: listed {len(listed)}, ran {len(counts)}")
        for label, names in (("never ran", missing), ("ran more than once", repeated),
                             ("ran but not listed", unknown)):
            for n in names:
                ok = False
                print(f"  {label}: {n}")
    print(f"check_cases_ran: listed {total_listed}, ran {total_ran}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
