#!/usr/bin/env bash
# What CI checks, in CI's order: formatting, lints, then the README's test command.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo fmt --all -- --check
cargo clippy --all-targets -- -D warnings
# the optional faer sparse backend (docs/fem.md, "Sparse factorisation backends")
cargo clippy --all-targets --features faer -- -D warnings
./scripts/test.sh
