#!/usr/bin/env bash
# Every check CI makes, in CI's order; `.ci/run` calls this script and nothing else, so what passes
# here passes there. Formatting, lints (default and all features, the wasm32 build), rustdoc with
# warnings denied; the JavaScript's format, lint and size limits (Biome, scripts/code-shape.mjs);
# then the README's test command, `npm test` (native, wasm and browser suites; its e2e stage also
# type-checks www/ with tsc once the wasm's declarations are built).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
rustup component add rustfmt clippy >/dev/null 2>&1 || true
rustup target add wasm32-unknown-unknown >/dev/null 2>&1 || true
cargo fmt --all -- --check
cargo clippy --all-targets -- -D warnings
cargo clippy --all-targets --all-features -- -D warnings
# The wasm32-only code (the browser view, the wasm suites) is linted too.
cargo clippy --target wasm32-unknown-unknown --no-default-features --features web,render --lib --tests -- -D warnings
# The lab's small first module (feature `web-live` alone: docs/lab.md, "Two modules, one crate").
cargo clippy --target wasm32-unknown-unknown --no-default-features --features web-live --lib -- -D warnings
RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --all-features
# npm packages (Biome, acorn) first; `npm test` installs the rest.
bash scripts/ensure-tools.sh
npm run --silent lint:js
npm test
