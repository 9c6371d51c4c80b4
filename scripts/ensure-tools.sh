#!/usr/bin/env bash
# Installs whatever the lab needs and is missing on this machine; skips what is already there.
#   scripts/ensure-tools.sh            wasm target, wasm-bindgen CLI (exact version), npm deps
#   scripts/ensure-tools.sh --browser  ... plus Debian's chromium + chromium-driver (tests)
#   scripts/ensure-tools.sh --wasm-pack ... plus wasm-pack (the wasm test suites; cargo install, ~5 min)
# Facts behind the choices: /work/shared/TOOLCHAIN.md (cargo install WITHOUT --locked; wasm-opt
# only from npm's binaryen; never `npx playwright install`).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

want_browser=0
want_wasm_pack=0
for a in "$@"; do
  case "$a" in
    --browser) want_browser=1 ;;
    --wasm-pack) want_wasm_pack=1 ;;
    *) echo "ensure-tools: unknown option $a" >&2; exit 2 ;;
  esac
done

# The wasm-bindgen crate is pinned exactly in Cargo.toml; the CLI must be the same version.
WB_VERSION=$(sed -n 's/^wasm-bindgen = { version = "=\([0-9.]*\)".*/\1/p' Cargo.toml)
if [ -z "$WB_VERSION" ]; then
  echo "ensure-tools: could not read the pinned wasm-bindgen version from Cargo.toml" >&2
  exit 1
fi

if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
  echo "ensure-tools: adding the wasm32-unknown-unknown target"
  rustup target add wasm32-unknown-unknown
fi

if [ "$(wasm-bindgen --version 2>/dev/null || true)" != "wasm-bindgen $WB_VERSION" ]; then
  echo "ensure-tools: installing wasm-bindgen-cli $WB_VERSION (takes about 5 minutes)"
  # No --locked: the CLI's lockfile pins a crate version the registry mirror lacks.
  cargo install wasm-bindgen-cli --version "$WB_VERSION"
fi

# wasm-pack (README, "wasm-pack"; scripts/test-all.sh wasm). --locked works for it (unlike the
# wasm-bindgen CLI). `npm install wasm-pack` cannot be used: its postinstall downloads from GitHub.
# It finds the wasm-bindgen CLI above on PATH and npm's wasm-opt (node_modules/.bin) when that is
# first on PATH; it cannot download either here.
WASM_PACK_VERSION=0.15.1
if [ "$want_wasm_pack" = 1 ] && [ "$(wasm-pack --version 2>/dev/null || true)" != "wasm-pack $WASM_PACK_VERSION" ]; then
  echo "ensure-tools: installing wasm-pack $WASM_PACK_VERSION (takes about 5 minutes)"
  cargo install wasm-pack --locked --version "$WASM_PACK_VERSION"
fi

if [ ! -x node_modules/.bin/wasm-opt ] || [ ! -d node_modules/uplot ] || [ ! -d node_modules/playwright-core ] \
   || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  echo "ensure-tools: installing npm dependencies"
  npm ci --no-audit --no-fund
fi

# Debian packages for the tests: Chromium + its driver (browser suites) and Mesa's lavapipe
# Vulkan driver (the renderer's offscreen golden-image tests run on it; no GPU needed).
if [ "$want_browser" = 1 ]; then
  pkgs=()
  { [ -x /usr/bin/chromium ] && [ -x /usr/bin/chromedriver ]; } || pkgs+=(chromium chromium-driver)
  dpkg -s mesa-vulkan-drivers >/dev/null 2>&1 || pkgs+=(mesa-vulkan-drivers)
  dpkg -s libvulkan1 >/dev/null 2>&1 || pkgs+=(libvulkan1)
  if [ "${#pkgs[@]}" -gt 0 ]; then
    echo "ensure-tools: installing ${pkgs[*]} (Debian)"
    SUDO=""
    if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
    $SUDO apt-get update
    $SUDO apt-get install -y --no-install-recommends -o DPkg::Lock::Timeout=600 "${pkgs[@]}"
  fi
fi
