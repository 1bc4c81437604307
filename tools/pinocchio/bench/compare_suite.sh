#!/usr/bin/env bash
# rodyn against Pinocchio on one suite of algorithms beyond compare.sh's,
# on UR5, Panda and Solo12 (same URDFs; each side its own 64 random states):
#
#   [ROUNDS=N] tools/pinocchio/bench/compare_suite.sh SUITE [milliseconds per measurement]
#
# SUITE is `kinematics` (joint Jacobians, a frame Jacobian, the centroidal
# map, CCRBA; one frame's Jacobian from q and a quadruped's four feet, also
# on ANYmal, the G1 and Talos from example-robot-data), `derivatives` (RNEA and ABA derivatives) or `contacts`
# (constrained forward dynamics on Solo12 and Talos; Talos's URDF from
# example-robot-data). Builds
# tools/pinocchio/bench/bench_SUITE.cpp with compare.sh's flags (g++ -O3,
# baseline x86-64) and runs it and rodyn-bench's `SUITE_timing` (release;
# `contacts_timing` is an example)
# alternately, ROUNDS times (2 unless set), printing a markdown table of
# the medians over the rounds and the ratio rodyn / Pinocchio; with more
# than two rounds also the fastest round, the quartiles (the spread) and
# the ratio of the fastest, which a shared machine's preemptions (they
# only add time) disturb least. compare_kinematics.sh and compare_derivatives.sh
# name the suite for you.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
OUT="$ROOT/target/pinocchio-bench"
mkdir -p "$OUT"
SUITE="${1:?usage: compare_suite.sh kinematics|derivatives|contacts [ms]}"
MS="${2:-50}"
ROUNDS="${ROUNDS:-2}"
if ! [[ "$ROUNDS" =~ ^[1-9][0-9]*$ ]]; then
    echo "ROUNDS must be a positive whole number, not '$ROUNDS'" >&2
    exit 2
fi
EXTRA=()
case "$SUITE" in
    kinematics)
        # The from-q frame Jacobians' branched robots (as in
        # host-tests/fixtures/frame_chain/).
        for robot in anymal_b_simple_description/robots/anymal.urdf \
            g1_description/urdf/g1_29dof_rev_1_0.urdf talos_data/robots/talos_reduced.urdf; do
            EXTRA+=("$(python3 "$ROOT/tools/pinocchio/make_models.py" --print-robot "$robot")")
        done
        ;;
    derivatives) ;;
    contacts)
        TALOS="$(python3 "$ROOT/tools/pinocchio/make_models.py" --print-robot talos_data/robots/talos_reduced.urdf)"
        EXTRA=("$TALOS")
        ;;
    *) echo "unknown suite '$SUITE': kinematics, derivatives or contacts" >&2; exit 2 ;;
esac

# PREFIX, CXXFLAGS and LDFLAGS, the same for every Pinocchio program here.
source "$ROOT/tools/pinocchio/bench/pinocchio_flags.sh"

SRC="$ROOT/tools/pinocchio/bench/bench_$SUITE.cpp"
HEADER="$ROOT/tools/pinocchio/bench/bench_timing.hpp"
EXE="$OUT/pinocchio-bench-$SUITE"
if [[ ! -x "$EXE" || "$SRC" -nt "$EXE" || "$HEADER" -nt "$EXE" || "$0" -nt "$EXE" || "$ROOT/tools/pinocchio/bench/pinocchio_flags.sh" -nt "$EXE" ]]; then
    echo "building $EXE (about a minute)" >&2
    g++ "${CXXFLAGS[@]}" "$SRC" -o "$EXE" "${LDFLAGS[@]}"
fi

cd "$ROOT"
RODYN="${CARGO_TARGET_DIR:-$ROOT/target}/release"
if [[ "$SUITE" == contacts || "$SUITE" == kinematics ]]; then
    # Examples: they read the fixtures of the unpublished rodyn-host-tests.
    cargo build --quiet -p rodyn-bench --release --example "${SUITE}_timing"
    RODYN="$RODYN/examples/${SUITE}_timing"
else
    cargo build --quiet -p rodyn-bench --release --bin "${SUITE}_timing"
    RODYN="$RODYN/${SUITE}_timing"
fi
TMP="$(mktemp -d)"
echo "$ROUNDS rounds from $(date -u '+%Y-%m-%d %H:%M') UTC, load $(cut -d' ' -f1-3 /proc/loadavg)" >&2
for round in $(seq 1 "$ROUNDS"); do
    "$RODYN" --ms "$MS" >>"$TMP/rodyn"
    "$EXE" "$MS" "${EXTRA[@]}" >>"$TMP/pinocchio"
done
echo "until $(date -u '+%H:%M') UTC, load $(cut -d' ' -f1-3 /proc/loadavg)" >&2
python3 - "$TMP/rodyn" "$TMP/pinocchio" "$ROUNDS" <<'PY'
import statistics, sys
def read(path):
    out = {}
    for line in open(path):
        model, algorithm, ns = line.split()
        out.setdefault((model, algorithm), []).append(float(ns))
    return out
rodyn, pin = read(sys.argv[1]), read(sys.argv[2])
spread = int(sys.argv[3]) > 2
def quartiles(v):
    q = statistics.quantiles(v, n=4)
    return f"{q[0]:.0f}-{q[2]:.0f}"
if spread:
    print("| model | algorithm | rodyn median (ns) | quartiles | fastest | Pinocchio median (ns) | quartiles | fastest | ratio of medians | ratio of fastest |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
else:
    print("| model | algorithm | rodyn (ns) | Pinocchio (ns) | rodyn / Pinocchio |")
    print("|---|---|---:|---:|---:|")
for key in rodyn:
    # rodyn's variants of an algorithm (`name_variant`) share Pinocchio's line.
    r = rodyn[key]
    p = pin.get(key) or pin[(key[0], key[1].rsplit("_", 1)[0])]
    rm, pm = statistics.median(r), statistics.median(p)
    if spread:
        print(f"| {key[0]} | {key[1]} | {rm:.0f} | {quartiles(r)} | {min(r):.0f} | {pm:.0f} | "
              f"{quartiles(p)} | {min(p):.0f} | {rm / pm:.2f}x | {min(r) / min(p):.2f}x |")
    else:
        print(f"| {key[0]} | {key[1]} | {rm:.0f} | {pm:.0f} | {rm / pm:.2f}x |")
PY
rm -r "$TMP"
