#!/usr/bin/env bash
# gaitlab build entry point.
#   ./build.sh [build] [--opt]  release wasm build of the browser app, assembled in dist/
#                               (--opt: also run wasm-opt from npm's binaryen; slow, 4-8 min)
#   ./build.sh serve [PORT]     build, then serve dist/ on http://127.0.0.1:PORT/ (default 8080)
#                               in the foreground; Ctrl-C stops it
#   ./build.sh test [--native]  formatting, lints (native and wasm32), every native test, the wasm
#                               build and the browser tests (what CI runs); --native skips the
#                               last two
#   ./build.sh bench            the performance figures (`gaitlab bench`)
#   ./build.sh bench --check [BASELINE] [--tolerance-pct N]
#                               run the same cases and compare with bench/baseline.json (or BASELINE):
#                               exits 3 naming each case more than N% (default 25) slower
#   ./build.sh bench --browser [--path webgpu]  wasm vs native per-frame time, and the time to first frame
#   ./build.sh bench --suite [--json OUT]  every bench case natively and in wasm (window.gaitlab.bench)
#   ./build.sh cli ...          run the gaitlab CLI in release mode with the given arguments
# Missing tools are installed on the way: Rust (rustup) with rustfmt, clippy and the wasm32 target,
# wasm-bindgen-cli at the version in Cargo.lock, and for the browser tests Debian's chromium and
# the npm packages pinned in tests/e2e/package-lock.json.
set -euo pipefail
cd "$(dirname "$0")"

WASM_TARGET=wasm32-unknown-unknown
WASM_PROFILE=wasm-release
TARGET_DIR=${CARGO_TARGET_DIR:-target}
E2E_DIR=tests/e2e

die() { echo "build.sh: $*" >&2; exit 1; }

as_root() {
  if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi
}

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
    rustup target list --installed 2>/dev/null | grep -q "^$WASM_TARGET\$" || rustup target add "$WASM_TARGET"
  fi
}

# The version of a package in Cargo.lock (the first entry of that name).
lock_version() {
  awk -v want="name = \"$1\"" '
    $0 == want { getline; if ($1 == "version") { gsub(/"/, "", $3); print $3; exit } }' Cargo.lock
}

# wasm-bindgen's CLI must match the wasm-bindgen crate in Cargo.lock exactly.
need_wasm_bindgen() {
  local want=$1 have
  # Another shell may be installing it right now: let it finish rather than build it twice.
  while pgrep -f 'cargo install wasm-bindgen-cli' >/dev/null 2>&1; do
    echo "build.sh: waiting for a running 'cargo install wasm-bindgen-cli'" >&2
    sleep 10
  done
  have=$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }' || true)
  if [ "$have" != "$want" ]; then
    echo "build.sh: installing wasm-bindgen-cli $want (found: ${have:-none}; takes a few minutes)" >&2
    # Without --locked: its lockfile pins a crate version this registry lacks (TOOLCHAIN.md).
    cargo install wasm-bindgen-cli --version "$want"
    have=$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }' || true)
    [ "$have" = "$want" ] || die "wasm-bindgen is $have after installing $want (is ~/.cargo/bin first in PATH?)"
  fi
}

need_node() {
  if ! command -v node >/dev/null 2>&1; then
    echo "build.sh: installing node and npm" >&2
    as_root apt-get -o DPkg::Lock::Timeout=600 update
    as_root apt-get -o DPkg::Lock::Timeout=600 install -y nodejs npm
  fi
  local major
  major=$(node -p 'process.versions.node.split(".")[0]')
  [ "$major" -ge 20 ] || die "node $(node --version) is too old: the browser tests need node >= 20"
}

need_chromium() {
  if [ ! -x /usr/bin/chromium ]; then
    echo "build.sh: installing chromium (Debian package)" >&2
    as_root apt-get -o DPkg::Lock::Timeout=600 update
    as_root apt-get -o DPkg::Lock::Timeout=600 install -y chromium
  fi
}

# playwright-core, pngjs and three (its BVHLoader reads exported BVH) exactly as
# tests/e2e/package-lock.json pins them (no browser download).
need_e2e_modules() {
  need_node
  if [ ! -f "$E2E_DIR/node_modules/.package-lock.json" ] ||
     [ "$E2E_DIR/package-lock.json" -nt "$E2E_DIR/node_modules/.package-lock.json" ]; then
    echo "== npm ci ($E2E_DIR)"
    (cd "$E2E_DIR" && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error)
  fi
}

# wasm-opt from npm's binaryen (Debian's v108 produces a broken module), installed under target/.
wasm_opt() {
  local file=$1 tools="$TARGET_DIR/npm-tools"
  need_node
  if [ ! -x "$tools/node_modules/.bin/wasm-opt" ]; then
    echo "== npm install binaryen (for wasm-opt)"
    mkdir -p "$tools"
    npm install --prefix "$tools" --no-save --no-audit --no-fund --loglevel=error binaryen@132.0.0
  fi
  echo "== wasm-opt -Os (slow)"
  # The features rustc enables by default for wasm32-unknown-unknown.
  "$tools/node_modules/.bin/wasm-opt" -Os \
    --enable-bulk-memory --enable-mutable-globals --enable-nontrapping-float-to-int \
    --enable-sign-ext --enable-reference-types --enable-multivalue \
    "$file" -o "$file.opt"
  mv "$file.opt" "$file"
}

report_size() {
  local file=$1 raw gz
  raw=$(stat -c %s "$file")
  gz=$(gzip -9 -c "$file" | wc -c)
  awk -v f="$file" -v r="$raw" -v g="$gz" \
    'BEGIN { printf "gaitlab: %s: %d bytes (%.2f MiB) raw, %d bytes (%.2f MiB) gzipped\n", f, r, r / 1048576, g, g / 1048576 }'
}

cmd_build() {
  local opt=0 arg
  for arg in "$@"; do
    case $arg in
      --opt) opt=1 ;;
      *) die "build: unknown option '$arg' (usage: ./build.sh build [--opt])" ;;
    esac
  done
  need_rust
  echo "== cargo build -p gaitlab-app --target $WASM_TARGET --profile $WASM_PROFILE"
  cargo build -p gaitlab-app --target "$WASM_TARGET" --profile "$WASM_PROFILE"
  local wasm="$TARGET_DIR/$WASM_TARGET/$WASM_PROFILE/gaitlab_app.wasm"
  [ -f "$wasm" ] || die "$wasm was not produced (is gaitlab-app a cdylib?)"

  local version
  version=$(lock_version wasm-bindgen)
  [ -n "$version" ] || die "wasm-bindgen is not in Cargo.lock"
  need_wasm_bindgen "$version"

  echo "== wasm-bindgen $version --target web → dist/"
  rm -rf dist.tmp
  mkdir -p dist.tmp
  wasm-bindgen --target web --no-typescript --out-dir dist.tmp/pkg "$wasm"
  if [ "$opt" = 1 ]; then wasm_opt dist.tmp/pkg/gaitlab_app_bg.wasm; fi
  cp index.html dist.tmp/
  cp -R web dist.tmp/web
  rm -rf dist
  mv dist.tmp dist
  report_size dist/pkg/gaitlab_app_bg.wasm
}

