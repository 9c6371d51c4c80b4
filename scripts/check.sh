#!/usr/bin/env bash
# What CI checks, in CI's order (.ci/run): formatting, lints (default and all features, the
# wasm32 build), rustdoc with warnings denied, then
# the README's test command, `npm test` (native, wasm and browser suites).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo fmt --all -- --check
cargo clippy --all-targets -- -D warnings
cargo clippy --all-targets --all-features -- -D warnings
# The wasm32-only code (the browser view, the wasm suites) is linted too.
cargo clippy --target wasm32-unknown-unknown --no-default-features --features web,render --lib --tests -- -D warnings
RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --all-features
npm test
