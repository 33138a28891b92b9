#!/usr/bin/env python3
"""Instructions per function of an emulated run, from QEMU's own traces.

    scripts/qemu-profile.py MACHINE ELF [TOP]
    scripts/qemu-profile.py MACHINE ELF SYMBOL-SUBSTRING   # blocks of one function
    scripts/qemu-profile.py MACHINE ELF --lines [TOP [SYMBOL-SUBSTRING]]  # per source line (innermost inlined frame)
    scripts/qemu-profile.py MACHINE ELF --annotate SYMBOL-SUBSTRING       # disassembly with executions per instruction
    scripts/qemu-profile.py MACHINE ELF --by-count SYMBOL-SUBSTRING       # instructions grouped by how often each ran

Runs ELF under qemu-system-arm -machine MACHINE (mps2-an386, mps2-an385 or mps2-an505)
with -d in_asm,exec,nochain, which logs every translated block (its
instructions) and every block executed. Executions times block sizes,
summed per symbol, give exact instruction counts per function (after
inlining: a function's count includes what was inlined into it).

--by-count splits one function's count by how many times each of its
instructions ran: in `rasterize`, say, the instructions run once per
triangle visit, once per row, once per span and once per pixel show up as
groups whose execution counts are those numbers, which gives the cost of
each level (instructions per visit, row, span, pixel) without counters in
the code.
"""
import collections, os, re, subprocess, sys, tempfile

machine, elf = sys.argv[1], sys.argv[2]
lines_mode = len(sys.argv) > 3 and sys.argv[3] == "--lines"
annotate = len(sys.argv) > 3 and sys.argv[3] == "--annotate"
by_count = len(sys.argv) > 3 and sys.argv[3] == "--by-count"
if lines_mode or annotate or by_count:
    del sys.argv[3]
arg = sys.argv[3] if len(sys.argv) > 3 else "25"
top = int(arg) if arg.isdigit() else None
cpu = {"mps2-an386": "cortex-m4", "mps2-an505": "cortex-m33"}.get(machine, "cortex-m3")
with tempfile.TemporaryDirectory() as d:
    log = os.path.join(d, "q.log")
    subprocess.run(["qemu-system-arm", "-machine", machine, "-cpu", cpu, "-nographic", "-semihosting-config",
                    "enable=on,target=native", "-icount", "shift=0", "-d", "in_asm,exec,nochain", "-D", log,
                    "-kernel", elf], check=True, stdout=subprocess.DEVNULL)
    size = {}
    name = {}
    addrs = collections.defaultdict(list)
    counts = collections.Counter()
    cur, n = None, 0
    with open(log, errors="replace") as f:
        for line in f:
            if line.startswith("IN:"):
                sym = line[3:].strip() or "?"
                cur, n = None, 0
                continue
            m = re.match(r"^0x([0-9a-f]{8}):", line)
            if m:
                if cur is None:
                    cur = int(m.group(1), 16)
                    name[cur] = sym
                    addrs[cur] = []
                n += 1
                size[cur] = n
                addrs[cur].append(int(m.group(1), 16))
                continue
            m = re.match(r"^Trace \d+: \S+ \[[0-9a-f]+/([0-9a-f]+)/", line)
            if m:
                counts[int(m.group(1), 16)] += 1
    if by_count or annotate:
        # Executions of each instruction of the function, summed over the
        # translated blocks that hold it (a jump into the middle of a block
        # starts another).
        per_pc = collections.Counter()
        for pc, c in counts.items():
            if arg in name.get(pc, ""):
                for a in addrs.get(pc, []):
                    per_pc[a] += c
    if by_count:
        # Per execution count: how many instructions ran that often, and
        # their total.
        groups = collections.Counter(per_pc.values())
        total = sum(c * n for c, n in groups.items())
        print(f"{total:>12,}  total")
        print(f"{'runs':>10} {'instr':>6} {'total':>12}")
        for c, n in sorted(groups.items(), key=lambda g: -g[0] * g[1]):
            if c * n * 200 >= total:
                print(f"{c:>10,} {n:>6} {c * n:>12,}  {100 * c * n / total:5.1f}%")
        sys.exit(0)
    if annotate:
        lo, hi = min(per_pc), max(per_pc) + 4
        # The M33's FPv5 instructions (vminnm, vsel, ...) decode only when named.
        mattr = ["--mattr=+fp-armv8d16sp,+dsp"] if machine == "mps2-an505" else []
        dis = subprocess.run(["llvm-objdump", "-d", "-l", "--no-show-raw-insn", *mattr, f"--start-address={lo:#x}",
                              f"--stop-address={hi:#x}", elf], capture_output=True, text=True).stdout
        for line in dis.splitlines():
            m = re.match(r"^\s*([0-9a-f]+):", line)
            if m:
                print(f"{per_pc.get(int(m.group(1), 16), 0):>8} {line}")
            elif line.startswith(";"):
                print("         " + re.sub(r"^; .*/(soft3d|main|library|registry/src/[^/]+)/", "; ", line))
        sys.exit(0)
    if lines_mode:
        # Instructions executed per address, then per source line of the
        # innermost (inlined) frame, by llvm-symbolizer from the debug info.
        per_pc = collections.Counter()
        only = sys.argv[4] if len(sys.argv) > 4 else ""
        for pc, c in counts.items():
            if only not in name.get(pc, ""):
                continue
            for a in addrs.get(pc, []):
                per_pc[a] += c
        pcs = sorted(per_pc)
        out = subprocess.run(["llvm-symbolizer", "--obj", elf], input="\n".join(hex(a) for a in pcs),
                             capture_output=True, text=True).stdout
        blocks = out.strip().split("\n\n")
        per_line = collections.Counter()
        # QEMU_PROFILE_FILE=raster.rs attributes each instruction to the
        # innermost inlined frame in that file instead (the caller's line).
        in_file = os.environ.get("QEMU_PROFILE_FILE")
        for a, b in zip(pcs, blocks):
            ls = b.strip().split("\n")
            locs = ls[1::2]
            loc = locs[0] if locs else "?"
            if in_file:
                loc = next((l for l in locs if in_file in l), loc)
            # Paths from this repository relative to it; others (core,
            # dependencies) by crate directory.
            loc = re.sub(r"^.*/(soft3d|main|qemu-bench)/", "", loc)
            loc = re.sub(r"^.*/(library|registry/src/[^/]+)/", "", loc)
            per_line[loc] += per_pc[a]
        total = sum(per_line.values())
        print(f"{total:>12,}  total")
        for s_, c in per_line.most_common(top or 40):
            print(f"{c:>12,}  {100 * c / total:5.1f}%  {s_}")
        sys.exit(0)
    if top is None:
        # Per-block view of the functions whose name contains `arg`: address,
        # executions, instructions in the block, total.
        rows = sorted((pc, c) for pc, c in counts.items() if arg in name.get(pc, ""))
        for pc, c in rows:
            print(f"{pc:08x} {c:>9,} x {size.get(pc, 0):>3} = {c * size.get(pc, 0):>10,}")
        sys.exit(0)
    per = collections.Counter()
    for pc, c in counts.items():
        per[name.get(pc, hex(pc))] += c * size.get(pc, 0)
    total = sum(per.values())
    print(f"{total:>12,}  total")
    for s, c in per.most_common(top):
        print(f"{c:>12,}  {100 * c / total:5.1f}%  {s}")
