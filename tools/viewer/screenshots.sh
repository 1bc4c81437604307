#!/bin/sh
# The viewer's pictures in docs/img/viewer/: the Panda of example-robot-data
# (its meshes) with its joint axes, and the quadruped's trot with its
# contact forces, drawn by headless Chromium. Run from the repository root:
#
#     tools/viewer/screenshots.sh
#
# Needs python3 (example-robot-data comes from the test command's venv,
# `cargo xtask python-env`, pinned to the version the tests use) and
# chromium (Debian: apt-get install --no-install-recommends chromium).
set -eu
out=docs/img/viewer
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
robots=$(cargo xtask python-env | sed -n 's/^example-robot-data robots: //p')
[ -n "$robots" ] || { echo "cargo xtask python-env did not name the robots folder" >&2; exit 1; }
share=${robots%/example-robot-data/robots}
cargo build -q -p rodyn-model -p rodyn-sim --bins
target/debug/rodyn-model view "$share/example-robot-data/robots/panda_description/urdf/panda.urdf" \
    --package-path "$share" --silence all -o "$work/panda.html"
target/debug/rodyn-sim run quadruped-trot --duration 2 -o "$work/trot" --html "$work/trot.html"
shot() { # URL PNG
    profile=$(mktemp -d)
    chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
        --disable-background-networking --disable-component-update --disable-sync \
        --hide-scrollbars --force-device-scale-factor=1 --enable-unsafe-swiftshader \
        --use-angle=swiftshader --virtual-time-budget=3000 --window-size=960,640 \
        --user-data-dir="$profile" --screenshot="$2" "$1" 2>/dev/null
    rm -rf "$profile"
}
mkdir -p "$out"
shot "file://$work/panda.html#q=0.3,-0.4,0,-2.0,0,1.6,0.8,0.02,0.02&show=axes" "$out/panda.png"
shot "file://$work/trot.html#t=1.2" "$out/trot.png"
echo "wrote $out/panda.png and $out/trot.png"
