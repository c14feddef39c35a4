#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Worst-case stack depth of a board image's call chains (docs/footprint.md).

Inputs:
  * the .ci files GCC writes with -fcallgraph-info=su beside each object
    (each board's image.cmake): one node per function emitted, with its
    frame size ("N bytes (static)"; "dynamic" if it uses alloca/VLAs) and one
    edge per call site that survived inlining;
  * the linked ELF, disassembled with objdump, for the functions no .ci
    describes (libm, libc, libgcc's soft-float helpers). ARM (Thumb-2):
    frame = push + vpush + "sub sp, #N" of the prologue, callees = bl/b.w
    targets. RISC-V: frame = the "addi sp,sp,-N" (or "li t, N; sub sp,sp,t")
    of the prologue, callees = jal/jalr/call targets, tail calls = j/jr/tail
    to another function.

For each root the script walks every call path (Kestrel's own functions
must not recurse: that is an error, as SPEC section 1 forbids it; a C
library routine that calls itself is counted one extra level deep, with a
note) and prints
the deepest one with the frame of each function on it. The sum is the stack
the chain needs below the caller's SP; a function's frame includes the
registers it saves and its locals, and a call adds nothing else on ARM or
RISC-V (the return address is in LR/ra, saved by the callee's prologue and
so counted in its frame).

Budget: with --budget N the worst chain from the roots matching
--budget-root (default: Tracker<...>::step) must be at most N bytes, or the
script exits 1 (and with --reject renames the ELF to <elf>.rejected, so the
failure repeats on the next build, as the size and symbol checks do).

Usage (each board wires it as a post-link step and a <image>-stack-report target):
  stack_report.py --elf kestrel-m4f.elf --objdump arm-none-eabi-objdump \
                  --ci-dir <object dir> [--ci-dir ...] [--root REGEX ...] [--out stack.txt]
                  [--budget BYTES [--budget-root REGEX]] [--json stack.json] [--reject]
"""

import argparse
import json
import os
import re
import subprocess
import sys

STEP_ROOT = r"kestrel::Tracker<.*>::step\("
DEFAULT_ROOTS = [
    STEP_ROOT,
    r"^kestrel::[a-z0-9_]+::firmware_main\(\)$",
    r"_IRQHandler$",
    r"^Reset_Handler$",
    r"^_GLOBAL__sub_I_",
]

NODE_RE = re.compile(r'^node: \{ title: "([^"]*)" label: "([^"]*)"')
EDGE_RE = re.compile(r'^edge: \{ sourcename: "([^"]*)" targetname: "([^"]*)"')
FRAME_RE = re.compile(r"(\d+) bytes \(([a-z, ]+)\)")


def symbol_of(title):
    """'/path/file.cpp:_Z...' -> '_Z...'; a bare external name stays as is."""
    return title.rsplit(":", 1)[1] if ":" in title and title.startswith("/") else title


def load_ci(ci_dirs):
    nodes = {}   # title -> (frame bytes, qualifier)
    edges = {}   # title -> set of target titles
    walk = [entry for d in ci_dirs for entry in os.walk(d)]
    for root, _dirs, files in walk:
        for name in files:
            if not name.endswith(".ci"):
                continue
            with open(os.path.join(root, name), encoding="utf-8", errors="replace") as f:
                for line in f:
                    m = NODE_RE.match(line)
                    if m:
                        fm = FRAME_RE.search(m.group(2))
                        if fm:  # a defined function (externals have no frame)
                            nodes[m.group(1)] = (int(fm.group(1)), fm.group(2))
                        continue
                    m = EDGE_RE.match(line)
                    if m:
                        edges.setdefault(m.group(1), set()).add(m.group(2))
    return nodes, edges


def demangle(names, cxxfilt):
    names = list(names)
    try:
        out = subprocess.run([cxxfilt], input="\n".join(names), capture_output=True, text=True,
                             check=True).stdout.splitlines()
        if len(out) == len(names):
            return dict(zip(names, out))
    except (OSError, subprocess.CalledProcessError):
        pass
    return {n: n for n in names}


def load_elf(objdump, elf):
    """Prologue frame size and direct callees of every function in the ELF."""
    text = subprocess.run([objdump, "-d", "--no-show-raw-insn", elf], capture_output=True, text=True,
                          check=True).stdout
    riscv = "riscv" in os.path.basename(objdump)
    frames, calls, indirect = {}, {}, set()
    current, in_prologue = None, 0
    last_li = {}
    func_re = re.compile(r"^[0-9a-f]+ <([^>]+)>:$")
    insn_re = re.compile(r"^\s*[0-9a-f]+:\s+(\S+)\s*(.*)$")
    for line in text.splitlines():
        m = func_re.match(line)
        if m:
            current = m.group(1)
            frames[current] = 0
            calls[current] = set()
            in_prologue = 12 if not riscv else 64
            last_li = {}
            continue
        m = insn_re.match(line)
        if not m or current is None:
            continue
        op, args = m.group(1), m.group(2)
        target = re.search(r"<([^>]+)>\s*$", args)
        target_name = target.group(1) if target else None
        if riscv:
            if in_prologue:
                in_prologue -= 1
                a = args.replace(" ", "")
                mm = re.match(r"sp,sp,-(\d+)$", a)
                if op in ("add", "addi", "c.addi", "c.addi16sp") and mm:
                    frames[current] += int(mm.group(1))
                mm = re.match(r"([a-z0-9]+),(-?\d+)$", a)
                if op in ("li", "c.li") and mm:
                    last_li[mm.group(1)] = int(mm.group(2))
                mm = re.match(r"sp,sp,([a-z][a-z0-9]*)$", a)
                if mm and mm.group(1) in last_li:
                    if op == "sub" and last_li[mm.group(1)] > 0:
                        frames[current] += last_li[mm.group(1)]
                    elif op == "add" and last_li[mm.group(1)] < 0:
                        frames[current] += -last_li[mm.group(1)]
            if op in ("jal", "jalr", "call", "c.jal", "c.jalr"):
                if target_name and "+" not in target_name:
                    calls[current].add(target_name)
                elif op in ("jalr", "c.jalr") and not target_name:
                    indirect.add(current)
            elif op in ("j", "jr", "tail", "c.j", "c.jr") and target_name and "+" not in target_name \
                    and target_name != current:
                calls[current].add(target_name)  # tail call into another function
            continue
        if in_prologue:
            in_prologue -= 1
            if op in ("push", "push.w", "stmdb") and ("sp!" in args or op.startswith("push")):
                regs = re.search(r"\{([^}]*)\}", args)
                if regs:
                    frames[current] += 4 * count_regs(regs.group(1))
            elif op == "vpush":
                regs = re.search(r"\{([^}]*)\}", args)
                if regs:
                    width = 8 if regs.group(1).strip().startswith("d") else 4
                    frames[current] += width * count_regs(regs.group(1))
            elif op in ("sub", "sub.w", "subw") and args.startswith("sp,"):
                imm = re.search(r"#(\d+)", args)
                if imm:
                    frames[current] += int(imm.group(1))
        target = re.search(r"<([^>+]+)>$", args)
        if op in ("bl", "blx") and target:
            calls[current].add(target.group(1))
        elif op in ("blx",) and not target:
            indirect.add(current)
        elif op in ("b.w", "b") and target and target.group(1) != current and "+" not in args.split("<")[1]:
            calls[current].add(target.group(1))  # tail call into another function
    # objdump labels each address with one of its names (__hypot, not
    # hypot): give every alias nm knows the same frame and callees.
    nm = re.sub(r"objdump$", "nm", objdump)
    try:
        listing = subprocess.run([nm, elf], capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        listing = ""
    by_addr = {}
    for line in listing.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[1] in "TtWw":
            by_addr.setdefault(int(parts[0], 16), []).append(parts[2])
    for m in re.finditer(r"^([0-9a-f]+) <([^>]+)>:$", text, re.M):
        label, addr = m.group(2), int(m.group(1), 16)
        for alias in by_addr.get(addr, []):
            if alias not in frames:
                frames[alias] = frames[label]
                calls[alias] = calls[label]
                if label in indirect:
                    indirect.add(alias)
    return frames, calls, indirect


def short(name):
    """Drop template arguments and parameter lists: 'a::B<...>::f(int)' -> 'a::B<>::f'."""
    prev = None
    while prev != name:
        prev = name
        name = re.sub(r"<[^<>]*>", "\x01", name)
    name = name.replace("\x01", "<>")
    name = re.sub(r" \[clone [^]]*\]$", "", name)
    name = name.replace("(anonymous namespace)", "\x02")
    prev = None
    while prev != name:  # parameter lists, innermost first
        prev = name
        name = re.sub(r"\([^()]*\)", "", name)
    name = re.sub(r" const$", "", name)
    return name.replace("\x02", "(anonymous namespace)")


def count_regs(spec):
    n = 0
    for part in spec.split(","):
        part = part.strip()
        r = re.match(r"([a-z]+)(\d+)-[a-z]+(\d+)$", part)
        n += int(r.group(3)) - int(r.group(2)) + 1 if r else 1
    return n


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--elf", required=True)
    ap.add_argument("--objdump", default="arm-none-eabi-objdump")
    ap.add_argument("--cxxfilt", default="c++filt")
    ap.add_argument("--ci-dir", required=True, action="append",
                    help="object directory of a target linked into the image (repeatable)")
    ap.add_argument("--root", action="append", help="regex on the demangled name (repeatable)")
    ap.add_argument("--out")
    ap.add_argument("--json", help="write the worst chain of every root and the budget verdict as JSON")
    ap.add_argument("--label", default="", help="row name for the JSON (e.g. the image name)")
    ap.add_argument("--budget", type=int, help="bytes the worst chain from --budget-root may use")
    ap.add_argument("--budget-root", default=STEP_ROOT, help="regex of the budgeted root(s)")
    ap.add_argument("--reject", action="store_true",
                    help="rename the ELF to <elf>.rejected when the budget is exceeded")
    args = ap.parse_args()

    nodes, edges = load_ci(args.ci_dir)
    elf_frames, elf_calls, elf_indirect = load_elf(args.objdump, args.elf)

    # A bare (external) name resolves to the defined .ci node of that symbol.
    by_symbol = {}
    for title in nodes:
        by_symbol.setdefault(symbol_of(title), title)

    def resolve(title):
        if title in nodes:
            return ("ci", title)
        sym = symbol_of(title)
        if sym in by_symbol:
            return ("ci", by_symbol[sym])
        return ("elf", sym)

    notes = set()

    memo, visiting = {}, set()

    def worst(key):
        if key in memo:
            return memo[key]
        if key in visiting:
            if key[0] == "ci":  # Kestrel's own code: SPEC section 1 forbids recursion
                raise SystemExit(f"stack_report: recursion through {key[1]}")
            # A C library routine that calls itself (glibc's
            # __ieee754_remainder rescales a huge divisor and recurses once):
            # count one more level of its frame and stop there.
            frame = elf_frames.get(key[1], 0)
            notes.add(f"recursion in library function {key[1]}: counted as one extra level ({frame} bytes)")
            return (frame, ((key[1], frame, "recursive call"),))
        visiting.add(key)
        memo[key] = result = worst_uncached(key)
        visiting.discard(key)
        return result

    def worst_uncached(key):
        kind, name = key
        if kind == "ci":
            frame, qual = nodes[name]
            if "dynamic" in qual:
                notes.add(f"dynamic stack (alloca/VLA) in {symbol_of(name)}: {qual}")
            callees = [resolve(t) for t in edges.get(name, ())]
            if any(symbol_of(t) == "__indirect_call" for t in edges.get(name, ())):
                notes.add(f"indirect call in {symbol_of(name)} (not followed)")
        else:
            if name not in elf_frames:
                notes.add(f"{name}: not in the image (inlined or discarded), counted as 0")
                return (0, ((name, 0, "absent"),))
            frame, qual = elf_frames[name], "prologue"
            if name in elf_indirect:
                notes.add(f"indirect call in {name} (not followed)")
            callees = [resolve(t) for t in elf_calls.get(name, ())]
        best = (0, ())
        for c in sorted(set(callees)):
            if c[1] in ("__indirect_call",):
                continue
            sub = worst(c)
            if sub[0] > best[0]:
                best = sub
        return (frame + best[0], ((symbol_of(name), frame, qual),) + best[1])

    # Cross-check the prologue parser on functions both sources describe.
    mismatches = [(symbol_of(t), f, elf_frames[symbol_of(t)]) for t, (f, _q) in nodes.items()
                  if symbol_of(t) in elf_frames and elf_frames[symbol_of(t)] != f]
    for sym, ci_frame, elf_frame in mismatches[:10]:
        notes.add(f"frame of {sym}: .ci says {ci_frame}, prologue parse says {elf_frame}")

    all_symbols = {symbol_of(t) for t in nodes} | set(elf_frames)
    names = demangle(all_symbols, args.cxxfilt)

    roots = list(args.root or DEFAULT_ROOTS)
    if args.budget is not None and args.budget_root not in roots:
        roots.insert(0, args.budget_root)
    lines = []
    results = []  # (pattern, short name, total, chain)
    for pattern in roots:
        rx = re.compile(pattern)
        matches = sorted(s for s in all_symbols if rx.search(names.get(s, s)))
        if not matches:
            lines.append(f"root /{pattern}/: no function matches (inlined?)\n")
            continue
        for sym in matches:
            total, chain = worst(resolve(sym))
            results.append((pattern, short(names.get(sym, sym)), total, chain))
            lines.append(f"{total:6d} bytes  worst chain from {short(names.get(sym, sym))}")
            for fn, frame, qual in chain:
                lines.append(f"    {frame:5d}  {short(names.get(fn, fn))}  [{qual}]")
            lines.append("")

    verdict = None
    budgeted = [r for r in results if r[0] == args.budget_root]
    worst_budgeted = max((r[2] for r in budgeted), default=None)
    if args.budget is not None:
        if worst_budgeted is None:
            verdict = f"FAIL: no function matches the budgeted root /{args.budget_root}/"
        elif worst_budgeted > args.budget:
            verdict = (f"FAIL: the worst chain from /{args.budget_root}/ needs {worst_budgeted} bytes, "
                       f"over its budget of {args.budget} bytes")
        else:
            verdict = (f"OK: the worst chain from /{args.budget_root}/ needs {worst_budgeted} bytes "
                       f"(budget {args.budget})")
        lines.append(verdict)
        lines.append("")
    if notes:
        lines.append("Notes:")
        lines.extend(f"  - {n}" for n in sorted(notes))
    report = "\n".join(lines) + "\n"
    sys.stdout.write(report)
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            f.write(report)
    if args.json:
        doc = {
            "label": args.label or os.path.basename(args.elf),
            "step_bytes": worst_budgeted,
            "budget": args.budget,
            "max_frame": max(((f, symbol_of(t)) for t, (f, _q) in nodes.items()), default=(0, ""))[0],
            "roots": [{"root": r[1], "bytes": r[2],
                       "chain": [{"function": short(names.get(fn, fn)), "frame": fr, "kind": q}
                                 for fn, fr, q in r[3]]} for r in results],
        }
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(doc, f, indent=2)
            f.write("\n")
    if verdict and verdict.startswith("FAIL"):
        if args.reject and os.path.exists(args.elf):
            os.replace(args.elf, args.elf + ".rejected")
            sys.stderr.write(f"stack_report: {args.elf} renamed to {args.elf}.rejected\n")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
