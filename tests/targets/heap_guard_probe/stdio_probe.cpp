// SPDX-License-Identifier: Apache-2.0
// Probe for the second net: it defines its own puts (so it links without
// newlib's stdio) and calls it; check_symbols.cmake must still reject the
// image because a symbol named puts is in it.
extern "C" __attribute__((noinline)) int puts(const char* s) { return s[0]; }

extern "C" [[noreturn]] void Reset_Handler() {
  volatile int sink = puts("kestrel");
  for (;;) sink = sink + 1;
}