cmd_serve() {
  local port=${1:-8080}
  case $port in
    '' | *[!0-9]*) die "serve: PORT must be a number (usage: ./build.sh serve [PORT])" ;;
  esac
  cmd_build
  if command -v node >/dev/null 2>&1; then
    # Prints "gaitlab: http://127.0.0.1:PORT/" once it listens.
    exec node "$E2E_DIR/static-server.mjs" dist "$port"
  fi
  # The real interpreter, not pyenv's shim, so the server owns this PID (TOOLCHAIN.md).
  local python
  python=$(python3 -c 'import sys; print(sys.executable)')
  echo "gaitlab: http://127.0.0.1:$port/"
  exec "$python" -m http.server "$port" --bind 127.0.0.1 --directory dist
}

cmd_test() {
  local browser=1 arg
  for arg in "$@"; do
    case $arg in
      --native) browser=0 ;;
      *) die "test: unknown option '$arg' (usage: ./build.sh test [--native])" ;;
    esac
  done
  need_rust
  if [ -n "${CI:-}" ]; then
    # A CI clone is built once: incremental caches only cost disk (1.5 GB), and a full disk
    # fails the link with a bus error. Say how much room there is, for the record.
    export CARGO_INCREMENTAL=0
    echo "== disk: $(df -h . | awk 'NR == 2 { print $4 " free of " $2 }')"
  fi
  echo "== cargo fmt --check"
  cargo fmt --all -- --check
  echo "== cargo clippy (native, all targets, warnings are errors)"
  cargo clippy --workspace --all-targets --quiet -- -D warnings
  echo "== cargo doc (broken intra-doc links are errors)"
  RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps --quiet
  echo "== cargo clippy (wasm32: the crates the browser app uses, the tuner it will run in Web Workers, and the app)"
  cargo clippy -p gaitlab-core -p gaitlab-motion -p gaitlab-physics -p gaitlab-engine -p gaitlab-tuner -p gaitlab-app --target "$WASM_TARGET" --quiet -- -D warnings
  echo "== import cycles between modules (tools/module_cycles.py)"
  python3 tools/module_cycles.py
  echo "== the app's folders: none imports another both ways (issue 44 item 6)"
  python3 tools/module_cycles.py --folders crates/app/src

  local status=0 log e2e_log
  log=$(mktemp)
  e2e_log=$(mktemp)

  echo "== cargo test"
  set +e
  cargo test --workspace 2>&1 | tee "$log"
  [ "${PIPESTATUS[0]}" = 0 ] || status=1
  set -e

  local e2e_pass=0 e2e_fail=0
  if [ "$browser" = 1 ]; then
    # A separate shell, so that `set -e` still stops the build at its first failure.
    if bash ./build.sh build; then
      need_chromium
      need_e2e_modules
      echo "== browser tests (node --test, playwright-core, $(/usr/bin/chromium --version 2>/dev/null | head -1))"
      set +e
      (cd "$E2E_DIR" && node --test --test-concurrency=1 --test-reporter=tap ./*.test.mjs) 2>&1 | tee "$e2e_log"
      local e2e_status=${PIPESTATUS[0]}
      set -e
      e2e_pass=$(awk '/^# pass / { n = $3 } END { print n + 0 }' "$e2e_log")
      e2e_fail=$(awk '/^# (fail|cancelled) / { n += $3 } END { print n + 0 }' "$e2e_log")
      local skipped
      skipped=$(awk '/^# skipped / { n = $3 } END { print n + 0 }' "$e2e_log")
      [ "$skipped" = 0 ] || echo "browser tests: $skipped skipped (see '# SKIP' above)"
      if [ "$e2e_status" != 0 ]; then
        status=1
        # A run that died before its summary still counts as a failure.
        [ "$e2e_fail" != 0 ] || e2e_fail=1
      fi
    else
      echo "build.sh: the wasm build failed; browser tests not run" >&2
      status=1
      e2e_fail=1
    fi
  fi

  # One closing line for the whole run: every test binary plus the browser tests.
  awk -v ep="$e2e_pass" -v ef="$e2e_fail" '
    /^test result:/ { passed += $4; failed += $6 }
    END { printf "tests: %d passed, %d failed\n", passed + ep, failed + ef }' "$log"
  rm -f "$log" "$e2e_log"
  return "$status"
}

cmd_bench() {
  need_rust
  if [ "${1:-}" = "--suite" ]; then
    # The performance budget's table: every suite case natively and in wasm, with the ratio.
    cmd_build
    need_node; need_chromium; need_e2e_modules
    local native_json="$PWD/$TARGET_DIR/bench-native.json"
    case "$TARGET_DIR" in /*) native_json="$TARGET_DIR/bench-native.json" ;; esac
    cargo run --release --quiet -p gaitlab-cli -- bench --json > "$native_json"
    (cd "$E2E_DIR" && node bench-suite.mjs --native "$native_json" "${@:2}")
    return
  fi
  if [ "${1:-}" != "--browser" ]; then
    cargo run --release --quiet -p gaitlab-cli -- bench "$@"
    return
  fi
  # The wasm/native ratio: the same per-frame work (human, walk, SDLS, 600 frames x 15) timed by
  # `gaitlab bench` natively and by window.gaitlab.bench() in headless Chromium, plus the time
  # from navigation to the first frame.
  cmd_build
  need_node; need_chromium; need_e2e_modules
  local native browser
  native=$(cargo run --release --quiet -p gaitlab-cli -- bench --preset human --method sdls --json)
  browser=$(cd "$E2E_DIR" && node bench.mjs "${@:2}")
  NATIVE="$native" BROWSER="$browser" node -e '
    const n = JSON.parse(process.env.NATIVE).ik[0];
    const b = JSON.parse(process.env.BROWSER);
    const w = b.wasm;
    console.log(`per frame (human, walk, sdls, ${w.iterations_per_frame} IK iterations):`);
    console.log(`  native  ${n.us_per_frame.toFixed(1)} us median, ${n.us_per_frame_best.toFixed(1)} best`);
    console.log(`  wasm    ${w.us_per_frame.toFixed(1)} us median, ${w.us_per_frame_best.toFixed(1)} best`);
    console.log(`  ratio   ${(w.us_per_frame / n.us_per_frame).toFixed(2)}x median, ${(w.us_per_frame_best / n.us_per_frame_best).toFixed(2)}x best (target <= 2x)`);
    const line = (kind, f, what) => console.log(`navigation -> first frame (${b.path}, ${kind}): ` +
      `median ${f.median === null ? "-" : f.median.toFixed(0)} ms, max ${f.max === null ? "-" : f.max.toFixed(0)} ms, ` +
      `${f.within_2s} of ${f.all.length} <= 2000 ms (${what})`);
    line("warm", b.first_frame_ms.warm, "later loads in one browser");
    line("cold", b.first_frame_ms.cold, "first load of a freshly launched browser");
    console.log(JSON.stringify({ native: n, browser: b }));'
}

cmd_cli() {
  need_rust
  cargo run --release --quiet -p gaitlab-cli -- "$@"
}

case "${1:-build}" in
  build) shift || true; cmd_build "$@" ;;
  --opt) cmd_build "$@" ;;
  test) shift; cmd_test "$@" ;;
  bench) shift; cmd_bench "$@" ;;
  cli) shift; cmd_cli "$@" ;;
  serve) shift; cmd_serve "$@" ;;
  *) echo "usage: ./build.sh [build [--opt] | serve [PORT] | test [--native] | bench [--check [BASELINE] | --browser | --suite] | cli ARGS...]" >&2; exit 2 ;;
esac
