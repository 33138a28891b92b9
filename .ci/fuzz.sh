# Fuzzing (fuzz/): each cargo-fuzz target for FUZZ_SECONDS (default 60),
# seeded with the committed corpus in tests/data/fuzz/<target>; a crash
# fails CI. Sourced by .ci/run (bash, set -euo pipefail, cwd = repository
# root), so it never exits the caller: the work runs in a subshell, and a
# missing nightly toolchain or cargo-fuzz is a note, not a failure.
(
  if [ ! -f fuzz/Cargo.toml ]; then
    echo "note: fuzz/ is absent; fuzzing skipped"
    exit 0
  fi
  # rustup needs its own download server, which CI may not reach.
  if ! rustup toolchain install nightly --profile minimal; then
    echo "note: no nightly toolchain (rustup unreachable?); fuzzing skipped"
    exit 0
  fi
  if ! cargo +nightly fuzz --version >/dev/null 2>&1; then
    if ! cargo install cargo-fuzz --locked; then
      echo "note: cargo-fuzz could not be installed; fuzzing skipped"
      exit 0
    fi
  fi
  seconds=${FUZZ_SECONDS:-60}
  cd fuzz
  cargo +nightly fuzz build
  for target in raster clip babylon; do
    echo "-- $target (${seconds}s)"
    # A scratch corpus: what the run adds is not kept, the committed seeds
    # are only read.
    work=$(mktemp -d)
    seeds=../tests/data/fuzz/$target
    [ "$target" = babylon ] && seeds=../tests/data/babylon
    case $target in
      raster) args=(-max_len=128) ;;
      clip) args=(-max_len=512) ;;
      babylon) args=(-max_len=8192 -dict=babylon.dict) ;;
    esac
    # A crash makes cargo fuzz exit non-zero, which set -e turns into a
    # CI failure; the input is left in fuzz/artifacts/$target/.
    cargo +nightly fuzz run "$target" "$work" "$seeds" -- "${args[@]}" -max_total_time="$seconds" -print_final_stats=1
    rm -rf "$work"
  done
)
