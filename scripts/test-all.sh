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

e2e() {
  echo "== e2e: build the lab, then node --test tests/js tests/e2e"
  bash scripts/build-web.sh www
  # The teachers' single-folder download, checked by tests/e2e/offline.test.mjs (its two wasm
  # modules and their compressed copies are www/'s, just built from the same sources).
  PKG_FROM_WWW=1 bash scripts/build-web.sh dist
  echo "== e2e: type-check the lab's JavaScript (tsc --noEmit over www/ against pkg/wingbeat.d.ts and uPlot's types)"
  npm run --silent check:js
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

case "$what" in
  native) bash scripts/ensure-tools.sh --browser; native ;;
  wasm) bash scripts/ensure-tools.sh --browser --wasm-pack; wasm ;;
  e2e) bash scripts/ensure-tools.sh --browser; e2e ;;
  all)
    # Each stage's wall time in the log (CI shows where the minutes go).
    t0=$SECONDS; bash scripts/ensure-tools.sh --browser --wasm-pack; echo "== tools: $((SECONDS - t0)) s"
    t0=$SECONDS; native; echo "== native: $((SECONDS - t0)) s"
    t0=$SECONDS; wasm; echo "== wasm: $((SECONDS - t0)) s"
    t0=$SECONDS; e2e; echo "== e2e: $((SECONDS - t0)) s"
    echo "== all test suites passed ($SECONDS s)" ;;
  *) echo "usage: scripts/test-all.sh [all|native|wasm|e2e]" >&2; exit 2 ;;
esac
