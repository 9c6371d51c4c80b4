#!/usr/bin/env bash
# Runs every test of the project (what `npm test` calls):
#   scripts/test-all.sh [all|native|wasm|e2e]
#   native  cargo test --all-features (core, CLI, FE backends, renderer goldens on lavapipe,
#           and the wasm API's plain-Rust helpers)
#   wasm    wasm-bindgen-test suites: tests/wasm_api.rs in node, tests/wasm_browser.rs in Chromium
#   e2e     build the lab, type-check www/ (npm run check:js: tsc, ~2-3 s), then node --test:
#           tests/js (unit + the real wasm in node) and tests/e2e (Playwright + Debian Chromium)
# Installs what is missing first (scripts/ensure-tools.sh --browser). Honours CARGO_TARGET_DIR.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
what="${1:-all}"

native() {
  echo "== native: cargo test --all-features (renderer goldens on Mesa lavapipe, required)"
  # The renderer's GPU tests must not silently skip here: ensure-tools installed lavapipe.
  export WINGBEAT_REQUIRE_GPU="${WINGBEAT_REQUIRE_GPU:-1}"
  if [ -z "${XDG_RUNTIME_DIR:-}" ]; then
    XDG_RUNTIME_DIR="$(mktemp -d)"
    chmod 0700 "$XDG_RUNTIME_DIR"
    export XDG_RUNTIME_DIR
  fi
  cargo test --all-features
}

wasm() {
  echo "== wasm: wasm-bindgen-test in node and headless Chromium"
  export CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER=wasm-bindgen-test-runner
  export WASM_BINDGEN_TEST_TIMEOUT=300
  # The same features as the lab build (scripts/build-web.sh), so the wasm dependencies compile once.
  local args=(--release --target wasm32-unknown-unknown --no-default-features --features web,render)
  cargo test "${args[@]}" --test wasm_api
  CHROMEDRIVER=/usr/bin/chromedriver cargo test "${args[@]}" --test wasm_browser
}

e2e() {
  echo "== e2e: build the lab, then node --test tests/js tests/e2e"
  bash scripts/build-web.sh www
  echo "== e2e: type-check the lab's JavaScript (tsc --noEmit over www/ against pkg/wingbeat.d.ts and uPlot's types)"
  npm run --silent check:js
  node --test --test-concurrency=1 tests/js/ tests/e2e/
}

case "$what" in
  native) bash scripts/ensure-tools.sh --browser; native ;;
  wasm) bash scripts/ensure-tools.sh --browser; wasm ;;
  e2e) bash scripts/ensure-tools.sh --browser; e2e ;;
  all) bash scripts/ensure-tools.sh --browser; native; wasm; e2e; echo "== all test suites passed" ;;
  *) echo "usage: scripts/test-all.sh [all|native|wasm|e2e]" >&2; exit 2 ;;
esac
