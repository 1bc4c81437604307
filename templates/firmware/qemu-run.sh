#!/usr/bin/env bash
# `cargo run`'s runner (.cargo/config.toml): boots the firmware ELF ($1) in
# QEMU's mps2-an386 board (a Cortex-M4F) and prints its defmt log.
#
# The firmware logs binary defmt frames over semihosting. defmt-print
# (`cargo install defmt-print --locked`) turns them into text with the
# strings kept in the ELF. Without it, or with DEFMT_PRINT set to an empty
# string, the raw frames go to stdout, for a decoder of your own. The exit
# code is the firmware's: 0 when it succeeds.
set -euo pipefail

elf="$1"
qemu=(
  # A firmware that hangs (or whose log reader went away) is stopped.
  timeout 120
  qemu-system-arm -machine mps2-an386 -cpu cortex-m4
  -nographic -monitor none -serial none
  # Every instruction takes 64 ns of virtual time, so SysTick's pacing and
  # the loop's timing do not depend on how busy the host is.
  -icount shift=6
  -semihosting-config enable=on,target=native
  -kernel "$elf"
)

decoder="${DEFMT_PRINT-defmt-print}"
if [ -n "$decoder" ] && command -v "$decoder" > /dev/null; then
  # pipefail: the firmware's exit code, not the decoder's.
  "${qemu[@]}" | "$decoder" -e "$elf"
else
  if [ -n "$decoder" ]; then
    echo "qemu-run.sh: no $decoder: printing raw defmt frames" \
      "(\`cargo install defmt-print --locked\` decodes them)" >&2
  fi
  exec "${qemu[@]}"
fi
