#!/usr/bin/env python3
"""Worst-case stack depth of the M4F image's call chains (docs/footprint.md).

Inputs:
  * the .ci files GCC writes with -fcallgraph-info=su beside each object
    (image.cmake): one node per function emitted, with its frame size
    ("N bytes (static)"; "dynamic" if it uses alloca/VLAs) and one edge per
    call site that survived inlining;
  * the linked ELF, disassembled with objdump, for the functions no .ci
    describes (newlib's libm and libc, libgcc's soft-float helpers): frame =
    push + vpush + "sub sp, #N" of the prologue, callees = bl/b.w targets.

For each root the script walks every call path (the graph must be acyclic:
recursion is reported as an error, as SPEC section 1 forbids it) and prints
the deepest one with the frame of each function on it. The sum is the stack
the chain needs below the caller's SP; a function's frame includes the
registers it saves and its locals, and a call adds nothing else on ARM (the
return address is in LR, saved by the callee's push and so counted in its
frame).

Usage (the build wires it to the kestrel-m4f-stack-report target):
  stack_report.py --elf kestrel-m4f.elf --objdump arm-none-eabi-objdump \
                  --ci-dir <object dir> [--ci-dir ...] [--root REGEX ...] [--out stack.txt]
"""

import argparse
import os
import re
import subprocess
import sys

DEFAULT_ROOTS = [
    r"kestrel::Tracker<.*>::step\(",
    r"^kestrel::m4f::firmware_main\(\)$",
    r"^USART2_IRQHandler$",
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
    frames, calls, indirect = {}, {}, set()
    current, in_prologue = None, 0
    func_re = re.compile(r"^[0-9a-f]+ <([^>]+)>:$")
    insn_re = re.compile(r"^\s*[0-9a-f]+:\s+(\S+)\s*(.*)$")
    for line in text.splitlines():
        m = func_re.match(line)
        if m:
            current = m.group(1)
            frames[current] = 0
            calls[current] = set()
            in_prologue = 12
            continue
        m = insn_re.match(line)
        if not m or current is None:
            continue
        op, args = m.group(1), m.group(2)
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
            raise SystemExit(f"stack_report: recursion through {key[1]}")
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

    roots = args.root or DEFAULT_ROOTS
    lines = []
    for pattern in roots:
        rx = re.compile(pattern)
        matches = sorted(s for s in all_symbols if rx.search(names.get(s, s)))
        if not matches:
            lines.append(f"root /{pattern}/: no function matches (inlined?)\n")
            continue
        for sym in matches:
            total, chain = worst(resolve(sym))
            lines.append(f"{total:6d} bytes  worst chain from {short(names.get(sym, sym))}")
            for fn, frame, qual in chain:
                lines.append(f"    {frame:5d}  {short(names.get(fn, fn))}  [{qual}]")
            lines.append("")
    if notes:
        lines.append("Notes:")
        lines.extend(f"  - {n}" for n in sorted(notes))
    report = "\n".join(lines) + "\n"
    sys.stdout.write(report)
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            f.write(report)


if __name__ == "__main__":
    main()
