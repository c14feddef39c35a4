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

Roots: the functions matched by --root (default: step, firmware_main, the
static constructors) and, on a Cortex-M image, every handler of its vector
table (g_vector_table: read from the ELF, so SysTick_Handler, the fault
handlers and any IRQ are roots whether or not their names match a pattern,
and a weak alias such as SysTick_Handler -> Default_Handler is followed to
the function it resolves to).

Calls: the .ci edges of a function plus the direct calls (bl/b.w, jal/j)
of its machine code in the ELF, so a call made from inline assembly (the
M0+ Reset_Handler's "bl kestrel_m0plus_start") is followed, and its frame
is the larger of the .ci frame and the prologue parse (a naked function
has no .ci frame). An indirect call in Kestrel's own code is taken to reach
every function of .preinit_array/.init_array (the start-up's constructor
loop is the only one; each function with an indirect call is listed in the
notes so this stays visible).

Main stack (Cortex-M): the thread-mode chain from the reset vector plus,
for every distinct handler function of the vector table, one exception
entry on top of it and the handler's own chain. Each exception is active
at most once, so this bounds any nesting whatever the priorities. The
exception entry is computed by rule from the ELF's build attributes
(readelf -A): the 8-word basic frame (32 bytes), or the 26-word extended
frame (104 bytes) when the image uses the FPU (Tag_FP_arch; ARMv7-M
B1.5.7), plus 4 bytes of alignment padding (CCR.STKALIGN, 8-byte aligned
frames). --main-budget N fails the script when that total exceeds N.

For each root the script walks every call path (Kestrel's own functions
must not recurse: that is an error, as docs/architecture.md forbids it; a C
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
                  [--budget BYTES [--budget-root REGEX]] [--main-budget BYTES]
                  [--json stack.json] [--reject]
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


def sibling_tool(objdump, name):
    """arm-none-eabi-objdump -> arm-none-eabi-<name> (same directory and prefix)."""
    return re.sub(r"objdump$", name, objdump)


def run(cmd):
    try:
        return subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return ""


def function_symbols(objdump, elf):
    """address -> names of the function symbols there (aliases share one), and size by name."""
    by_addr, sizes = {}, {}
    for line in run([sibling_tool(objdump, "nm"), "-S", elf]).splitlines():
        parts = line.split()
        if len(parts) == 4:
            addr, size, kind, name = parts
            sizes[name] = (int(addr, 16), int(size, 16))
        elif len(parts) == 3:
            addr, kind, name = parts
        else:
            continue
        if kind in "TtWw":
            by_addr.setdefault(int(addr, 16) & ~1, []).append(name)
    return by_addr, sizes


def read_words(objdump, elf, start, size):
    """The 32-bit little-endian words of the image at [start, start + size)."""
    dump = run([objdump, "-s", "--start-address=0x%x" % start, "--stop-address=0x%x" % (start + size), elf])
    data = bytearray()
    for line in dump.splitlines():
        m = re.match(r"^ ([0-9a-f]+) ((?:[0-9a-f]{2,8} ?){1,4})", line)
        if m:
            data += bytes.fromhex(m.group(2).replace(" ", ""))
    return [int.from_bytes(data[i:i + 4], "little") for i in range(0, len(data) - 3, 4)]


def section_words(objdump, elf, names):
    words = []
    for line in run([objdump, "-h", elf]).splitlines():
        parts = line.split()
        if len(parts) >= 4 and parts[1] in names:
            size, vma = int(parts[2], 16), int(parts[3], 16)
            if size:
                words += read_words(objdump, elf, vma, size)
    return words


def exception_entry_bytes(objdump, elf):
    """Bytes one exception entry pushes on a Cortex-M, by rule from the build
    attributes: 8 words, or 26 with the FPU's extended frame, + 4 alignment."""
    attrs = run([sibling_tool(objdump, "readelf"), "-A", elf])
    fpu = re.search(r"Tag_FP_arch:\s*(\S+)", attrs)
    uses_fpu = bool(fpu) and fpu.group(1) not in ("No",)
    arch = re.search(r"Tag_CPU_arch:\s*(\S+)", attrs)
    frame = 104 if uses_fpu else 32
    rule = ("%s, %s: %s frame %d bytes + 4 bytes alignment padding"
            % (arch.group(1) if arch else "?", "FPU" if uses_fpu else "no FPU",
               "extended (26 words: R0-R3, R12, LR, PC, xPSR, S0-S15, FPSCR, reserved)" if uses_fpu
               else "basic (8 words: R0-R3, R12, LR, PC, xPSR)", frame))
    return frame + 4, rule


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
    ap.add_argument("--main-budget", type=int,
                    help="bytes the worst main stack (thread chain + every handler's entry and chain) may use")
    ap.add_argument("--reject", action="store_true",
                    help="rename the ELF to <elf>.rejected when the budget is exceeded")
    args = ap.parse_args()

    nodes, edges = load_ci(args.ci_dir)
    elf_frames, elf_calls, elf_indirect = load_elf(args.objdump, args.elf)
    by_addr, sym_sizes = function_symbols(args.objdump, args.elf)

    def function_at(addr, prefer=()):
        names = by_addr.get(addr & ~1, [])
        for n in names:  # the name the call graphs use, if any
            if n in prefer:
                return n
        return sorted(names, key=lambda n: (n not in elf_frames, n))[0] if names else None

    ci_symbols = {symbol_of(t) for t in nodes}
    init_functions = [f for f in (function_at(w, ci_symbols) for w in
                                  section_words(args.objdump, args.elf, (".preinit_array", ".init_array")))
                      if f]
    # Cortex-M: every handler of the vector table (word 0 is the initial SP, word 1 the reset vector).
    vectors = []
    if "g_vector_table" in sym_sizes:
        addr, size = sym_sizes["g_vector_table"]
        for i, w in enumerate(read_words(args.objdump, args.elf, addr, size)[1:], start=1):
            f = function_at(w, ci_symbols) if w else None
            if f:
                vectors.append((i, f, sorted(by_addr.get(w & ~1, []))))

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
            if key[0] == "ci":  # Kestrel's own code: docs/architecture.md forbids recursion
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
            sym = symbol_of(name)
            if "dynamic" in qual:
                notes.add(f"dynamic stack (alloca/VLA) in {sym}: {qual}")
            if elf_frames.get(sym, 0) > frame:  # e.g. a naked function: the machine code's push counts
                frame, qual = elf_frames[sym], "prologue"
            # .ci edges, plus the direct calls of the machine code (inline asm included).
            callees = [resolve(t) for t in edges.get(name, ())] + [resolve(t) for t in elf_calls.get(sym, ())]
            if any(symbol_of(t) == "__indirect_call" for t in edges.get(name, ())) or sym in elf_indirect:
                if init_functions:
                    notes.add(f"indirect call in {sym}: taken to reach every .init_array/.preinit_array function")
                    callees += [resolve(f) for f in init_functions]
                else:
                    notes.add(f"indirect call in {sym} (not followed)")
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
    for _i, f, _aliases in vectors:  # every handler is a root, named or not
        pattern = "^" + re.escape(names.get(f, f)) + "$"
        if pattern not in roots and not any(re.search(r, names.get(f, f)) for r in roots):
            roots.append(pattern)
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

    main_stack = None
    if vectors:
        entry, rule = exception_entry_bytes(args.objdump, args.elf)
        reset = next(f for i, f, _a in vectors if i == 1)
        thread = worst(resolve(reset))[0]
        handlers = []
        for f in sorted({f for i, f, _a in vectors if i != 1}):
            count = sum(1 for _i, g, _a in vectors if g == f)
            aliases = sorted({a for _i, g, al in vectors if g == f for a in al if a != f})
            chain = worst(resolve(f))[0]
            handlers.append({"handler": short(names.get(f, f)), "vectors": count, "aliases": aliases,
                             "chain": chain, "entry": entry, "bytes": entry + chain})
        total = thread + sum(h["bytes"] for h in handlers)
        main_stack = {"bytes": total, "thread_root": short(names.get(reset, reset)), "thread": thread,
                      "exception_entry": entry, "rule": rule, "handlers": handlers}
        lines.append(f"{total:6d} bytes  worst main stack: the thread chain from {short(names.get(reset, reset))} "
                     f"({thread}) + one exception entry and chain per distinct handler")
        lines.append(f"    exception entry {entry} bytes: {rule}")
        for h in handlers:
            alias = (" = " + ", ".join(h["aliases"][:6]) + (", ..." if len(h["aliases"]) > 6 else "")) \
                if h["aliases"] else ""
            lines.append(f"    {h['bytes']:5d}  {h['handler']} ({h['vectors']} vectors{alias}): "
                         f"entry {h['entry']} + chain {h['chain']}")
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
    if args.main_budget is not None:
        if main_stack is None:
            main_verdict = "FAIL: --main-budget given but the image has no vector table (g_vector_table)"
        elif main_stack["bytes"] > args.main_budget:
            main_verdict = (f"FAIL: the worst main stack needs {main_stack['bytes']} bytes, "
                            f"over its budget of {args.main_budget} bytes")
        else:
            main_verdict = f"OK: the worst main stack needs {main_stack['bytes']} bytes (budget {args.main_budget})"
        lines.append(main_verdict)
        lines.append("")
        if main_verdict.startswith("FAIL") and not (verdict and verdict.startswith("FAIL")):
            verdict = main_verdict
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
            "main_stack": main_stack,
            "main_budget": args.main_budget,
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
