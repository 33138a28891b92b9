# The accuracy study (docs/accuracy.md): the tool's lint and tests, then a
# check, with fresh emulator figures, that the committed tables of the
# built-in scenes are current. Sourced by .ci/run.
if cargo fmt --version >/dev/null 2>&1; then (cd tools/accuracy && cargo fmt -- --check); fi
(cd tools/accuracy && cargo clippy --release --all-targets -- -D warnings)
if target_installed thumbv6m-none-eabi && target_installed thumbv7em-none-eabihf; then
  command -v qemu-system-arm >/dev/null || apt_install qemu-system-arm
  bash scripts/accuracy.sh --quick
  # A flat scene pays nothing for unused effects (fails beyond 1%).
  bash scripts/effects-bench.sh
else
  # The committed tables hold instruction counts of the rustup toolchain's
  # code; Debian's older compiler (the -Zbuild-std fallback) emits other code.
  echo "note: rustup targets unavailable; accuracy check skipped (its figures are the rustup compiler's)"
fi
