#!/usr/bin/env bash
# Runs every test of the project (what `npm test` calls):
#   scripts/test-all.sh [all|native|wasm|e2e]
#   native  cargo nextest run --all-features + cargo test --doc (cargo test --all-features where
#           nextest is missing): core, CLI, FE backends, renderer goldens on lavapipe, and the
#           wasm API's plain-Rust helpers
#   wasm    wasm-bindgen-test suites through wasm-pack (README, "wasm-pack"): tests/wasm_api.rs
#           with `wasm-pack test --node`, tests/wasm_browser.rs with `--headless --chrome`
#   e2e     build the lab (www/ and the dist/ download), type-check www/ (npm run check:js: tsc, ~2-3 s), then node --test
#           (two test files at a time, one per two cores on bigger machines, at most four;
#           WINGBEAT_E2E_JOBS=N sets it):
#           tests/js (unit + the real wasm in node) and tests/e2e (Playwright + Debian Chromium)
#   all     the three in that order; on 4 or more CPUs the wasm suites and the lab's build run
#           beside the native suite, then the browser tests (WINGBEAT_OVERLAP=1 / 0 forces it)
# Installs what is missing first (scripts/ensure-tools.sh --browser [--wasm-pack]). Honours CARGO_TARGET_DIR.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
what="${1:-all}"

native() {
  echo "== native: the tests of cargo test --all-features (renderer goldens on Mesa lavapipe, required)"
  # The renderer's GPU tests must not silently skip here: ensure-tools installed lavapipe.
  export WINGBEAT_REQUIRE_GPU="${WINGBEAT_REQUIRE_GPU:-1}"
  if [ -z "${XDG_RUNTIME_DIR:-}" ]; then
    XDG_RUNTIME_DIR="$(mktemp -d)"
    chmod 0700 "$XDG_RUNTIME_DIR"
    export XDG_RUNTIME_DIR
  fi
  # cargo-nextest (on the machine image, /usr/local/bin) runs the test binaries side by side, not
  # one after another: 75 s instead of 95 s on this 2-core machine (2026-12-03, 331 tests), more
  # with more cores. It does not run doc tests: `cargo test --doc` does. Without it, cargo test.
  if cargo nextest --version >/dev/null 2>&1; then
    cargo nextest run --all-features --no-fail-fast
    cargo test --all-features --doc
  else
    cargo test --all-features
  fi
}

wasm() {
  echo "== wasm: wasm-pack test --node (tests/wasm_api.rs) and --headless --chrome (tests/wasm_browser.rs)"
  # npm's binaryen wasm-opt first on PATH: wasm-pack cannot download its own.
  export PATH="$PWD/node_modules/.bin:$PATH"
  export WASM_BINDGEN_TEST_TIMEOUT=300
  # The README's commands, limited to the two wasm_bindgen_test suites (the other test targets
  # hold only native #[test]s; linking each for wasm32 would cost minutes and run nothing).
  # --release and the lab's features, as scripts/build-web.sh: the wasm dependencies compile once.
  local args=(--release -- --no-default-features --features web,render)
  wasm-pack test --node "${args[@]}" --test wasm_api
  wasm-pack test --headless --chrome --chromedriver /usr/bin/chromedriver "${args[@]}" --test wasm_browser
}

e2e_build() {
  echo "== e2e: build the lab (www/ and the dist/ download)"
  bash scripts/build-web.sh www
  # The teachers' single-folder download, checked by tests/e2e/offline.test.mjs (its two wasm
  # modules and their compressed copies are www/'s, just built from the same sources).
  PKG_FROM_WWW=1 bash scripts/build-web.sh dist
  echo "== e2e: type-check the lab's JavaScript (tsc --noEmit over www/ against pkg/wingbeat.d.ts and uPlot's types)"
  npm run --silent check:js
}

