// SPDX-License-Identifier: Apache-2.0
// Control probe: no heap use. Must link with the board's options, so the
// failures of the other probes are due to what they call, not to the setup.
extern "C" [[noreturn]] void Reset_Handler() {
  volatile unsigned counter = 0;
  for (;;) counter = counter + 1u;
}
