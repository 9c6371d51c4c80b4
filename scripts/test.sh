#!/usr/bin/env bash
# Runs every test of wingbeat. Installs nothing beyond what cargo fetches itself.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo test --all-targets
cargo test --doc
# the optional faer sparse backend against the skyline one
cargo test --features faer --test fem_backends