e2e_run() {
  echo "== e2e: node --test tests/js tests/e2e"
  # Test files run side by side: a browser test waits on Chromium's renderer and GPU processes
  # much of the time, so two at once pay even on 2 cores (2026-12-03, this 2-core machine, the same
  # 417 tests: 1304 s one file at a time, 1061 s two at a time); with more cores, one file per two
  # cores, at most four (WINGBEAT_E2E_JOBS=N overrides). Every file starts its own server on a free
  # port and its own browser, and writes only files named after its own tests.
  local jobs="${WINGBEAT_E2E_JOBS:-$(node -e 'const n = require("os").availableParallelism(); console.log(Math.max(2, Math.min(4, Math.floor(n / 2))))')}"
  if ! [[ "$jobs" =~ ^[1-9][0-9]?$ ]]; then
    echo "test-all: WINGBEAT_E2E_JOBS must be a whole number from 1 to 99 (got '$jobs')" >&2
    exit 2
  fi
  echo "== e2e: node --test, $jobs test files at a time"
  node --test --test-concurrency="$jobs" tests/js/ tests/e2e/
}

e2e() {
  e2e_build
  e2e_run
}

# Whether `all` runs the wasm suites and the lab's build beside the native suite: on 4 or more
# CPUs (a 2-core machine is kept busy by either alone). The native build (target/debug) and the
# wasm builds (target/wasm32-unknown-unknown/release, host tools in target/release) lock different
# build directories, so neither waits for the other; the lab's build spends minutes in npm's
# single-threaded wasm-opt. WINGBEAT_OVERLAP=1 / 0 forces it on / off.
overlap() {
  case "${WINGBEAT_OVERLAP:-auto}" in
    1) return 0 ;;
    0) return 1 ;;
    auto) [ "$(nproc 2>/dev/null || echo 1)" -ge 4 ] ;;
    *) echo "test-all: WINGBEAT_OVERLAP must be 1, 0 or auto (got '${WINGBEAT_OVERLAP}')" >&2; exit 2 ;;
  esac
}

# The wasm suites, then the lab's build, in the background with their output in a file (shown
# when they end); the native suite in the foreground. A failure of either fails the run.
all_overlapped() {
  local log bg t0=$SECONDS
  log="$(mktemp)"
  echo "== $(nproc) CPUs: the wasm suites and the lab's build run beside the native suite (their log follows it)"
  set -m # the background stage in its own process group, so a failure here can stop all of it
  # Its compiles get half the CPUs (the native build takes them all), so at most about 1.5× the
  # usual number of compilers share the machine's memory.
  (
    jobs=$(($(nproc) / 2)); export CARGO_BUILD_JOBS=$((jobs > 0 ? jobs : 1))
    t=$SECONDS; wasm; echo "== wasm: $((SECONDS - t)) s"
    t=$SECONDS; e2e_build; echo "== e2e build: $((SECONDS - t)) s"
  ) >"$log" 2>&1 &
  bg=$!
  set +m
  # shellcheck disable=SC2064 # the values are fixed now
  trap "kill -TERM -- -$bg 2>/dev/null || true; echo '== the wasm suites and the lab build (stopped):'; tail -n 40 '$log'" EXIT
  native
  echo "== native: $((SECONDS - t0)) s"
  local ok=1
  wait "$bg" || ok=0
  trap - EXIT
  echo "== the wasm suites and the lab's build, beside it (until $((SECONDS - t0)) s):"
  cat "$log"
  rm -f "$log"
  [ "$ok" = 1 ] || { echo "test-all: the wasm suites or the lab's build failed (above)" >&2; exit 1; }
}

case "$what" in
  native) bash scripts/ensure-tools.sh --browser; native ;;
  wasm) bash scripts/ensure-tools.sh --browser --wasm-pack; wasm ;;
  e2e) bash scripts/ensure-tools.sh --browser; e2e ;;
  all)
    # Each stage's wall time in the log (CI shows where the minutes go).
    t0=$SECONDS; bash scripts/ensure-tools.sh --browser --wasm-pack; echo "== tools: $((SECONDS - t0)) s"
    if overlap; then
      all_overlapped
      t0=$SECONDS; e2e_run; echo "== e2e tests: $((SECONDS - t0)) s"
    else
      t0=$SECONDS; native; echo "== native: $((SECONDS - t0)) s"
      t0=$SECONDS; wasm; echo "== wasm: $((SECONDS - t0)) s"
      t0=$SECONDS; e2e; echo "== e2e: $((SECONDS - t0)) s"
    fi
    echo "== all test suites passed ($SECONDS s)" ;;
  *) echo "usage: scripts/test-all.sh [all|native|wasm|e2e]" >&2; exit 2 ;;
esac
