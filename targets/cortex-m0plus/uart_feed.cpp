// SPDX-License-Identifier: Apache-2.0
// UART0 driver of the RP2040 (PL011, FIFOs off: one byte per interrupt each
// way, like the Cortex-M boards' USARTs). See uart_feed.hpp.
#include "uart_feed.hpp"

#include <atomic>

#include "registers.hpp"

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
// 125 MHz / (16 * 115200) = 67.817 -> IBRD 67, FBRD 52 (0.0 % error).
constexpr std::uint32_t kDiv64 = (8u * kPeriHz / kUartBaud + 1u) / 2u;  // round(4 * f / baud)
constexpr std::uint32_t kIbrd = kDiv64 >> 6;
constexpr std::uint32_t kFbrd = kDiv64 & 0x3Fu;
static_assert(kIbrd >= 1 && kIbrd <= 0xFFFF, "UART0: baud rate out of range for clk_peri");

// ARMv6-M: 2 priority bits (7:6 of each byte); byte 0 of IPR5 is IRQ 20.
constexpr std::uint32_t kNvicPriority = 0x80;

}  // namespace

RxRing& uart0_rx_ring() { return g_rx_ring; }
TxRing& uart0_tx_ring() { return g_tx_ring; }

void uart0_start() {
  using namespace regs;
  reg(kResetsReset + kAliasSet) = kResetUart0;
  reg(kResetsReset + kAliasClr) = kResetUart0;
  while ((reg(kResetsResetDone) & kResetUart0) == 0) {
  }

  reg(kUartIbrd) = kIbrd;
  reg(kUartFbrd) = kFbrd;
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
