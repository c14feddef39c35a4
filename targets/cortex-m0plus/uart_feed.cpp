// SPDX-License-Identifier: Apache-2.0
// UART0 driver of the RP2040 (PL011, FIFOs off: one byte per interrupt each
// way, like the Cortex-M boards' USARTs). See uart_feed.hpp.
#include "uart_feed.hpp"

#include <atomic>

#include "registers.hpp"
#include "system.hpp"

namespace kestrel::m0plus {
namespace {

constinit RxRing g_rx_ring{};
constinit TxRing g_tx_ring{};
constinit std::atomic<std::uint32_t> g_overruns{0};
constinit std::atomic<std::uint32_t> g_framing_errors{0};

void count(std::atomic<std::uint32_t>& counter) {
  counter.store(counter.load(std::memory_order_relaxed) + 1u, std::memory_order_relaxed);
}

// PL011 divisor = f_peri / (16 baud) as 16.6 fixed point, rounded:
// 125 MHz / (16 * 115200) = 67.817 -> IBRD 67, FBRD 52 (0.0 % error);
// 12 MHz (crystal fallback) -> 6.510 -> IBRD 6, FBRD 33 (0.0 %); 6.5 MHz
// (ring oscillator, nominal) -> IBRD 3, FBRD 34, only as right as the
// oscillator. One of these three clocks is what configure_clocks() leaves,
// so the divisors are constants: ARMv6-M has no divide instruction.
constexpr std::uint32_t div64(std::uint32_t peri_hz) {
  return static_cast<std::uint32_t>((8ull * peri_hz / kUartBaud + 1u) / 2u);  // round(4 * f / baud)
}
static_assert((div64(kPeriHz) >> 6) >= 1 && (div64(kPeriHz) >> 6) <= 0xFFFF, "UART0: baud out of range");
static_assert((div64(kRoscNominalHz) >> 6) >= 1, "UART0: baud out of range on the ring oscillator");
std::uint32_t div64_at(std::uint32_t peri_hz) {
  if (peri_hz == kPeriHz) return div64(kPeriHz);
  if (peri_hz == kXoscHz) return div64(kXoscHz);
  return div64(kRoscNominalHz);
}

// ARMv6-M: 2 priority bits (7:6 of each byte); byte 0 of IPR5 is IRQ 20.
constexpr std::uint32_t kNvicPriority = 0x80;

}  // namespace

RxRing& uart0_rx_ring() { return g_rx_ring; }
TxRing& uart0_tx_ring() { return g_tx_ring; }

bool uart0_start(std::uint32_t peri_hz) {
  using namespace regs;
  reg(kResetsReset + kAliasSet) = kResetUart0;
  reg(kResetsReset + kAliasClr) = kResetUart0;
  // Bounded (system.cpp's wait): a UART0 that does not leave reset is left
  // alone, and the caller decides (false).
  if (!wait_for_reset_done(kResetUart0)) return false;

  const std::uint32_t div = div64_at(peri_hz);
  reg(kUartIbrd) = div >> 6;
  reg(kUartFbrd) = div & 0x3Fu;
  reg(kUartLcrH) = kUartLcrHWlen8;  // 8N1, FIFOs off; writing LCR_H latches the divisors
  reg(kUartCr) = kUartCrEn | kUartCrTxe | kUartCrRxe;
  reg(kUartImsc) = kUartIntRx | kUartIntRt;

  reg(kGpio0Ctrl) = kFuncSelUart;  // GPIO0: UART0 TX
  reg(kGpio1Ctrl) = kFuncSelUart;  // GPIO1: UART0 RX

  // IPR registers are word-access only on ARMv6-M.
  const Address ipr = kNvicIpr0 + 4 * (kUart0Irq / 4);
  const std::uint32_t shift = 8 * (kUart0Irq % 4);
  reg(ipr) = (reg(ipr) & ~(0xFFu << shift)) | (kNvicPriority << shift);
  reg(kNvicIser) = 1u << kUart0Irq;
  return true;
}

void uart0_kick_tx() { regs::reg(regs::kUartImsc + regs::kAliasSet) = regs::kUartIntTx; }

UartLineErrors uart0_line_errors() {
  return {g_overruns.load(std::memory_order_relaxed), g_framing_errors.load(std::memory_order_relaxed)};
}

}  // namespace kestrel::m0plus

/// UART0 interrupt: a received byte -> RX ring (errors counted; reading DR
/// clears the receive interrupt); transmitter empty -> next byte of the TX
/// ring, or the TX interrupt masked when the ring is empty. Bounded: one
/// byte each way per entry.
extern "C" void UART0_IRQHandler() {
  using namespace kestrel::m0plus;
  using namespace kestrel::m0plus::regs;
  if ((reg(kUartFr) & kUartFrRxfe) == 0) {
    const std::uint32_t dr = reg(kUartDr);
    if ((dr & kUartDrOe) != 0) count(g_overruns);
    if ((dr & kUartDrFe) != 0) count(g_framing_errors);
    (void)g_rx_ring.push(static_cast<std::uint8_t>(dr & 0xFFu));
  }
  if ((reg(kUartMis) & kUartIntTx) != 0) {
    std::uint8_t byte = 0;
    if (g_tx_ring.pop(byte)) {
      reg(kUartDr) = byte;  // clears the TX interrupt until the byte has gone
    } else {
      reg(kUartImsc + kAliasClr) = kUartIntTx;
    }
  }
}
