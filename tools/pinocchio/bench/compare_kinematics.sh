#!/usr/bin/env bash
# rodyn against Pinocchio on the kinematics-for-control algorithms:
#
#   tools/pinocchio/bench/compare_kinematics.sh [milliseconds per measurement]
#
# See compare_suite.sh.
exec "$(dirname "${BASH_SOURCE[0]}")/compare_suite.sh" kinematics "$@"
