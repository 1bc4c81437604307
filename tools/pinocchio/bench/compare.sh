#!/usr/bin/env bash
# rodyn against Pinocchio: same URDFs, same states, interleaved runs.
#
#   tools/pinocchio/bench/compare.sh [--rounds N] [--ms M]
#   tools/pinocchio/bench/compare.sh --build-only
#
# The second builds the timing program and writes the models' inputs, then
# prints the program's path (`cargo xtask host-profile --pinocchio` uses it).
#
# Needs `pip install pin cmeel-eigen cmeel-urdfdom-headers` (everything from
# PyPI: the `pin` wheel ships Pinocchio's headers and shared libraries under
# its cmeel prefix). Builds tools/pinocchio/bench/bench.cpp with g++ into
# target/pinocchio-bench/, then runs the `compare` binary of rodyn-bench,
# which times rodyn and calls the Pinocchio program round by round and prints
# a markdown table. Arguments go to the compare binary.
#
# Both sides compile for the baseline x86-64 target (no -march=native) at
# full optimisation: g++ -O3 -DNDEBUG, and cargo's release profile
# (opt-level 3). Pinocchio's algorithms are header templates, so they are
# instantiated in bench.cpp with these flags rather than taken from the
# wheel's precompiled library.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
OUT="$ROOT/target/pinocchio-bench"
mkdir -p "$OUT"

# PREFIX, CXXFLAGS and LDFLAGS, the same for every Pinocchio program here.
source "$ROOT/tools/pinocchio/bench/pinocchio_flags.sh"

SRC="$ROOT/tools/pinocchio/bench/bench.cpp"
EXE="$OUT/pinocchio-bench"
if [[ ! -x "$EXE" || "$SRC" -nt "$EXE" || "$0" -nt "$EXE" || "$ROOT/tools/pinocchio/bench/pinocchio_flags.sh" -nt "$EXE" ]]; then
    echo "building $EXE: g++ ${CXXFLAGS[*]:0:3} (about a minute)" >&2
    g++ "${CXXFLAGS[@]}" "$SRC" -o "$EXE" "${LDFLAGS[@]}"
fi

cd "$ROOT"
if [[ "${1:-}" == "--build-only" ]]; then
    cargo run --quiet -p rodyn-bench --release --bin compare -- --inputs-only >/dev/null
    echo "$EXE"
    exit 0
fi
exec cargo run --quiet -p rodyn-bench --release --bin compare -- --pinocchio "$EXE" "$@"
