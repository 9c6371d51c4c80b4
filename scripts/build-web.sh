#!/usr/bin/env bash
# Builds the lab's wasm module and assembles a static site.
#   scripts/build-web.sh www    wasm + vendor files into www/ (what `npm start` serves)
#   scripts/build-web.sh dist   a self-contained static dist/ (www/ + wasm + vendor files)
# Honours CARGO_TARGET_DIR. Set WASM_OPT=0 to skip wasm-opt.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
dest="${1:-www}"
case "$dest" in www|dist) ;; *) echo "build-web: destination must be www or dist" >&2; exit 2 ;; esac
target_dir="${CARGO_TARGET_DIR:-target}"

# Two modules from one crate: the full lab API with the renderer (wingbeat_bg.wasm), and the
# live analysis alone (wingbeat_live_bg.wasm, feature `web-live`), which the lab loads first and
# paints its first plot from while the full module loads behind it (issue 25, docs/lab.md).
wasm="$target_dir/wasm32-unknown-unknown/release/wingbeat.wasm"

if [ "$dest" = dist ]; then
  rm -rf dist
  mkdir -p dist
  cp -R www/. dist/
  rm -rf dist/pkg dist/vendor
fi
rm -rf "$dest/pkg"

# wasm-opt: npm's binaryen only (Debian's v108 emits modules Chromium rejects).
optimise() {
  local file="$1" opt=node_modules/.bin/wasm-opt
  [ "${WASM_OPT:-1}" != 0 ] || return 0
  if "$opt" -O3 --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
       --enable-mutable-globals --enable-reference-types --enable-multivalue \
       "$file" -o "$file.opt"; then
    mv "$file.opt" "$file"
  else
    echo "build-web: WARNING: wasm-opt failed on $file; keeping the unoptimised module" >&2
    rm -f "$file.opt"
  fi
}

if [ "$dest" = dist ] && [ "${PKG_FROM_WWW:-0}" = 1 ] && [ -f www/pkg/wingbeat_bg.wasm ] && [ -f www/pkg/wingbeat_live_bg.wasm ]; then
  # scripts/test-all.sh builds www/ first, from the same sources: take its modules (and their
  # compressed copies) instead of compiling, binding and compressing them again.
  echo "build-web: dist/pkg from www/pkg (PKG_FROM_WWW=1)"
  cp -Rp www/pkg "$dest/pkg"
else
# The same target directory for both: cargo keeps both builds' dependencies, and the second
# build of the crate overwrites wingbeat.wasm, so each is taken by wasm-bindgen at once. The full
# module first: `npm test` has just compiled the crate with these features for the wasm test
# suites (scripts/test-all.sh wasm; the same features resolve, Cargo.toml's serde_json line), so
# in CI this build finds it up to date and only the live module is compiled here.
cargo build --release --target wasm32-unknown-unknown --lib --no-default-features --features web,render
wasm-bindgen --target web --out-dir "$dest/pkg" --out-name wingbeat "$wasm"
# npm's wasm-opt is single-threaded and the full module is its longest job (≈ 2.5 min on a
# 2-core machine): it runs while the live module compiles and is optimised.
optimise "$dest/pkg/wingbeat_bg.wasm" &
opt_full=$!
# (a failed build stops it: the subshell and its wasm-opt)
trap 'pkill -P "$opt_full" 2>/dev/null; kill "$opt_full" 2>/dev/null || true' EXIT

cargo build --release --target wasm32-unknown-unknown --lib --no-default-features --features web-live
wasm-bindgen --target web --out-dir "$dest/pkg" --out-name wingbeat_live "$wasm"
optimise "$dest/pkg/wingbeat_live_bg.wasm"
wait "$opt_full"
trap - EXIT
fi

mkdir -p "$dest/vendor"
cp node_modules/uplot/dist/uPlot.esm.js node_modules/uplot/dist/uPlot.min.css "$dest/vendor/"
cp node_modules/uplot/LICENSE "$dest/vendor/uPlot.LICENSE" 2>/dev/null || true

# The lab's modules in one minified file, lab.bundle.js, which index.html's main.js imports
# (scripts/bundle.mjs; the modules stay for embedding and the npm package).
node scripts/bundle.mjs "$dest"

# Brotli and gzip copies of the wasm, its glue and the vendor files, which scripts/serve.mjs sends
# to browsers that accept them (the first visit's bytes, issue 25).
node scripts/precompress.mjs "$dest"

# The service worker's precache list (www/sw.js): the real files of this folder, written after
# everything else is in place (the dist/ extras below are left out by the script itself).
node scripts/precache-manifest.mjs "$dest"

if [ "$dest" = dist ]; then
  # The single-folder download: a little server (node serve.mjs), README.txt, and the service
  # worker's build stamp (a hash of the folder's files, so a new build replaces the old copy).
  cp scripts/download/serve.mjs scripts/download/README.txt dist/
  cp scripts/serve.mjs dist/serve-lib.mjs
  stamp=$(cd dist && find . -type f ! -name sw.js -print0 | LC_ALL=C sort -z | xargs -0 sha256sum | sha256sum | cut -c1-12)
  sed -i "s/const BUILD = 'dev';/const BUILD = '$stamp';/" dist/sw.js
  grep -q "const BUILD = '$stamp';" dist/sw.js || { echo "build-web: could not stamp dist/sw.js" >&2; exit 1; }
fi

for m in wingbeat_live wingbeat; do
  raw=$(wc -c < "$dest/pkg/${m}_bg.wasm")
  gz=$(gzip -9 -c "$dest/pkg/${m}_bg.wasm" | wc -c)
  echo "build-web: $dest/pkg/${m}_bg.wasm $raw bytes ($gz gzipped)"
done
echo "build-web: $dest/ ready"
