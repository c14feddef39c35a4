// SPDX-License-Identifier: Apache-2.0
// Negative probe: operator new and delete. The board's link must refuse it
// with "undefined reference to `__wrap__Znwj'" (ILP32) or `__wrap__Znwm' (LP64).
extern "C" [[noreturn]] void Reset_Handler() {
  int* volatile p = new int(42);
  delete p;
  for (;;) {
  }
}
