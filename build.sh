#!/usr/bin/env bash
# gaitlab build entry point.
#   ./build.sh test     formatting, lints and every native test (what CI runs)
#   ./build.sh bench    the performance figures (`gaitlab bench`)
#   ./build.sh serve    build and serve the browser app (arrives with the app crate)
#   ./build.sh cli ...  run the gaitlab CLI in release mode with the given arguments
set -euo pipefail
cd "$(dirname "$0")"

need_rust() {
  if ! command -v cargo >/dev/null 2>&1; then
    if [ -x "$HOME/.cargo/bin/cargo" ]; then
      export PATH="$HOME/.cargo/bin:$PATH"
    else
      echo "build.sh: installing the Rust toolchain with rustup" >&2
      curl --proto '=https' --tlsv1.2 -sSf https://sh.rustup.rs | sh -s -- -y --profile minimal
      export PATH="$HOME/.cargo/bin:$PATH"
    fi
  fi
  if command -v rustup >/dev/null 2>&1; then
    rustup component list --installed 2>/dev/null | grep -q '^rustfmt' || rustup component add rustfmt
    rustup component list --installed 2>/dev/null | grep -q '^clippy' || rustup component add clippy
    rustup target list --installed 2>/dev/null | grep -q '^wasm32-unknown-unknown$' || rustup target add wasm32-unknown-unknown
  fi
}

cmd_test() {
  need_rust
  echo "== cargo fmt --check"
  cargo fmt --all -- --check
  echo "== cargo clippy (native, all targets, warnings are errors)"
  cargo clippy --workspace --all-targets --quiet -- -D warnings
  echo "== cargo clippy (wasm32: the crates the browser app will use)"
  cargo clippy -p gaitlab-core -p gaitlab-motion --target wasm32-unknown-unknown --quiet -- -D warnings
  echo "== cargo test"
  local log
  log=$(mktemp)
  set +e
  cargo test --workspace 2>&1 | tee "$log"
  local status=${PIPESTATUS[0]}
  set -e
  # One closing line for the whole run: the sum over every test binary.
  awk '/^test result:/ { passed += $4; failed += $6 } END { printf "tests: %d passed, %d failed\n", passed, failed }' "$log"
  rm -f "$log"
  return "$status"
}

cmd_bench() {
  need_rust
  cargo run --release --quiet -p gaitlab-cli -- bench "$@"
}

cmd_cli() {
  need_rust
  cargo run --release --quiet -p gaitlab-cli -- "$@"
}

cmd_serve() {
  echo "The browser app is not built yet (it is the next milestone)." >&2
  echo "Meanwhile the engine runs from the command line, e.g.:" >&2
  echo "  ./build.sh cli run human --mode walk --method sdls --seconds 20 --json" >&2
  exit 1
}

case "${1:-test}" in
  test) shift || true; cmd_test "$@" ;;
  bench) shift; cmd_bench "$@" ;;
  cli) shift; cmd_cli "$@" ;;
  serve) shift; cmd_serve "$@" ;;
  *) echo "usage: ./build.sh [test|bench|serve|cli ARGS...]" >&2; exit 2 ;;
esac
