#!/usr/bin/env bash
# rodyn against Pinocchio on forward dynamics with rigid contacts
# (constraintDynamics): Solo12 on four point feet, Talos on two soles:
#
#   tools/pinocchio/bench/compare_contacts.sh [milliseconds per measurement]
#
# See compare_suite.sh; Talos comes from example-robot-data
# (`pip install example-robot-data`).
exec "$(dirname "${BASH_SOURCE[0]}")/compare_suite.sh" contacts "$@"
