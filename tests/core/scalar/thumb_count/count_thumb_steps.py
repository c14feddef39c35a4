#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Thumb instructions per tracker step on the Cortex-M0+ code generation.

Builds step_count_armv6m.cpp with the board's flags (arm-none-eabi-g++,
-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft -Os, newlib-nano), runs it
under qemu-arm's Linux user mode with one instruction per translation
block and no chaining (-singlestep -d nochain,exec: one log line per
executed instruction; Debian's QEMU 7.2 has no TCG plugins), reads the log
through a FIFO and counts the lines between each call of
kestrel_count_begin() and kestrel_count_end(). Prints every measured step
and the median, minimum and maximum per class.

  python3 tests/core/scalar/thumb_count/count_thumb_steps.py [--out DIR]
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "..", ".."))
FLAGS = ["-mcpu=cortex-m0plus", "-mthumb", "-mfloat-abi=soft", "-Os", "-std=c++20", "-fno-exceptions",
         "-fno-rtti", "-DEIGEN_NO_MALLOC", "-nostartfiles", "--specs=nano.specs"]
# The log counter: C, because the log has a line per instruction.
COUNTER = r"""
#include <stdio.h>
#include <string.h>
int main(void) {
  static char line[4096];
  unsigned long long n = 0;
  int inside = 0;
  while (fgets(line, sizeof line, stdin)) {
    if (inside) {
      ++n;
      if (strstr(line, " kestrel_count_end\n")) { printf("%llu\n", n); inside = 0; }
    } else if (strstr(line, " kestrel_count_begin\n")) {
      inside = 1;
      n = 0;
    }
  }
  return 0;
}
"""


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=None, help="directory for the ELF (default: a temporary one)")
    ap.add_argument("--cxx", default="arm-none-eabi-g++")
    ap.add_argument("--qemu", default="qemu-arm")
    ap.add_argument("--root", default=ROOT, help="source tree whose core/hal headers are built (default: this one)")
    args = ap.parse_args()
    out = args.out or tempfile.mkdtemp(prefix="kestrel-thumb-")
    os.makedirs(out, exist_ok=True)
    elf = os.path.join(out, "step_count_m0plus.elf")
    src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "step_count_armv6m.cpp")
    includes = ["-I" + os.path.join(os.path.abspath(args.root), d) for d in ("core/include", "hal/include")] + \
               ["-I" + os.path.join(ROOT, "tests"), "-isystem", "/usr/include/eigen3"]
    build = [args.cxx] + FLAGS + includes + [src, "-o", elf]
    print("$ " + " ".join(build), flush=True)
    subprocess.run(build, check=True)
    fifo = os.path.join(out, "exec.fifo")
    if os.path.exists(fifo):
        os.unlink(fifo)
    os.mkfifo(fifo)
    run = [args.qemu, "-singlestep", "-d", "nochain,exec", "-D", fifo, elf]
    print("$ " + " ".join(run), flush=True)
    counter = os.path.join(out, "count_lines")
    subprocess.run(["cc", "-O2", "-x", "c", "-", "-o", counter], input=COUNTER, text=True, check=True)
    reader = subprocess.Popen("%s < %s" % (counter, fifo), shell=True, stdout=subprocess.PIPE, text=True)
    proc = subprocess.run(run, capture_output=True, text=True)
    counts = [int(v) for v in reader.communicate()[0].split()]
    sys.stdout.write(proc.stdout)
    if proc.returncode != 0:
        sys.stderr.write(proc.stderr)
        sys.exit("step_count program failed (exit %d)" % proc.returncode)
    flags = next((l.split(":")[1].strip() for l in proc.stdout.splitlines() if l.startswith("normal flags:")), "")
    if len(counts) != len(flags) + 1:
        sys.exit("expected %d measured steps, found %d" % (len(flags) + 1, len(counts)))
    normal = [c for c, f in zip(counts, flags) if f == "1"]
    for name, c in (("normal (S1 seed 1, the normal steps of 10..29)", normal),
                    ("full frame (8 tracks x 32 plots)", counts[-1:])):
        print("%s: median %d, min %d, max %d Thumb instructions per step (%d steps)" %
              (name, statistics.median(c), min(c), max(c), len(c)))
        print("  " + " ".join(str(v) for v in c))

if __name__ == "__main__":
    main()
