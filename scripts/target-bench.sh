#!/usr/bin/env bash
# Renders the benchmark scenes on emulated Cortex-M cores and on the host,
# prints instructions per frame and checks that every frame is bit-identical.
#
#   scripts/target-bench.sh            # table
#   scripts/target-bench.sh --csv      # scene,mode,target,instr_per_frame,instr_per_pixel,crc,host_crc,static_ram,stack,flash
#   scripts/target-bench.sh --readme   # rewrites the table in README.md
#
# Targets: thumbv7em-none-eabihf on QEMU mps2-an386 (Cortex-M4F),
# thumbv6m-none-eabi on mps2-an385 (a Cortex-M3 running M0+ code: the
# stand-in for an RP2040) and thumbv8m.main-none-eabihf on mps2-an505
# (Cortex-M33, the RP2350's core). With -icount shift=0 each instruction is
# 1 ns of virtual time and SysTick ticks every 40 instructions (25 MHz on
# the an385 and an386) or 50 (20 MHz on the an505); the firmware measures
# this factor on a loop of known length and the script fails if it is not
# the one assumed. The README's table has the M4F and M0+ rows; the M33's
# are compared with the M4F's in a table of their own.
#
# Columns: instr_per_frame is everything the renderer does for a frame
# (strip clears and handing strips to the DrawTarget included) minus the
# benchmark's checksum sink, which is timed separately; instr_per_pixel
# divides it by the pixels drawn (pixels of the final frame that are not
# background, counted on the host); static_ram is size_of the renderer
# (on a board it is a static); stack is the peak stack of the frame, by
# stack painting; flash is the whole benchmark firmware (text + data).
# "fps@150MHz" assumes one instruction per cycle: an estimate, no more.
# Needs qemu-system-arm and the two rustup targets, or Debian's rustc-web
# and rust-web-src where rustup cannot add them (scripts/fw-cargo.sh; .ci/run
# installs whichever it can).
set -euo pipefail
cd "$(dirname "$0")/.."
mode_arg=${1:-}

size_tool=""
for c in "$(rustc --print sysroot)/lib/rustlib/x86_64-unknown-linux-gnu/bin/llvm-size" "$(command -v llvm-size || true)"; do
  if [ -n "$c" ] && [ -x "$c" ]; then size_tool=$c; break; fi
done

host=$(cargo run -q --release --example bench_host --features simulator)
rows=""
declare -A flash
for t in thumbv7em-none-eabihf thumbv6m-none-eabi thumbv8m.main-none-eabihf; do
  (cd firmware/qemu-bench && ../../scripts/fw-cargo.sh "$t" build -q --release)
  out=$(cd firmware/qemu-bench && timeout 600 ../../scripts/fw-cargo.sh "$t" run -q --release)
  case $t in
    thumbv6m-none-eabi) core=m0 ;;
    thumbv8m.main-none-eabihf) core=m33 ;;
    *) core=m4f ;;
  esac
  # `calibration,instructions_per_tick,MEASURED,assumed,ASSUMED`: the
  # firmware's counts hold only if the two agree.
  cal=$(grep '^calibration,' <<<"$out" || true)
  if [ -z "$cal" ] || [ "$(cut -d, -f3 <<<"$cal")" != "$(cut -d, -f5 <<<"$cal")" ]; then
    echo "$core: instructions per tick calibration differs from the factor the firmware assumes: ${cal:-no calibration line}" >&2
    exit 1
  fi
  elf=firmware/qemu-bench/target/$t/release/soft3d-qemu-bench
  # Where scripts/fw-cargo.sh put it when it built `core` itself.
  if [ "${SOFT3D_BUILD_STD:-0}" = 1 ] || ! grep -qx "$t" <<<"$(rustup target list --installed 2>/dev/null || true)"; then
    elf=firmware/qemu-bench/target/build-std/$t/release/soft3d-qemu-bench
  fi
  if [ -n "$size_tool" ]; then
    flash[$core]=$("$size_tool" "$elf" | awk 'NR == 2 { print $1 + $2 }')
  else
    flash[$core]=n/a
  fi
  rows+=$(grep -v '^calibration,\|^scene,' <<<"$out")$'\n'
done

fail=0
md=""
declare -A rendered pixels
# 1234567 -> 1,234,567
commas() { sed ':a;s/\B[0-9]\{3\}\>/,&/;ta' <<<"$1"; }
if [ "$mode_arg" = "--csv" ]; then
  echo "scene,mode,target,instr_per_frame,instr_per_pixel,crc,host_crc,static_ram,stack,flash"
else
  printf '%-10s %-6s %-4s %12s %9s %11s %7s %9s %9s %7s %7s  %s\n' scene mode core instr/frame instr/px fps@150MHz queued crc ram stack flash host
