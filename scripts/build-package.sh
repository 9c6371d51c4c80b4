#!/usr/bin/env bash
# Builds the npm package `wingbeat-lab` (the <wing-lab> element, its worker, styles, vendored
# uPlot, the wasm module and TypeScript types) into npm-package/ (git-ignored), then packs it:
#   scripts/build-package.sh          -> npm-package/wingbeat-lab/ and npm-package/wingbeat-lab-<version>.tgz
# Uses the lab as built in www/ (scripts/build-web.sh www; built first when www/pkg is missing).
# The package's files are copied from www/ unchanged (packaging/assemble.mjs); see
# docs/embedding.md, section 3.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

if [ ! -f www/pkg/wingbeat_bg.wasm ] || [ ! -f www/vendor/uPlot.esm.js ]; then
  bash scripts/build-web.sh www
fi

out=npm-package
node packaging/assemble.mjs www "$out/wingbeat-lab"
rm -f "$out"/wingbeat-lab-*.tgz
tgz=$(cd "$out" && npm pack ./wingbeat-lab --silent --pack-destination . | tail -n 1)
size=$(wc -c < "$out/$tgz")
echo "build-package: $out/$tgz ($size bytes)"
