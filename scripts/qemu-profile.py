#!/usr/bin/env python3
"""Instructions per function of an emulated run, from QEMU's own traces.

    scripts/qemu-profile.py MACHINE ELF [TOP]
    scripts/qemu-profile.py MACHINE ELF SYMBOL-SUBSTRING   # blocks of one function

Runs ELF under qemu-system-arm -machine MACHINE (mps2-an386 or mps2-an385)
with -d in_asm,exec,nochain, which logs every translated block (its
instructions) and every block executed. Executions times block sizes,
summed per symbol, give exact instruction counts per function (after
inlining: a function's count includes what was inlined into it).
"""
import collections, os, re, subprocess, sys, tempfile

machine, elf = sys.argv[1], sys.argv[2]
arg = sys.argv[3] if len(sys.argv) > 3 else "25"
top = int(arg) if arg.isdigit() else None
cpu = "cortex-m4" if machine == "mps2-an386" else "cortex-m3"
with tempfile.TemporaryDirectory() as d:
    log = os.path.join(d, "q.log")
    subprocess.run(["qemu-system-arm", "-machine", machine, "-cpu", cpu, "-nographic", "-semihosting-config",
                    "enable=on,target=native", "-icount", "shift=0", "-d", "in_asm,exec,nochain", "-D", log,
                    "-kernel", elf], check=True, stdout=subprocess.DEVNULL)
    size = {}
    name = {}
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
                n += 1
                size[cur] = n
                continue
            m = re.match(r"^Trace \d+: \S+ \[[0-9a-f]+/([0-9a-f]+)/", line)
            if m:
                counts[int(m.group(1), 16)] += 1
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