fi
while IFS=, read -r scene mode core instr sink queued crc geometry stack ram; do
  [ -n "$scene" ] || continue
  want=$(grep "^$scene,$mode," <<<"$host" | cut -d, -f3)
  drawn=$(grep "^$scene,$mode," <<<"$host" | cut -d, -f4)
  [ "$crc" = "$want" ] || fail=1
  if ! [[ "$instr" =~ ^[0-9]+$ ]]; then
    echo "$scene $mode $core: instruction count overflowed ($instr)" >&2
    exit 1
  fi
  render=$((instr - sink))
  rendered["$scene,$mode,$core"]=$render
  pixels["$scene"]=$drawn
  per_px=$([ "$drawn" -gt 0 ] && awk -v n="$render" -v p="$drawn" 'BEGIN { printf "%.1f", n / p }' || echo "n/a")
  fps=$(awk -v n="$render" 'BEGIN { printf "%.1f", 150000000 / n }')
  [ "$core" = m33 ] || md+="| $scene | $mode | $core | $(commas "$render") | $per_px | $(commas "$geometry") | $(commas "$drawn") | $queued | $fps | $(commas "$ram") | $(commas "$stack") |"$'\n'
  if [ "$mode_arg" = "--csv" ]; then
    echo "$scene,$mode,$core,$render,$per_px,$crc,$want,$ram,$stack,${flash[$core]}"
  else
    printf '%-10s %-6s %-4s %12d %9s %11s %7d %9s %9d %7d %7s  %s\n' "$scene" "$mode" "$core" "$render" "$per_px" "$fps" "$queued" "$crc" "$ram" "$stack" "${flash[$core]}" \
      "$([ "$crc" = "$want" ] && echo same || echo "DIFFERS ($want)")"
  fi
done <<<"$rows"
if [ "$fail" != 0 ]; then
  echo "target and host frames differ" >&2
  exit 1
fi
# Per effect, the cost of a pixel: a wall scene's frame minus the empty
# frame (clears and strip hand-off), over the pixels it draws (all 76,800,
# which tests/benchmark_scenes.rs checks). Two
# triangles' setup per strip is included (a fraction of an instruction per
# pixel).
effects_md="| effect (wall scene) | fixed M4F | f32 M4F | fixed M0+ | f32 M0+ |"$'\n'"| --- | ---: | ---: | ---: | ---: |"$'\n'
for scene in $(cut -d, -f1 <<<"$rows" | grep '^wall-' | awk '!seen[$0]++'); do
  line="| $scene |"
  for key in fixed,m4f f32,m4f fixed,m0 f32,m0; do
    mode=${key%,*} core=${key#*,}
    w=${rendered[$scene,$mode,$core]:-} e=${rendered[empty,$mode,$core]:-}
    line+=" $([ -n "$w" ] && [ -n "$e" ] && awk -v w="$w" -v e="$e" -v p="${pixels[$scene]}" 'BEGIN { printf "%.1f", (w - e) / p }' || echo n/a) |"
  done
  effects_md+="$line"$'\n'
done
# The M33 (RP2350 code) against the M4F, scene by scene.
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a != "" && b > 0) printf "%.3f", a / b; else printf "n/a" }'; }
m33_md="| scene | fixed M33 | M33 / M4F | f32 M33 | M33 / M4F |"$'\n'"| --- | ---: | ---: | ---: | ---: |"$'\n'
for scene in $(cut -d, -f1 <<<"$rows" | awk 'NF && !seen[$0]++'); do
  line="| $scene |"
  for mode in fixed f32; do
    a=${rendered[$scene,$mode,m33]:-} b=${rendered[$scene,$mode,m4f]:-}
    line+=" $([ -n "$a" ] && commas "$a" || echo n/a) | $(ratio "$a" "$b") |"
  done
  m33_md+="$line"$'\n'
done
if [ -z "$mode_arg" ]; then
  echo
  echo "Cortex-M33 (mps2-an505) against the M4F, instructions per frame:"
  printf '%s' "$m33_md"
  echo
  echo "Instructions per pixel by effect, (wall frame - empty frame) / 76,800:"
  printf '%s' "$effects_md"
fi
if [ "$mode_arg" = "--readme" ]; then
  # Replace the lines between the two markers with the new table.
  table="| scene | mode | core | instructions / frame | per pixel drawn | of which geometry | pixels drawn | triangles drawn | fps at 150 MHz (estimate) | renderer RAM | peak stack |"$'\n'
  table+="| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"$'\n'"$md"
  table+=$'\n'"Benchmark firmware flash: $(commas "${flash[m4f]}") bytes (M4F), $(commas "${flash[m0]}") bytes (M0+ code), $(commas "${flash[m33]}") bytes (M33)."$'\n'
  table+=$'\n'"The same frames on the Cortex-M33 (\`thumbv8m.main-none-eabihf\`, the RP2350's code, on QEMU \`mps2-an505\`), every checksum equal to the host's, against the M4F's instructions per frame:"$'\n\n'"$m33_md"
  table+=$'\n'"Instructions per pixel by effect: each \`wall-*\` frame minus the \`empty\` frame (clears and strip hand-off), over its 76,800 pixels:"$'\n\n'"$effects_md"
  awk -v table="$table" '
    /<!-- target-bench:begin -->/ { print; printf "%s", table; skip = 1; next }
    /<!-- target-bench:end -->/ { skip = 0 }
    !skip { print }' README.md > README.md.new
  mv README.md.new README.md
  echo "README.md updated"
fi
