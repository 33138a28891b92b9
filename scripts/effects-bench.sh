#!/usr/bin/env bash
# "A scene pays only for the effects it uses", measured on emulated
# Cortex-M cores: builds the effects firmwares of firmware/qemu-bench,
# runs them in QEMU and compares a flat-shaded scene's instructions per
# frame, the firmware's flash and its static RAM between
#
#   flat-only          only the Flat effect exists (renderer V = 0)
#   flat-nodepth-only  the same with DepthOff materials (what depth costs)
#   flat-only-v6       Flat only, but the general renderer's V = 6
#                      (diagnostic: the wider vertex buffer alone)
#   all                the general firmware: V = 6 and every effect linked
#                      in (it also renders the scene with each of them)
#
#   scripts/effects-bench.sh                 # tables and checks
#   scripts/effects-bench.sh --csv out.csv   # also writes
#                                            # build,core,scene,instructions,geometry,flash,ram,checksum
#
# Fails (exit 1) if a frame's checksum differs between builds that render
# it, if the general build's flat frame takes more than 1% more
# instructions than the flat-only build's, or if the flat-only firmware's
# flash is not smaller than the general one's.
#
# Targets: thumbv7em-none-eabihf on QEMU mps2-an386 (Cortex-M4F) and
# thumbv6m-none-eabi on mps2-an385 (a Cortex-M3 running M0+ code), as in
# scripts/target-bench.sh: with -icount shift=0 each instruction is 1 ns and
# SysTick ticks every 40 instructions (checked at start-up). Instructions
# run from begin_frame to finish, the checksum sink's own work excluded;
# "geometry" is the part spent in the draw calls. flash = text + data and
# static RAM = data + bss of the ELF (the renderer is a static), by
# llvm-size (rustup's llvm-tools, installed here if missing) or, failing
# that, readelf. Needs qemu-system-arm and the two rustup targets.
set -euo pipefail

csv_path=""
while [ $# -gt 0 ]; do
  case "$1" in
    --csv)
      [ $# -ge 2 ] || { echo "usage: $0 [--csv PATH]" >&2; exit 2; }
      csv_path=$2
      shift 2
      ;;
    *)
      echo "usage: $0 [--csv PATH]" >&2
      exit 2
      ;;
  esac
done

# The CSV path is relative to where the script was started.
[ -z "$csv_path" ] || csv_path=$(realpath -m "$csv_path")
cd "$(dirname "$0")/.."

bins=(effects_flat effects_flat_nodepth effects_flat_v6 effects_all)
# Where cargo puts the ELFs (CARGO_TARGET_DIR is relative to the package).
target_dir=$(cd firmware/qemu-bench && realpath -m "${CARGO_TARGET_DIR:-target}")

# llvm-size from the toolchain's llvm-tools (installing the component if it
# is missing), else one on PATH; readelf as the last resort.
size_tool=""
find_size_tool() {
  local c
  for c in "$(rustc --print sysroot)/lib/rustlib/$(rustc -vV | sed -n 's/^host: //p')/bin/llvm-size" "$(command -v llvm-size || true)"; do
    if [ -n "$c" ] && [ -x "$c" ]; then
      size_tool=$c
      return
    fi
  done
}
find_size_tool
if [ -z "$size_tool" ] && command -v rustup >/dev/null; then
  rustup component add llvm-tools >/dev/null 2>&1 || true
  find_size_tool
fi
if [ -z "$size_tool" ] && ! command -v readelf >/dev/null; then
  echo "effects-bench: neither llvm-size (rustup component llvm-tools) nor readelf found" >&2
  exit 1
fi

# "flash ram" of an ELF: text + data, data + bss.
elf_sizes() {
  if [ -n "$size_tool" ]; then
    "$size_tool" "$1" | awk 'NR == 2 { print $1 + $2, $2 + $3 }'
  else
    # Allocated sections: with contents (PROGBITS) they are in flash; the
    # writable ones are in RAM too (.data is copied there, .bss is NOBITS).
    readelf -SW "$1" | sed 's/^ *\[ *[0-9]*\]//' | awk '
      function hex(s, i, n) {
        n = 0
        for (i = 1; i <= length(s); i++) n = n * 16 + index("0123456789abcdef", substr(tolower(s), i, 1)) - 1
        return n
      }
      ($2 == "PROGBITS" || $2 == "NOBITS") && $7 ~ /A/ {
        if ($2 == "PROGBITS") flash += hex($5)
        if ($7 ~ /W/ || $1 == ".data") ram += hex($5)
      }
      END { print flash + 0, ram + 0 }'
  fi
}

# 1234567 -> 1,234,567
commas() { sed ':a;s/\B[0-9]\{3\}\>/,&/;ta' <<<"$1"; }

