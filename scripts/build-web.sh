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

cargo build --release --target wasm32-unknown-unknown --lib --no-default-features --features web,render
wasm="$target_dir/wasm32-unknown-unknown/release/wingbeat.wasm"

if [ "$dest" = dist ]; then
  rm -rf dist
  mkdir -p dist
  cp -R www/. dist/
  rm -rf dist/pkg dist/vendor
fi

rm -rf "$dest/pkg"
wasm-bindgen --target web --out-dir "$dest/pkg" --out-name wingbeat "$wasm"

if [ "${WASM_OPT:-1}" != 0 ]; then
  # npm's binaryen only: Debian's (v108) emits modules Chromium rejects.
  opt=node_modules/.bin/wasm-opt
  if "$opt" -O3 --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
       --enable-mutable-globals --enable-reference-types --enable-multivalue \
       "$dest/pkg/wingbeat_bg.wasm" -o "$dest/pkg/wingbeat_bg.opt.wasm"; then
    mv "$dest/pkg/wingbeat_bg.opt.wasm" "$dest/pkg/wingbeat_bg.wasm"
  else
    echo "build-web: WARNING: wasm-opt failed; keeping the unoptimised module" >&2
    rm -f "$dest/pkg/wingbeat_bg.opt.wasm"
  fi
fi

mkdir -p "$dest/vendor"
cp node_modules/uplot/dist/uPlot.esm.js node_modules/uplot/dist/uPlot.min.css "$dest/vendor/"
cp node_modules/uplot/LICENSE "$dest/vendor/uPlot.LICENSE" 2>/dev/null || true

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

raw=$(wc -c < "$dest/pkg/wingbeat_bg.wasm")
gz=$(gzip -9 -c "$dest/pkg/wingbeat_bg.wasm" | wc -c)
echo "build-web: $dest/ ready; wingbeat_bg.wasm $raw bytes ($gz gzipped)"
