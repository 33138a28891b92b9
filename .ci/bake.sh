# The bake tool (tools/bake): its own cargo workspace, a host program.
# Sourced by .ci/run (bash, set -euo pipefail, cwd = repository root); the
# subshell keeps the cd from leaking into the steps after this one.
(
  if [ ! -f tools/bake/Cargo.toml ]; then
    echo "note: tools/bake is absent; bake tool checks skipped"
    exit 0
  fi
  cd tools/bake
  if cargo fmt --version >/dev/null 2>&1; then
    cargo fmt -- --check
  else
    echo "note: rustfmt not installed, skipping the bake tool's format check"
  fi
  cargo clippy --all-targets -- -D warnings
  # Includes tests/compile.rs, which builds (and clippy-checks, and tests)
  # the generated source in a scratch no_std crate under target/tmp.
  cargo test
  # The demo's baked crate (src/scenes/crate_scene.rs) must be what the
  # bake tool makes of assets/demo today.
  fresh=$(mktemp -d)
  cargo run --quiet --release -- ../../assets/demo/crate.babylon -o "$fresh/crate_scene.rs" --quantize i16 >/dev/null
  if ! diff -u ../../src/scenes/crate_scene.rs "$fresh/crate_scene.rs"; then
    echo "src/scenes/crate_scene.rs is stale; rebake it with the command in src/scenes/mod.rs"
    exit 1
  fi
  rm -rf "$fresh"
  # CLI smoke test on a real scene (the shared assets are never copied
  # into the repository; they sit beside it when present).
  monkey=../../../shared/assets/monkey.babylon
  if [ -f "$monkey" ]; then
    out=$(mktemp -d)
    cargo run --quiet -- "$monkey" -o "$out/monkey.rs" --quantize i16 --texture-format palette8
    grep -q 'pub static SUZANNE: ::soft3d::mesh::Mesh' "$out/monkey.rs"
    rm -rf "$out"
  else
    echo "note: $monkey absent; bake CLI smoke test skipped"
  fi
)
