#!/usr/bin/env bash
# Every check CI makes, in CI's order; `.ci/run` calls this script and nothing else, so what passes
# here passes there. Formatting, lints (default and all features, the wasm32 build), rustdoc with
# warnings denied; the JavaScript's format, lint and size limits (Biome, scripts/code-shape.mjs);
# then the README's test command, `npm test` (native, wasm and browser suites; its e2e stage also
# type-checks www/ with tsc once the wasm's declarations are built).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
# Each step prints its wall time, so a CI log shows where the minutes go.
step() {
  local t0=$SECONDS
  "$@"
  echo "== check.sh: $* — $((SECONDS - t0)) s (total $SECONDS s)"
}
# The machine, for reading a CI log's step times against this one's (docs/benchmarks.md, "CI").
echo "== check.sh: $(nproc 2>/dev/null || echo '?') CPUs,$(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | cut -d: -f2 || true), $(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo 2>/dev/null || true)"
rustup component add rustfmt clippy >/dev/null 2>&1 || true
rustup target add wasm32-unknown-unknown >/dev/null 2>&1 || true
step cargo fmt --all -- --check
step cargo clippy --all-targets -- -D warnings
step cargo clippy --all-targets --all-features -- -D warnings
# The wasm32-only code (the browser view, the wasm suites) is linted too.
step cargo clippy --target wasm32-unknown-unknown --no-default-features --features web,render --lib --tests -- -D warnings
# The lab's small first module (feature `web-live` alone: docs/lab.md, "Two modules, one crate").
step cargo clippy --target wasm32-unknown-unknown --no-default-features --features web-live --lib -- -D warnings
RUSTDOCFLAGS="-D warnings" step cargo doc --no-deps --all-features
# npm packages (Biome, acorn) first; `npm test` installs the rest.
step bash scripts/ensure-tools.sh
step npm run --silent lint:js
step npm test
