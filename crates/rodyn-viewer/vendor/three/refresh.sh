#!/bin/sh
# Rebuilds three.min.js from the npm package three@VERSION (see README.md).
set -eu
version=${1:?usage: refresh.sh THREE_VERSION}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
npm init -y >/dev/null
npm install --no-audit --no-fund "three@$version" esbuild@0.28.2 >/dev/null
cp "$here/entry.js" .
npx esbuild entry.js --bundle --minify --format=iife --global-name=THREE \
    --legal-comments=none --outfile="$here/three.min.js"
cp node_modules/three/LICENSE "$here/LICENSE"
echo "three.min.js now holds three.js $version"
