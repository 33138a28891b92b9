#!/usr/bin/env bash
# Runs cargo for a bare-metal target, in the current directory (a firmware
# crate), with whichever toolchain can build for it:
#
#   scripts/fw-cargo.sh TARGET CARGO-ARGS...     e.g. fw-cargo.sh thumbv6m-none-eabi build --release
#
# - rustup's prebuilt `core` when `rustup target add TARGET` has worked;
# - otherwise (or with SOFT3D_BUILD_STD=1) Debian's rustc from `rustc-web`
#   building `core` from `rust-web-src` (-Zbuild-std, allowed on a release
#   compiler by RUSTC_BOOTSTRAP=1), linking with the rust-lld of the rustup
#   toolchain. Its artifacts go to target/build-std so the two never mix.
#   `.ci/run` installs both packages when rustup cannot add a target.
set -euo pipefail
target=$1
shift
installed=$(rustup target list --installed 2>/dev/null || true)
if [ "${SOFT3D_BUILD_STD:-0}" != 1 ] && grep -qx "$target" <<<"$installed"; then
  exec cargo "$@" --target "$target"
fi
deb_rustc=$(dpkg -L rustc-web 2>/dev/null | grep -m1 -E '/bin/rustc(-web)?$' || true)
if [ -z "$deb_rustc" ]; then
  echo "fw-cargo: no rustup target $target and no Debian rustc-web (apt-get install rustc-web rust-web-src)" >&2
  exit 1
fi
lld=$(rustc --print sysroot)/lib/rustlib/x86_64-unknown-linux-gnu/bin/rust-lld
# `--config` adds to the crate's .cargo/config.toml (its rustflags stay).
RUSTC="$deb_rustc" RUSTC_BOOTSTRAP=1 CARGO_TARGET_DIR=target/build-std exec cargo "$@" --target "$target" \
  --config "target.$target.linker=\"$lld\"" \
  -Zbuild-std=core,compiler_builtins -Zbuild-std-features=compiler-builtins-mem
