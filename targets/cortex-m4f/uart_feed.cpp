// SPDX-License-Identifier: Apache-2.0
// USART2 driver (registers, interrupt handler, both rings). See
// uart_feed.hpp for the data path.
#include "uart_feed.hpp"

#include <atomic>

#include "registers.hpp"

namespace kestrel::m4f {
namespace {

// Constant-initialised (constexpr constructors), so they sit in .bss and
// are usable before any static constructor runs.
constinit RxRing g_rx_ring{};
constinit TxRing g_tx_ring{};

// Written by the ISR only; relaxed is enough for counters read for diagnostics.
constinit std::atomic<std::uint32_t> g_overruns{0};
constinit std::atomic<std::uint32_t> g_framing_errors{0};
constinit std::atomic<std::uint32_t> g_noise_errors{0};

void count(std::atomic<std::uint32_t>& counter) {
  counter.store(counter.load(std::memory_order_relaxed) + 1u, std::memory_order_relaxed);
}

// BRR with OVER8 = 0 holds f_APB1 / baud (mantissa and 4-bit fraction of
// f / (16 * baud)); rounded to nearest. 42 MHz / 115200 -> 365 (0.08 %
// error) on the PLL, 16 MHz / 115200 -> 139 (0.08 %) on the HSI fallback.
constexpr std::uint32_t brr(std::uint32_t apb1_hz) { return (apb1_hz + kUartBaud / 2) / kUartBaud; }
static_assert(brr(kApb1Hz) >= 16 && brr(kApb1Hz) <= 0xFFFF, "USART2: baud rate out of range for APB1");
static_assert(brr(kHsiHz) >= 16 && brr(kHsiHz) <= 0xFFFF, "USART2: baud rate out of range on the HSI");

constexpr std::uint32_t kNvicPriority = 0x80;  // mid priority (upper 4 bits are implemented)

}  // namespace

RxRing& usart2_rx_ring() { return g_rx_ring; }
TxRing& usart2_tx_ring() { return g_tx_ring; }

void usart2_start(std::uint32_t apb1_hz) {
  using namespace regs;
  reg(kRccAhb1enr) |= kRccAhb1enrGpioaEn;
  reg(kRccApb1enr) |= kRccApb1enrUsart2En;
  // Errata ES0182: wait after a clock enable before the first access; a read-back does.
  [[maybe_unused]] const std::uint32_t settle = reg(kRccApb1enr);

  // PA2 (TX) and PA3 (RX): alternate function 7, fast, pull-up on RX so an
  // unconnected line idles high instead of producing framing errors.
  reg(kGpioaAfrl) = (reg(kGpioaAfrl) & ~(0xFFu << 8)) | (0x77u << 8);
  reg(kGpioaOspeedr) = (reg(kGpioaOspeedr) & ~(0xFu << 4)) | (0xAu << 4);
  reg(kGpioaPupdr) = (reg(kGpioaPupdr) & ~(0xFu << 4)) | (0x4u << 4);
  reg(kGpioaModer) = (reg(kGpioaModer) & ~(0xFu << 4)) | (0xAu << 4);

  reg(kUsart2Cr1) = 0;  // disabled while configuring; M = 0 (8 data bits), no parity
  reg(kUsart2Cr2) = 0;  // 1 stop bit
  reg(kUsart2Cr3) = 0;  // no flow control, no DMA
  reg(kUsart2Brr) = brr(apb1_hz);
  reg(kUsart2Cr1) = kUsartCr1Ue | kUsartCr1Te | kUsartCr1Re | kUsartCr1Rxneie;

  reinterpret_cast<volatile std::uint8_t*>(kNvicIpr0)[kUsart2Irq] = kNvicPriority;
  reg(kNvicIser0 + 4 * (kUsart2Irq / 32)) = 1u << (kUsart2Irq % 32);
}

void usart2_kick_tx() {
  // Read-modify-write from the main loop; the ISR may clear TXEIE in
  // between, in which case this sets it again and the ISR takes one extra
  // TXE interrupt, finds the ring empty (or not) and behaves correctly.
  regs::reg(regs::kUsart2Cr1) |= regs::kUsartCr1Txeie;
}

void usart2_poll_tx() {
  using namespace regs;
  // TXEIE is on exactly while the transmit ring holds bytes (the ISR clears
  // it on an empty ring). With TXE set the hardware has already raised the
  // interrupt, so setting it pending again changes nothing on the STM32.
  if ((reg(kUsart2Cr1) & kUsartCr1Txeie) != 0 && (reg(kUsart2Sr) & kUsartSrTxe) != 0) {
    reg(kNvicIspr0 + 4 * (kUsart2Irq / 32)) = 1u << (kUsart2Irq % 32);
  }
}

UartLineErrors usart2_line_errors() {
  return {g_overruns.load(std::memory_order_relaxed), g_framing_errors.load(std::memory_order_relaxed),
          g_noise_errors.load(std::memory_order_relaxed)};
}

}  // namespace kestrel::m4f

/// USART2 global interrupt: RXNE (and ORE) -> receive ring; TXE -> next byte
/// of the transmit ring, or TXEIE off when it is empty. Bounded: one byte
/// each way per entry.
extern "C" void USART2_IRQHandler() {
  using namespace kestrel::m4f;
  using namespace kestrel::m4f::regs;
  const std::uint32_t sr = reg(kUsart2Sr);
  if ((sr & (kUsartSrRxne | kUsartSrOre)) != 0) {
    // Reading SR then DR clears RXNE, ORE, FE and NF (RM0090 30.6.1).
    const auto byte = static_cast<std::uint8_t>(reg(kUsart2Dr) & 0xFFu);
    if ((sr & kUsartSrOre) != 0) count(g_overruns);
    if ((sr & kUsartSrFe) != 0) count(g_framing_errors);
    if ((sr & kUsartSrNf) != 0) count(g_noise_errors);
    // A full ring drops the byte and counts it (ByteRingBuffer::overflow_count).
    (void)g_rx_ring.push(byte);
  }
  const std::uint32_t cr1 = reg(kUsart2Cr1);
  if ((cr1 & kUsartCr1Txeie) != 0 && (sr & kUsartSrTxe) != 0) {
    std::uint8_t byte = 0;
    if (g_tx_ring.pop(byte)) {
      reg(kUsart2Dr) = byte;
    } else {
      reg(kUsart2Cr1) = cr1 & ~kUsartCr1Txeie;
    }
  }
}
