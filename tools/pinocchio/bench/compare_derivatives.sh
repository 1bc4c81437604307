#!/usr/bin/env bash
# rodyn against Pinocchio on the analytic derivatives of RNEA and ABA:
#
#   tools/pinocchio/bench/compare_derivatives.sh [milliseconds per measurement]
#
# See compare_suite.sh.
exec "$(dirname "${BASH_SOURCE[0]}")/compare_suite.sh" derivatives "$@"
