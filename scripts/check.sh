#!/usr/bin/env bash
# What CI checks, in CI's order (.ci/run): formatting, lints (default and all features), then
# the README's test command, `npm test` (native, wasm and browser suites).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo fmt --all -- --check
cargo clippy --all-targets -- -D warnings
cargo clippy --all-targets --all-features -- -D warnings
npm test
