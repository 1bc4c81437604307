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

PREFIX="$(python3 -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')/cmeel.prefix"
for header in pinocchio/config.hpp eigen3/Eigen/Core urdfdom_headers/urdf_model/model.h; do
    if [[ ! -e "$PREFIX/include/$header" ]]; then
        echo "missing $PREFIX/include/$header: pip install pin cmeel-eigen cmeel-urdfdom-headers" >&2
        exit 1
    fi
done

CXXFLAGS=(-std=c++17 -O3 -DNDEBUG -g
    -I"$PREFIX/include" -I"$PREFIX/include/eigen3"
    -I"$PREFIX/include/urdfdom" -I"$PREFIX/include/urdfdom_headers"
    -DPINOCCHIO_WITH_URDFDOM
    -DPINOCCHIO_URDFDOM_HEADERS_MAJOR_VERSION=3
    -DPINOCCHIO_URDFDOM_HEADERS_MINOR_VERSION=0
    -DPINOCCHIO_URDFDOM_HEADERS_PATCH_VERSION=0
    -DBOOST_MPL_LIMIT_LIST_SIZE=30 -DBOOST_MPL_LIMIT_VECTOR_SIZE=30
    -DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS -DBOOST_FUSION_INVOKE_MAX_ARITY=12)
LDFLAGS=(-L"$PREFIX/lib" -Wl,-rpath,"$PREFIX/lib"
    -lpinocchio_parsers -lpinocchio_default -lurdfdom_model -lconsole_bridge
    -ltinyxml2 -lboost_filesystem)

SRC="$ROOT/tools/pinocchio/bench/bench.cpp"
EXE="$OUT/pinocchio-bench"
if [[ ! -x "$EXE" || "$SRC" -nt "$EXE" || "$0" -nt "$EXE" ]]; then
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
