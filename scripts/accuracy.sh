#!/usr/bin/env bash
# The accuracy study (docs/accuracy.md): every precision choice rendered
# against an exact reference, with its cost on emulated Cortex-M cores.
#
#   bash scripts/accuracy.sh          # regenerates docs/accuracy.md, docs/accuracy/ (figures, target.csv,
#                                     # micromath.csv, mathfns.csv, effects.csv, host.csv)
#   bash scripts/accuracy.sh --quick  # CI: the study tool's tests, then checks that the committed
#                                     # tables of the built-in scenes are current (fresh emulator figures)
#
# Emulator figures come from firmware/qemu-bench's `study` binary on
# mps2-an386 (Cortex-M4F) and mps2-an385 (thumbv6m code, the M0+ stand-in),
# `key,scene,core,instructions,checksum` rows; the tool fails if any frame's
# checksum differs from the host's. The math-backend rows come from second
# builds of both with soft3d's `micromath` feature (keys `+micromath`), the
# per-call figures of the math functions from the `mathfns` binary. Needs
# qemu-system-arm and the two rustup targets (.ci/run installs them).
set -euo pipefail
cd "$(dirname "$0")/.."
quick=${1:-}
tool=(cargo run -q --release --manifest-path tools/accuracy/Cargo.toml --)
# The configurations also rendered with micromath (tools/accuracy/src/backend.rs).
micromath_keys=fixed-6-span16-nearest-gouraud,f32-6-span16-nearest-gouraud,f32-6-span16-nearest-phong

csv=$(mktemp) calls=$(mktemp) micromath=$(mktemp)
trap 'rm -f "$csv" "$calls" "$micromath"' EXIT
echo "key,scene,core,instructions,checksum" >"$csv"

# Runs firmware/qemu-bench binary $2 built for target $1 in QEMU.
run() {
  local t=$1 bin=$2 machine=mps2-an386 cpu=cortex-m4
  if [ "$t" = thumbv6m-none-eabi ]; then machine=mps2-an385 cpu=cortex-m3; fi
  timeout 900 qemu-system-arm -machine "$machine" -cpu "$cpu" -nographic -semihosting-config enable=on,target=native \
    -icount shift=0 -kernel "firmware/qemu-bench/target/$t/release/$bin"
}

for t in thumbv7em-none-eabihf thumbv6m-none-eabi; do
  # Every configuration with libm, then the math-backend ones with micromath
  # (a separate build: the backend is a feature of the whole crate).
  for backend in libm micromath; do
    if [ $backend = libm ]; then
      (cd firmware/qemu-bench && cargo build -q --release --target "$t" --bin study)
    else
      (cd firmware/qemu-bench && SOFT3D_STUDY_ONLY=$micromath_keys cargo build -q --release --target "$t" --bin study \
        --no-default-features --features micromath)
    fi
    out=$(run "$t" study)
    if ! grep -q '^calibration,instructions_per_tick,40,' <<<"$out"; then
      echo "accuracy: instructions per tick calibration is not 40 on $t" >&2
      exit 1
    fi
    grep '^study,' <<<"$out" | cut -d, -f2- >>"$csv"
  done
  (cd firmware/qemu-bench && cargo build -q --release --target "$t" --bin mathfns)
  out=$(run "$t" mathfns)
  # soft3d's square root (the FPU's on the M4F) against libm's, bit for bit.
  check=$(grep '^mathcheck,sqrt,' <<<"$out" || true)
  if [ -z "$check" ] || [ "$(cut -d, -f5 <<<"$check")" != 0 ]; then
    echo "accuracy: soft3d's sqrt differs from libm's on $t: ${check:-no mathcheck line}" >&2
    exit 1
  fi
  echo "$check"
  grep '^mathfn,' <<<"$out" | cut -d, -f2- >>"$calls"
done
# The host's micromath renders (errors and checksums of the twins).
cargo run -q --release --manifest-path tools/accuracy/Cargo.toml --no-default-features --features micromath -- \
  ${quick:+--quick} --micromath "$micromath"

if [ "$quick" = --quick ]; then
  cargo test -q --release --manifest-path tools/accuracy/Cargo.toml
  "${tool[@]}" --quick --check --target "$csv" --micromath "$micromath" --calls "$calls"
else
  mkdir -p docs/accuracy
  cp "$csv" docs/accuracy/target.csv
  cp "$calls" docs/accuracy/mathfns.csv
  cp "$micromath" docs/accuracy/micromath.csv
  # Pay for what you use (emulated firmware builds; fails if a flat scene
  # pays more than 1% for effects it does not use).
  bash scripts/effects-bench.sh --csv docs/accuracy/effects.csv
  # Host time per frame (criterion; noisy on a shared machine, so only
  # the full run refreshes docs/accuracy/host.csv).
  cargo bench -q --features simulator --bench study
  "${tool[@]}" --criterion target/criterion
fi