rows=""
declare -A flash ram
for t in thumbv7em-none-eabihf thumbv6m-none-eabi; do
  if [ "$t" = thumbv6m-none-eabi ]; then machine=mps2-an385 cpu=cortex-m3 core=m0; else machine=mps2-an386 cpu=cortex-m4 core=m4f; fi
  (cd firmware/qemu-bench && cargo build -q --release --target "$t" "${bins[@]/#/--bin=}")
  for b in "${bins[@]}"; do
    elf=$target_dir/$t/release/$b
    out=$(timeout 600 qemu-system-arm -machine "$machine" -cpu "$cpu" -nographic -semihosting-config enable=on,target=native \
      -icount shift=0 -kernel "$elf")
    if ! grep -q '^calibration,instructions_per_tick,40,' <<<"$out"; then
      echo "effects-bench: instructions per tick calibration is not 40 on $machine ($b)" >&2
      exit 1
    fi
    build=$(grep '^renderer,' <<<"$out" | cut -d, -f2)
    read -r flash["$build,$core"] ram["$build,$core"] < <(elf_sizes "$elf")
    # effects,build,scene,core,instructions,geometry,checksum,queued
    rows+=$(grep '^effects,' <<<"$out")$'\n'
  done
done

# The value of column `field` (instructions, geometry, checksum) of a frame.
get() {
  local build=$1 scene=$2 core=$3 field=$4 col
  case "$field" in instructions) col=5 ;; geometry) col=6 ;; checksum) col=7 ;; esac
  awk -F, -v b="$build" -v s="$scene" -v c="$core" -v k="$col" '$2 == b && $3 == s && $4 == c { print $k }' <<<"$rows"
}

fail=0
complain() {
  echo "FAIL: $*" >&2
  fail=1
}

if [ -n "$csv_path" ]; then
  echo "build,core,scene,instructions,geometry,flash,ram,checksum" >"$csv_path"
fi
printf '%-18s %-4s %-14s %12s %12s %9s %10s %9s\n' build core scene instr/frame geometry flash "static RAM" checksum
while IFS=, read -r _ build scene core instr geometry sum _; do
  [ -n "$build" ] || continue
  key="$build,$core"
  printf '%-18s %-4s %-14s %12s %12s %9s %10s %9s\n' "$build" "$core" "$scene" "$(commas "$instr")" "$(commas "$geometry")" \
    "$(commas "${flash[$key]}")" "$(commas "${ram[$key]}")" "$sum"
  if [ -n "$csv_path" ]; then
    echo "$build,$core,$scene,$instr,$geometry,${flash[$key]},${ram[$key]},$sum" >>"$csv_path"
  fi
  if ! [[ "$instr" =~ ^[0-9]+$ ]]; then
    complain "$build $scene on $core: instruction count overflowed"
  fi
done <<<"$rows"

# n / d, and the difference in percent.
ratio() { awk -v n="$1" -v d="$2" 'BEGIN { printf "%.4f (%+.2f%%)", n / d, 100 * (n - d) / d }'; }

echo
for core in m4f m0; do
  flat=$(get flat-only flat "$core" instructions)
  general=$(get all flat "$core" instructions)
  v6=$(get flat-only-v6 flat "$core" instructions)
  nodepth=$(get flat-nodepth-only flat-nodepth "$core" instructions)
  if [ -z "$flat" ] || [ -z "$general" ] || [ -z "$v6" ] || [ -z "$nodepth" ]; then
    complain "missing frames on $core"
    continue
  fi
  # Every frame two builds render must be the same picture.
  for pair in "flat-only all flat" "flat-only-v6 all flat" "flat-nodepth-only all flat-nodepth"; do
    read -r a b scene <<<"$pair"
    if [ "$(get "$a" "$scene" "$core" checksum)" != "$(get "$b" "$scene" "$core" checksum)" ]; then
      complain "$scene frame differs between $a and $b on $core"
    fi
  done
  f_flat=${flash[flat-only,$core]} f_all=${flash[all,$core]} f_nodepth=${flash[flat-nodepth-only,$core]}
  echo "$core: flat scene, general / flat-only build: $(ratio "$general" "$flat"), $(commas $((general - flat))) instructions per frame"
  echo "$core:   of which the geometry (draw calls): $(commas $(($(get all flat "$core" geometry) - $(get flat-only flat "$core" geometry))))"
  echo "$core:   flat-only with the general V = 6 / flat-only: $(ratio "$v6" "$flat")"
  echo "$core: flash, flat-only $(commas "$f_flat") bytes, all effects $(commas "$f_all") bytes:" \
    "$(commas $((f_all - f_flat))) more ($(awk -v a="$f_all" -v f="$f_flat" 'BEGIN { printf "%.1f", a / f }')x)"
  echo "$core: static RAM, flat-only $(commas "${ram[flat-only,$core]}") bytes, all effects $(commas "${ram[all,$core]}") bytes"
  echo "$core: depth test, flat-only / flat-nodepth-only: $(ratio "$flat" "$nodepth") instructions," \
    "$(commas $((f_flat - f_nodepth))) bytes of flash"
  if awk -v g="$general" -v f="$flat" 'BEGIN { exit !(g > f * 1.01) }'; then
    complain "on $core the general build's flat frame takes more than 1% more instructions than the flat-only build's"
  fi
  if [ "$f_flat" -ge "$f_all" ]; then
    complain "on $core the flat-only firmware's flash is not smaller than the general one's"
  fi
done
exit "$fail"
