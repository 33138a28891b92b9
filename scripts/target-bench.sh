#!/usr/bin/env bash
# Renders the benchmark scenes on emulated Cortex-M cores and on the host,
# prints instructions per frame and checks that every frame is bit-identical.
#
#   scripts/target-bench.sh            # table
#   scripts/target-bench.sh --csv      # scene,mode,target,instr_per_frame,geometry_instr,sink_instr,queued,crc,host_crc
#   scripts/target-bench.sh --readme   # rewrites the table in README.md
#
# Targets: thumbv7em-none-eabihf on QEMU mps2-an386 (Cortex-M4F) and
# thumbv6m-none-eabi on mps2-an385 (a Cortex-M3 running M0+ code: the
# stand-in for an RP2040). With -icount shift=0 each instruction is 1 ns of
# virtual time and SysTick (25 MHz) ticks every 40 instructions.
# instr_per_frame excludes the checksum sink (measured separately);
# geometry_instr is the part spent in draw calls (vertex stage, clipping,
# culling, queuing) before rasterization;
# "fps@150MHz" assumes one instruction per cycle and is only an estimate.
# Needs qemu-system-arm and the two rustup targets (.ci/run installs them).
set -euo pipefail
cd "$(dirname "$0")/.."
csv=${1:-}

host=$(cargo run -q --release --example bench_host --no-default-features --features libm,std)
rows=""
for t in thumbv7em-none-eabihf thumbv6m-none-eabi; do
  out=$(cd firmware/qemu-bench && timeout 600 cargo run -q --release --target "$t")
  rows+=$(tail -n +2 <<<"$out")$'\n'
done

fail=0
md=""
# 1234567 -> 1,234,567
commas() { sed ':a;s/\B[0-9]\{3\}\>/,&/;ta' <<<"$1"; }
[ "$csv" = "--csv" ] && echo "scene,mode,target,instr_per_frame,geometry_instr,sink_instr,queued,crc,host_crc"
[ "$csv" = "--csv" ] || printf '%-10s %-6s %-4s %12s %12s %11s %7s %9s  %s\n' scene mode core instr/frame of.geometry fps@150MHz queued crc host
while IFS=, read -r scene mode core instr sink queued crc geometry; do
  [ -n "$scene" ] || continue
  want=$(grep "^$scene,$mode," <<<"$host" | cut -d, -f3)
  [ "$crc" = "$want" ] || fail=1
  render=$((instr - sink))
  md+="| $scene | $mode | $core | $(commas "$render") | $(commas "$geometry") | $(commas "$sink") | $queued |"$'\n'
  if [ "$csv" = "--csv" ]; then
    echo "$scene,$mode,$core,$render,$geometry,$sink,$queued,$crc,$want"
  else
    printf '%-10s %-6s %-4s %12d %12d %11.1f %7d %9s  %s\n' "$scene" "$mode" "$core" "$render" "$geometry" "$(awk -v n="$render" "BEGIN { print 150000000 / n }")" "$queued" "$crc" \
      "$([ "$crc" = "$want" ] && echo same || echo "DIFFERS ($want)")"
  fi
done <<<"$rows"
if [ "$fail" != 0 ]; then
  echo "target and host frames differ" >&2
  exit 1
fi
if [ "$csv" = "--readme" ]; then
  # Replace the lines between the two markers with the new table.
  table="| scene | mode | core | instructions / frame | of which geometry | sink (excluded) | triangles drawn |"$'\n'
  table+="| --- | --- | --- | ---: | ---: | ---: | ---: |"$'\n'"$md"
  awk -v table="$table" '
    /<!-- target-bench:begin -->/ { print; printf "%s", table; skip = 1; next }
    /<!-- target-bench:end -->/ { skip = 0 }
    !skip { print }' README.md > README.md.new
  mv README.md.new README.md
  echo "README.md updated"
fi
