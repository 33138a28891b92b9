# Board firmware (docs/boards.md): format check, clippy and a release build
# of each board's crate. Nothing here runs on hardware; the rendering itself
# is checked by the emulated benchmark (firmware/qemu-bench).
#
# Sourced by .ci/run from the repository root with `set -euo pipefail`
# active; uses its target_installed. Everything runs in subshells so the
# working directory is left alone.

# Builds firmware/$1 for target $2: with rustup's target (added if
# needed) it is also linted; without, scripts/fw-cargo.sh builds it with
# Debian's rustc-web and a `core` built from rust-web-src.
firmware_board() {
  local board=$1 target=$2
  echo "-- firmware/$board ($target)"
  if ! target_installed "$target"; then
    rustup target add "$target" || true
  fi
  (
    cd "firmware/$board"
    if cargo fmt --version >/dev/null 2>&1; then
      cargo fmt -- --check
    else
      echo "note: rustfmt not installed, skipping the format check of firmware/$board"
    fi
    local elf="target/$target/release/soft3d-$board"
    if target_installed "$target"; then
      cargo clippy --release -- -D warnings
      cargo build --release
    else
      echo "note: rustup target $target unavailable; building with -Zbuild-std, not linted"
      ../../scripts/fw-cargo.sh "$target" build --release
      elf="target/build-std/$target/release/soft3d-$board"
    fi
    test -s "$elf"
    if command -v llvm-size >/dev/null 2>&1; then
      # Berkeley format: text (code, read-only data, vectors) and the .data
      # image are in flash; .data and .bss are static RAM.
      llvm-size -B "$elf" | awk -v b="$board" 'NR == 2 { printf "%s: flash %d bytes, static RAM %d bytes\n", b, $1 + $2, $2 + $3 }'
    fi
  )
}

firmware_board rp2040-st7789 thumbv6m-none-eabi
firmware_board stm32f4-ili9341 thumbv7em-none-eabihf
firmware_board rp2350-st7789 thumbv8m.main-none-eabihf
unset -f firmware_board
