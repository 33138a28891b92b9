#!/usr/bin/env bash
# The accuracy study (docs/accuracy.md): every precision choice rendered
# against an exact reference, with its cost on emulated Cortex-M cores.
#
#   bash scripts/accuracy.sh          # regenerates docs/accuracy.md, docs/accuracy/ (figures, target.csv)
#   bash scripts/accuracy.sh --quick  # CI: the study tool's tests, then checks that the committed
#                                     # tables of the built-in scenes are current (fresh emulator figures)
#
# Emulator figures come from firmware/qemu-bench's `study` binary on
# mps2-an386 (Cortex-M4F) and mps2-an385 (thumbv6m code, the M0+ stand-in),
# `key,scene,core,instructions,checksum` rows; the tool fails if any frame's
# checksum differs from the host's. Needs qemu-system-arm and the two
# rustup targets (.ci/run installs them).
set -euo pipefail
cd "$(dirname "$0")/.."
quick=${1:-}
tool=(cargo run -q --release --manifest-path tools/accuracy/Cargo.toml --)

csv=$(mktemp)
trap 'rm -f "$csv"' EXIT
echo "key,scene,core,instructions,checksum" >"$csv"
for t in thumbv7em-none-eabihf thumbv6m-none-eabi; do
  if [ "$t" = thumbv6m-none-eabi ]; then machine=mps2-an385 cpu=cortex-m3; else machine=mps2-an386 cpu=cortex-m4; fi
  (cd firmware/qemu-bench && cargo build -q --release --target "$t" --bin study)
  out=$(timeout 600 qemu-system-arm -machine "$machine" -cpu "$cpu" -nographic -semihosting-config enable=on,target=native \
    -icount shift=0 -kernel "firmware/qemu-bench/target/$t/release/study")
  if ! grep -q '^calibration,instructions_per_tick,40,' <<<"$out"; then
    echo "accuracy: instructions per tick calibration is not 40 on $machine" >&2
    exit 1
  fi
  grep '^study,' <<<"$out" | cut -d, -f2- >>"$csv"
done

if [ "$quick" = --quick ]; then
  cargo test -q --release --manifest-path tools/accuracy/Cargo.toml
  "${tool[@]}" --quick --check --target "$csv"
else
  mkdir -p docs/accuracy
  cp "$csv" docs/accuracy/target.csv
  "${tool[@]}"
fi
