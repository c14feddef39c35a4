#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""footprint_doc_matches_build: the generated tables of docs/footprint.md
(sizes, stack of step, main stack, deepest chains) must be what the board
images built by this CTest run measure (the evidence JSON their post-link
steps wrote). A difference fails with a diff and the command that rewrites
the document; with KESTREL_UPDATE_FOOTPRINT=1 in the environment the test
rewrites docs/footprint.md instead, so

    KESTREL_UPDATE_FOOTPRINT=1 ctest --preset host-release -L boards

is the same command CI runs, regenerating what it checks. The test also
proves the check can fail: a copy of the document with one figure changed
must be refused.

usage: footprint_doc_test.py <footprint_table.py> <docs/footprint.md> <evidence dir>...
exit: 0 pass, 1 fail, 77 skip (a board tree has no evidence: its compiler is missing).
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile


def main():
    table, doc, dirs = sys.argv[1], sys.argv[2], sys.argv[3:]
    missing = [d for d in dirs if not os.path.isdir(d) or not any(f.endswith(".size.json") for f in os.listdir(d))]
    if missing:
        print("SKIP: no board evidence in " + ", ".join(missing) + " (board compiler missing, or its image test did not run)")
        return 77
    if os.environ.get("KESTREL_UPDATE_FOOTPRINT") == "1":
        subprocess.run([sys.executable, table, "--doc", doc] + dirs, check=True)
        print("KESTREL_UPDATE_FOOTPRINT=1: %s rewritten from %s" % (doc, " ".join(dirs)))
        return 0

    # The check must be able to fail: change one figure of a copy.
    with tempfile.TemporaryDirectory() as tmp:
        probe = os.path.join(tmp, "footprint.md")
        shutil.copy(doc, probe)
        with open(probe) as f:
            text = f.read()
        start = text.index("<!-- evidence:sizes -->")
        m = re.compile(r"\| (\d+) / ").search(text, start)
        if not m:
            print("FAIL: no 'value / budget' figure in the sizes table of " + doc)
            return 1
        text = text[:m.start(1)] + str(int(m.group(1)) + 1) + text[m.end(1):]
        with open(probe, "w") as f:
            f.write(text)
        r = subprocess.run([sys.executable, table, "--doc", probe, "--check"] + dirs, capture_output=True, text=True)
        if r.returncode != 1:
            print(r.stdout, r.stderr)
            print("FAIL: footprint_table.py --check accepted a document with a changed figure")
            return 1
        print("footprint_table.py --check refuses a document with one figure changed")

    r = subprocess.run([sys.executable, table, "--doc", doc, "--check"] + dirs)
    return 0 if r.returncode == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
